#pragma once
// A process's state at a step boundary as named entries: arrays of doubles (with their shape),
// integers and texts. Values are kept bit for bit, so a state put in and read back is the same
// state (a restart that is exact needs nothing less). Names are paths ("structures/rag/x_m").
// get_*() of an entry that is absent or of another kind throws CheckpointError naming it.

#include "common/Types.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fsi::checkpoint {

struct ArchiveEntry {
  enum class Kind : std::uint8_t { doubles = 1, integer = 2, text = 3 };
  Kind kind = Kind::doubles;
  std::vector<std::uint64_t> shape; ///< doubles only; row-major
  std::vector<double> values;       ///< doubles
  std::int64_t integer = 0;
  std::string text;
};

class StateArchive {
public:
  void put_doubles(const std::string &name, std::vector<double> values, std::vector<std::uint64_t> shape);
  void put_points(const std::string &name, const PointArray &points);
  void put_vector(const std::string &name, const Eigen::VectorXd &values);
  void put_double(const std::string &name, double value);
  void put_integer(const std::string &name, std::int64_t value);
  void put_text(const std::string &name, const std::string &value);

  bool has(const std::string &name) const { return entries_.count(name) > 0; }
  /// An N x 3 array; `expected_rows` >= 0 checks the number of rows.
  PointArray points(const std::string &name, long expected_rows = -1) const;
  Eigen::VectorXd vector(const std::string &name, long expected_size = -1) const;
  double number(const std::string &name) const;
  std::int64_t integer(const std::string &name) const;
  const std::string &text(const std::string &name) const;

  const std::map<std::string, ArchiveEntry> &entries() const { return entries_; }
  void put_entry(const std::string &name, ArchiveEntry entry);
  /// Where the archive came from, for messages ("checkpoints/step-000000100/structure.ckpt").
  void set_source(std::string source) { source_ = std::move(source); }
  const std::string &source() const { return source_; }

private:
  const ArchiveEntry &entry(const std::string &name, ArchiveEntry::Kind kind) const;

  std::map<std::string, ArchiveEntry> entries_;
  std::string source_ = "state archive";
};

} // namespace fsi::checkpoint
