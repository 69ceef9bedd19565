#include "BruteForceMesh.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace fsi::geometry::testing {

Vec3 closest_point_on_triangle(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a; // vertex region a
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b; // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return a + d1 / (d1 - d3) * ab; // edge ab
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c; // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return a + d2 / (d2 - d6) * ac; // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b); // edge bc
  }
  const double denom = 1.0 / (va + vb + vc); // face region
  return a + ab * (vb * denom) + ac * (vc * denom);
}

Vec3 BruteForceMesh::closest_point(const Vec3 &p) const {
  Vec3 best = p;
  double best_sq = std::numeric_limits<double>::infinity();
  for (Eigen::Index t = 0; t < soup_.triangles.rows(); ++t) {
    const Vec3 q = closest_point_on_triangle(p, corner(t, 0), corner(t, 1), corner(t, 2));
    const double sq = (q - p).squaredNorm();
    if (sq < best_sq) {
      best_sq = sq;
      best = q;
    }
  }
  return best;
}

double BruteForceMesh::winding_number(const Vec3 &p) const {
  double total_solid_angle = 0.0;
  for (Eigen::Index t = 0; t < soup_.triangles.rows(); ++t) {
    const Vec3 a = corner(t, 0) - p, b = corner(t, 1) - p, c = corner(t, 2) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    total_solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return total_solid_angle / (4.0 * M_PI);
}

bool BruteForceMesh::is_inside(const Vec3 &p) const { return std::abs(winding_number(p)) > 0.5; }

double BruteForceMesh::signed_distance(const Vec3 &p, bool fluid_outside) const {
  const bool in_fluid = is_inside(p) != fluid_outside;
  return (in_fluid ? 1.0 : -1.0) * unsigned_distance(p);
}

} // namespace fsi::geometry::testing
