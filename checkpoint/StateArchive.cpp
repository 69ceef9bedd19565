#include "checkpoint/StateArchive.hpp"

#include "checkpoint/CheckpointError.hpp"

namespace fsi::checkpoint {
namespace {

const char *kind_name(ArchiveEntry::Kind kind) {
  switch (kind) {
  case ArchiveEntry::Kind::doubles:
    return "an array of numbers";
  case ArchiveEntry::Kind::integer:
    return "an integer";
  case ArchiveEntry::Kind::text:
    return "a text";
  }
  return "an unknown kind";
}

} // namespace

void StateArchive::put_entry(const std::string &name, ArchiveEntry entry) { entries_[name] = std::move(entry); }

void StateArchive::put_doubles(const std::string &name, std::vector<double> values, std::vector<std::uint64_t> shape) {
  std::uint64_t count = 1;
  for (const auto d : shape)
    count *= d;
  if (count != values.size())
    throw std::invalid_argument("state archive entry '" + name + "': shape and number of values disagree");
  ArchiveEntry e;
  e.kind = ArchiveEntry::Kind::doubles;
  e.shape = std::move(shape);
  e.values = std::move(values);
  put_entry(name, std::move(e));
}

void StateArchive::put_points(const std::string &name, const PointArray &points) {
  std::vector<double> values(static_cast<std::size_t>(points.size()));
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    for (Eigen::Index j = 0; j < 3; ++j)
      values[static_cast<std::size_t>(3 * i + j)] = points(i, j);
  put_doubles(name, std::move(values), {static_cast<std::uint64_t>(points.rows()), 3});
}

void StateArchive::put_vector(const std::string &name, const Eigen::VectorXd &values) {
  put_doubles(name, std::vector<double>(values.data(), values.data() + values.size()),
              {static_cast<std::uint64_t>(values.size())});
}

void StateArchive::put_double(const std::string &name, double value) { put_doubles(name, {value}, {}); }

void StateArchive::put_integer(const std::string &name, std::int64_t value) {
  ArchiveEntry e;
  e.kind = ArchiveEntry::Kind::integer;
  e.integer = value;
  put_entry(name, std::move(e));
}

void StateArchive::put_text(const std::string &name, const std::string &value) {
  ArchiveEntry e;
  e.kind = ArchiveEntry::Kind::text;
  e.text = value;
  put_entry(name, std::move(e));
}

const ArchiveEntry &StateArchive::entry(const std::string &name, ArchiveEntry::Kind kind) const {
  const auto found = entries_.find(name);
  if (found == entries_.end())
    throw CheckpointError(source_ + ": has no entry '" + name + "'");
  if (found->second.kind != kind)
    throw CheckpointError(source_ + ": entry '" + name + "' is " + kind_name(found->second.kind) + ", not " +
                          kind_name(kind));
  return found->second;
}

PointArray StateArchive::points(const std::string &name, long expected_rows) const {
  const ArchiveEntry &e = entry(name, ArchiveEntry::Kind::doubles);
  if (e.shape.size() != 2 || e.shape[1] != 3)
    throw CheckpointError(source_ + ": entry '" + name + "' is not an N x 3 array of points");
  const auto rows = static_cast<Eigen::Index>(e.shape[0]);
  if (expected_rows >= 0 && rows != expected_rows)
    throw CheckpointError(source_ + ": entry '" + name + "' has " + std::to_string(rows) + " points, the case has " +
                          std::to_string(expected_rows));
  PointArray points(rows, 3);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < 3; ++j)
      points(i, j) = e.values[static_cast<std::size_t>(3 * i + j)];
  return points;
}

Eigen::VectorXd StateArchive::vector(const std::string &name, long expected_size) const {
  const ArchiveEntry &e = entry(name, ArchiveEntry::Kind::doubles);
  if (e.shape.size() != 1)
    throw CheckpointError(source_ + ": entry '" + name + "' is not a vector");
  if (expected_size >= 0 && static_cast<long>(e.values.size()) != expected_size)
    throw CheckpointError(source_ + ": entry '" + name + "' has " + std::to_string(e.values.size()) +
                          " values, expected " + std::to_string(expected_size));
  return Eigen::Map<const Eigen::VectorXd>(e.values.data(), static_cast<Eigen::Index>(e.values.size()));
}

double StateArchive::number(const std::string &name) const {
  const ArchiveEntry &e = entry(name, ArchiveEntry::Kind::doubles);
  if (!e.shape.empty())
    throw CheckpointError(source_ + ": entry '" + name + "' is an array, not a number");
  return e.values.front();
}

std::int64_t StateArchive::integer(const std::string &name) const {
  return entry(name, ArchiveEntry::Kind::integer).integer;
}

const std::string &StateArchive::text(const std::string &name) const {
  return entry(name, ArchiveEntry::Kind::text).text;
}

} // namespace fsi::checkpoint
