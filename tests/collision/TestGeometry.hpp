#pragma once
// Shared test helpers: the meshes of the oracle tests and random point clouds around them.

#include "structure_solver/collision/MeshGenerators.hpp"
#include "structure_solver/collision/TriangleSoup.hpp"

#include <Eigen/Geometry>

#include <random>
#include <vector>

namespace fsi::structure::collision::testing {

inline TriangleSoup test_icosphere() { return make_icosphere(Vec3(0.1, -0.2, 0.3), 0.5, 3); }

inline TriangleSoup test_torus() { return make_torus(Vec3(-0.1, 0.05, 0.0), 0.6, 0.2, 36, 18); }

/// Uniform random points in the soup's bounding box grown by `grow` times its size.
inline std::vector<Vec3> random_points_around(const TriangleSoup &soup, int n_points, double grow,
                                              unsigned seed) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index v = 0; v < soup.vertices_m.rows(); ++v) {
    box.extend(Vec3(soup.vertices_m.row(v).transpose()));
  }
  const Vec3 lo = box.min() - grow * box.sizes(), hi = box.max() + grow * box.sizes();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points;
  for (int n = 0; n < n_points; ++n) {
    points.push_back(lo + Vec3(unit(rng), unit(rng), unit(rng)).cwiseProduct(hi - lo));
  }
  return points;
}

inline PointArray to_point_array(const std::vector<Vec3> &points) {
  PointArray array(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    array.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  }
  return array;
}

} // namespace fsi::structure::collision::testing
