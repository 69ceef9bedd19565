#include "apps/fsi-surface-query/QueryServer.hpp"

#include "geometry/SpatialHashGrid.hpp"
#include "geometry/StlIo.hpp"

#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fsi::apps {
namespace {

/// Twice the area below which a triangle counts as degenerate (its edges belong to its
/// neighbours): the threshold of the metrics' former Python engine.
constexpr double kMinDoubleArea_m2 = 1e-24;

std::string read_line(std::FILE *in) {
  std::string line;
  for (int c = std::fgetc(in); c != EOF && c != '\n'; c = std::fgetc(in))
    line.push_back(static_cast<char>(c));
  return line;
}

/// A non-negative count of a request line, refused when absent or out of range.
long count_of(std::istringstream &words, const std::string &line) {
  long n = -1;
  if (!(words >> n) || n < 0 || n > (1L << 40))
    throw std::runtime_error("request '" + line + "': a count is missing or out of range");
  return n;
}

} // namespace

QueryServer::QueryServer(std::FILE *in, std::FILE *out) : in_(in), out_(out) {}

void QueryServer::serve() {
  while (true) {
    const std::string line = read_line(in_);
    if (line == "quit" || (line.empty() && std::feof(in_)))
      return;
    answer(line);
    std::fflush(out_);
  }
}

void QueryServer::answer(const std::string &line) {
  std::istringstream words(line);
  std::string command;
  words >> command;
  if (command == "regions") {
    std::string path;
    std::getline(words >> std::ws, path);
    regions(path);
  } else if (command == "set") {
    add_set(count_of(words, line));
  } else if (command == "nearest") {
    const long set = count_of(words, line), n_points = count_of(words, line), capped = count_of(words, line);
    nearest(set, n_points, capped != 0);
  } else if (command == "pairs") {
    const long n_frames = count_of(words, line), n_points = count_of(words, line);
    double distance_m = 0.0;
    if (!(words >> distance_m))
      throw std::runtime_error("request '" + line + "': no distance");
    pairs(n_frames, n_points, distance_m, count_of(words, line));
  } else {
    throw std::runtime_error("unknown request '" + line + "' (regions, set, nearest, pairs, quit)");
  }
}

void QueryServer::regions(const std::string &path) {
  geometry::RegionSoup soup;
  try {
    soup = geometry::read_stl_regions(path);
  } catch (const std::exception &e) {
    write_line(std::string("error ") + e.what());
    return;
  }
  std::vector<std::vector<double>> coordinates(soup.region_names.size());
  for (Eigen::Index t = 0; t < soup.soup.triangles.rows(); ++t) {
    auto &values = coordinates[static_cast<std::size_t>(soup.region_of_triangle[static_cast<std::size_t>(t)])];
    for (int corner = 0; corner < 3; ++corner)
      for (int axis = 0; axis < 3; ++axis)
        values.push_back(soup.soup.vertices_m(soup.soup.triangles(t, corner), axis));
  }
  write_line("ok " + std::to_string(soup.region_names.size()));
  for (std::size_t r = 0; r < soup.region_names.size(); ++r) {
    write_line(soup.region_names[r].empty() ? "unnamed" : soup.region_names[r]);
    write_line(std::to_string(coordinates[r].size() / 9));
    write_values(coordinates[r]);
  }
}

void QueryServer::add_set(long n_triangles) {
  const std::vector<double> values = read_doubles(static_cast<std::size_t>(n_triangles) * 9);
  TriangleSet set;
  std::vector<geometry::TriangleBvh::Triangle> triangles;
  for (long t = 0; t < n_triangles; ++t) {
    geometry::TriangleBvh::Triangle triangle;
    for (int corner = 0; corner < 3; ++corner)
      triangle[static_cast<std::size_t>(corner)] = Vec3::Map(&values[static_cast<std::size_t>(9 * t + 3 * corner)]);
    if ((triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).norm() <= kMinDoubleArea_m2)
      continue;
    triangles.push_back(triangle);
    set.request_index.push_back(static_cast<std::int32_t>(t));
  }
  if (triangles.empty()) {
    write_line("error a triangle set with no triangle of non-zero area");
    return;
  }
  set.bvh = std::make_unique<geometry::TriangleBvh>(triangles);
  sets_.push_back(std::move(set));
  write_line("ok " + std::to_string(sets_.size() - 1) + " " + std::to_string(triangles.size()));
}

void QueryServer::nearest(long set, long n_points, bool capped) {
  const auto n = static_cast<std::size_t>(n_points);
  const std::vector<double> points = read_doubles(3 * n);
  const std::vector<double> caps = capped ? read_doubles(n) : std::vector<double>();
  if (set >= static_cast<long>(sets_.size())) {
    write_line("error no triangle set " + std::to_string(set) + " (" + std::to_string(sets_.size()) + " made)");
    return;
  }
  const TriangleSet &s = sets_[static_cast<std::size_t>(set)];
  std::vector<double> distance_m(n, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> triangle(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = Vec3::Map(&points[3 * i]);
    const geometry::TriangleBvh::Nearest hit = capped ? s.bvh->nearest_within(p, caps[i]) : s.bvh->nearest(p);
    if (hit.face < 0)
      continue;
    distance_m[i] = std::sqrt(hit.distance_sq_m2);
    triangle[i] = s.request_index[static_cast<std::size_t>(hit.face)];
  }
  write_line("ok");
  write_values(distance_m);
  write_values(triangle);
}

void QueryServer::pairs(long n_frames, long n_points, double distance_m, long grid_columns) {
  const auto n = static_cast<std::size_t>(n_points);
  const std::vector<double> values = read_doubles(static_cast<std::size_t>(n_frames) * n * 3);
  if (!(distance_m > 0.0) || !std::isfinite(distance_m)) {
    write_line("error pair distance " + std::to_string(distance_m) + " m: not a positive length");
    return;
  }
  std::vector<std::int64_t> found;
  for (long f = 0; f < n_frames; ++f) {
    const PointArray x = PointArray::Map(&values[static_cast<std::size_t>(f) * n * 3], n_points, 3);
    const geometry::SpatialHashGrid grid(x, distance_m);
    for (const auto &[i, j] : grid.pairs_within(distance_m)) {
      const bool neighbours = grid_columns > 0 && std::abs(i / grid_columns - j / grid_columns) <= 1 &&
                              std::abs(i % grid_columns - j % grid_columns) <= 1;
      if (!neighbours)
        found.insert(found.end(), {f, static_cast<std::int64_t>(i), static_cast<std::int64_t>(j)});
    }
  }
  write_line("ok " + std::to_string(found.size() / 3));
  write_values(found);
}

std::vector<double> QueryServer::read_doubles(std::size_t count) {
  std::vector<double> values(count);
  if (count > 0 && std::fread(values.data(), sizeof(double), count, in_) != count)
    throw std::runtime_error("the input ended inside a payload of " + std::to_string(count) + " numbers");
  return values;
}

void QueryServer::write_line(const std::string &line) {
  std::fputs(line.c_str(), out_);
  std::fputc('\n', out_);
}

template <typename T> void QueryServer::write_values(const std::vector<T> &values) {
  if (!values.empty() && std::fwrite(values.data(), sizeof(T), values.size(), out_) != values.size())
    throw std::runtime_error("cannot write a reply (the reader went away)");
}

} // namespace fsi::apps
