#include "geometry/BoxSurface.hpp"

#include "geometry/VectorFormat.hpp"

#include <limits>
#include <stdexcept>

namespace fsi::geometry {

BoxSurface::BoxSurface(const Vec3 &min_m, const Vec3 &max_m) : min_m_(min_m), max_m_(max_m) {
  if (!(min_m.array() < max_m.array()).all() || !min_m.allFinite() || !max_m.allFinite()) {
    throw std::invalid_argument("BoxSurface: min corner " + detail::format_vec3(min_m) +
                                " must be below max corner " + detail::format_vec3(max_m) +
                                " on every axis.");
  }
}

SurfaceDistance BoxSurface::distance(const Vec3 &point_body_m) const {
  const bool inside = (point_body_m.array() >= min_m_.array()).all() &&
                      (point_body_m.array() <= max_m_.array()).all();
  return inside ? distance_from_inside(point_body_m) : distance_from_outside(point_body_m);
}

SurfaceDistance BoxSurface::distance_from_inside(const Vec3 &point_m) const {
  SurfaceDistance nearest{std::numeric_limits<double>::infinity(), Vec3::UnitX()};
  for (int axis = 0; axis < 3; ++axis) {
    const double to_min_wall_m = point_m[axis] - min_m_[axis];
    const double to_max_wall_m = max_m_[axis] - point_m[axis];
    if (to_min_wall_m < nearest.signed_distance_m) {
      nearest = {to_min_wall_m, Vec3::Unit(axis)};
    }
    if (to_max_wall_m < nearest.signed_distance_m) {
      nearest = {to_max_wall_m, -Vec3::Unit(axis)};
    }
  }
  return nearest;
}

SurfaceDistance BoxSurface::distance_from_outside(const Vec3 &point_m) const {
  const Vec3 closest_m = point_m.cwiseMax(min_m_).cwiseMin(max_m_);
  const Vec3 to_box_m = closest_m - point_m;
  const double length_m = to_box_m.norm();
  return {-length_m, to_box_m / length_m};
}

std::string BoxSurface::describe() const {
  return "box (fluid inside) from " + detail::format_vec3(min_m_) + " to " +
         detail::format_vec3(max_m_);
}

bool BoxSurface::may_be_within(const Vec3 &point_body_m, double radius_m) const {
  const Vec3 lower_m = min_m_.array() + radius_m;
  const Vec3 upper_m = max_m_.array() - radius_m;
  return !((point_body_m.array() > lower_m.array()).all() &&
           (point_body_m.array() < upper_m.array()).all());
}

} // namespace fsi::geometry
