#pragma once
// Test oracle for TriangleMeshSurface: a loop over every triangle (closest point by Ericson's
// region test, Real-Time Collision Detection 5.1.5) and an inside test by the generalized
// winding number (sum of solid angles, Van Oosterom & Strackee 1983). Slow on purpose:
// nothing here shares code with the accelerated implementation.

#include "geometry/TriangleSoup.hpp"

namespace fsi::geometry::testing {

/// Closest point of triangle abc to p.
Vec3 closest_point_on_triangle(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c);

class BruteForceMesh {
public:
  explicit BruteForceMesh(TriangleSoup soup) : soup_(std::move(soup)) {}

  /// Closest point of the whole mesh to p.
  Vec3 closest_point(const Vec3 &p) const;
  double unsigned_distance(const Vec3 &p) const { return (closest_point(p) - p).norm(); }
  /// Winding number of the surface around p (+-1 inside, 0 outside, sign by orientation).
  double winding_number(const Vec3 &p) const;
  bool is_inside(const Vec3 &p) const;
  /// Signed distance, positive on the fluid side.
  double signed_distance(const Vec3 &p, bool fluid_outside) const;

private:
  Vec3 corner(Eigen::Index t, int k) const {
    return soup_.vertices_m.row(soup_.triangles(t, k)).transpose();
  }

  TriangleSoup soup_;
};

} // namespace fsi::geometry::testing
