#pragma once
// Shared test helpers: the meshes of the oracle tests and random point clouds around them.

#include "geometry/MeshGenerators.hpp"
#include "geometry/TriangleSoup.hpp"

#include <Eigen/Geometry>

#include <random>
#include <vector>

namespace fsi::geometry::testing {

inline TriangleSoup test_icosphere() { return make_icosphere(Vec3(0.1, -0.2, 0.3), 0.5, 3); }

inline TriangleSoup test_torus() { return make_torus(Vec3(-0.1, 0.05, 0.0), 0.6, 0.2, 36, 18); }

/// Axis-aligned cube [0, 0.4]^3 shifted by `origin_m`, two triangles a face (sharp convex
/// edges and corners, flat face diagonals), counter-clockwise seen from outside.
inline TriangleSoup test_cube(const Vec3 &origin_m = Vec3(0.1, -0.2, 0.05)) {
  return make_box(origin_m, origin_m + Vec3::Constant(0.4));
}

/// A thin blade: a prism whose cross-section is a wedge of about 17 degrees, extruded along
/// z (a knife edge at x = 0: its faces' normals differ by about 163 degrees).
inline TriangleSoup test_blade() {
  TriangleSoup soup;
  soup.vertices_m.resize(6, 3);
  soup.vertices_m << 0.0, 0.0, 0.0, 0.4, 0.06, 0.0, 0.4, -0.06, 0.0, //
      0.0, 0.0, 0.3, 0.4, 0.06, 0.3, 0.4, -0.06, 0.3;
  soup.triangles.resize(8, 3);
  soup.triangles << 0, 2, 1, 3, 4, 5, 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 2, 0, 3, 2, 3, 5;
  return soup;
}

/// Icosphere of radius 0.5 whose cap above z = 0.3 is pushed in to radius 0.3: a pit with a
/// sharp convex rim and concave edges and vertices where its walls meet its floor.
inline TriangleSoup test_crater() {
  TriangleSoup soup = make_icosphere(Vec3::Zero(), 0.5, 3);
  for (Eigen::Index v = 0; v < soup.vertices_m.rows(); ++v) {
    if (soup.vertices_m(v, 2) > 0.3)
      soup.vertices_m.row(v) *= 0.6;
  }
  return soup;
}

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

} // namespace fsi::geometry::testing
