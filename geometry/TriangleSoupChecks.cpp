#include "geometry/TriangleSoupChecks.hpp"

#include "geometry/MeshErrors.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace fsi::geometry {
namespace {

/// Relative area below which a triangle counts as degenerate: |cross| <= tol * longest^2.
constexpr double kZeroAreaTolerance = 1e-12;

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

void check_indices(const TriangleSoup &soup, const std::string &source) {
  const Eigen::Index n_vertices = soup.vertices_m.rows();
  if (soup.triangles.size() > 0 &&
      (soup.triangles.minCoeff() < 0 || soup.triangles.maxCoeff() >= n_vertices)) {
    throw MeshDegenerateError(source, "a triangle refers to a vertex index outside [0, " +
                                          std::to_string(n_vertices) + ")");
  }
  if (!soup.vertices_m.allFinite()) {
    throw MeshDegenerateError(source, "a vertex has a non-finite coordinate");
  }
}

} // namespace

std::vector<std::array<int, 2>> border_edges(const TriangleArray &triangles) {
  std::unordered_map<std::uint64_t, int> uses;
  uses.reserve(static_cast<std::size_t>(triangles.rows()) * 2);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      ++uses[edge_key(triangles(t, k), triangles(t, (k + 1) % 3))];
    }
  }
  std::vector<std::array<int, 2>> border;
  for (const auto &[key, n_uses] : uses) {
    if (n_uses % 2)
      border.push_back({static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffULL)});
  }
  std::sort(border.begin(), border.end());
  return border;
}

std::size_t count_border_edges(const TriangleArray &triangles) { return border_edges(triangles).size(); }

std::size_t count_misoriented_edges(const TriangleArray &triangles) {
  std::unordered_map<std::uint64_t, int> runs; // directed edge a -> b, key (a, b) unordered
  runs.reserve(static_cast<std::size_t>(triangles.rows()) * 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      const auto key =
          (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
      ++runs[key];
    }
  }
  return static_cast<std::size_t>(
      std::count_if(runs.begin(), runs.end(), [](const auto &entry) { return entry.second > 1; }));
}

double signed_volume_m3(const TriangleSoup &soup) {
  if (soup.vertices_m.rows() == 0)
    return 0.0;
  const Vec3 origin = soup.vertices_m.row(0).transpose(); // tetrahedra from a nearby apex: less round-off
  double six_volume = 0.0;
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    const Vec3 a = soup.vertices_m.row(soup.triangles(t, 0)).transpose() - origin;
    const Vec3 b = soup.vertices_m.row(soup.triangles(t, 1)).transpose() - origin;
    const Vec3 c = soup.vertices_m.row(soup.triangles(t, 2)).transpose() - origin;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

std::size_t count_zero_area_triangles(const TriangleSoup &soup) {
  std::size_t n_zero = 0;
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    const Vec3 a = soup.vertices_m.row(soup.triangles(t, 0)).transpose();
    const Vec3 b = soup.vertices_m.row(soup.triangles(t, 1)).transpose();
    const Vec3 c = soup.vertices_m.row(soup.triangles(t, 2)).transpose();
    const double longest_sq =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if ((b - a).cross(c - a).norm() <= kZeroAreaTolerance * longest_sq) {
      ++n_zero;
    }
  }
  return n_zero;
}

void check_triangle_soup(const TriangleSoup &soup, const std::string &source) {
  if (soup.triangles.rows() == 0) {
    throw MeshDegenerateError(source, "it has no triangle");
  }
  check_indices(soup, source);
  const std::size_t n_zero_area = count_zero_area_triangles(soup);
  if (n_zero_area > 0) {
    throw MeshDegenerateError(source, std::to_string(n_zero_area) + " of " +
                                          std::to_string(soup.triangles.rows()) +
                                          " triangles have zero area");
  }
  const std::size_t n_border = count_border_edges(soup.triangles);
  if (n_border > 0) {
    throw MeshNotClosedError(source, n_border);
  }
}

} // namespace fsi::geometry
