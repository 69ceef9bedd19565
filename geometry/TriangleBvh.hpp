#pragma once
// Bounding-volume hierarchy over a triangle mesh for exact closest-triangle queries in double
// precision: a binary tree of axis-aligned boxes (stored as floats rounded outwards, so they
// still contain their triangles), split at the median of the triangle centroids along the
// longest axis, visited nearest box first and pruned by the best distance found so far.

#include "common/Types.hpp"
#include "geometry/TrianglePoint.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace fsi::geometry {

class TriangleBvh {
public:
  using Triangle = std::array<Vec3, 3>;

  /// The closest triangle to a point.
  struct Nearest {
    std::int32_t face = -1;    ///< index into the constructor's triangles
    TrianglePoint closest;     ///< closest point on that triangle and its feature
    double distance_sq_m2 = 0; ///< squared distance to `closest`
  };

  explicit TriangleBvh(const std::vector<Triangle> &triangles);

  /// Exact closest triangle to p. `start_face` (optional, -1 for none) is a triangle
  /// believed to be close: its distance bounds the search from the start.
  Nearest nearest(const Vec3 &point_m, std::int32_t start_face = -1) const;

  /// Exact closest triangle to p if one lies within max_distance_m (inclusive); otherwise
  /// face -1 and an infinite distance. The bound prunes the search from the start, so far
  /// points cost a few box tests.
  Nearest nearest_within(const Vec3 &point_m, double max_distance_m) const;

  std::size_t n_nodes() const { return nodes_.size(); }

private:
  struct Node {
    std::array<float, 3> lo; ///< box, rounded down
    std::array<float, 3> hi; ///< box, rounded up
    std::uint32_t first;     ///< leaf: first triangle; inner node: index of the second child
    std::uint32_t count;     ///< leaf: number of triangles; inner node: 0 (first child follows)
  };

  /// Builds the subtree of triangles [begin, end) of order_ and returns its node index.
  std::uint32_t build(std::uint32_t begin, std::uint32_t end,
                      const std::vector<Triangle> &triangles, const std::vector<Vec3> &centroids);
  /// Depth-first search improving `best` (whose distance bounds it from the start).
  void search(const Vec3 &p, Nearest &best) const;
  double box_distance_sq(const Node &node, const Vec3 &p) const;
  void test_triangle(std::uint32_t slot, const Vec3 &p, Nearest &best) const;

  std::vector<Node> nodes_;
  std::vector<Triangle> triangles_; ///< in leaf order
  std::vector<std::int32_t> face_;  ///< original index of each triangle in leaf order
  std::vector<std::uint32_t> slot_; ///< leaf-order slot of each original triangle
};

} // namespace fsi::geometry
