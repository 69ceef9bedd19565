#include "geometry/CylinderSurface.hpp"

#include "geometry/VectorFormat.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace fsi::geometry {

CylinderSurface::CylinderSurface(const Vec3 &axis_start_m, const Vec3 &axis_end_m, double radius_m)
    : axis_start_m_(axis_start_m), axis_end_m_(axis_end_m), radius_m_(radius_m) {
  const double length_m = (axis_end_m - axis_start_m).norm();
  if (!(length_m > 0.0) || !std::isfinite(length_m)) {
    throw std::invalid_argument("CylinderSurface: the axis from " +
                                detail::format_vec3(axis_start_m) + " to " +
                                detail::format_vec3(axis_end_m) + " must have a non-zero length.");
  }
  if (!(radius_m > 0.0) || !std::isfinite(radius_m)) {
    throw std::invalid_argument("CylinderSurface: radius_m = " + std::to_string(radius_m) +
                                " must be positive.");
  }
  centre_m_ = 0.5 * (axis_start_m + axis_end_m);
  unit_axis_ = (axis_end_m - axis_start_m) / length_m;
  half_length_m_ = 0.5 * length_m;
}

SurfaceDistance CylinderSurface::distance(const Vec3 &point_body_m) const {
  const Vec3 offset_m = point_body_m - centre_m_;
  const double axial_m = unit_axis_.dot(offset_m);
  const Vec3 radial_m = offset_m - axial_m * unit_axis_;
  const double radial_length_m = radial_m.norm();
  const Vec3 radial_unit =
      radial_length_m > 0.0 ? Vec3(radial_m / radial_length_m) : any_radial_direction();
  const Vec3 cap_unit = axial_m >= 0.0 ? unit_axis_ : Vec3(-unit_axis_);
  // Excess beyond the mantle and beyond the nearer cap (negative inside).
  const double beyond_mantle_m = radial_length_m - radius_m_;
  const double beyond_cap_m = std::abs(axial_m) - half_length_m_;
  if (beyond_mantle_m > 0.0 && beyond_cap_m > 0.0) { // closest point on a rim circle
    const double distance_m = std::hypot(beyond_mantle_m, beyond_cap_m);
    const Vec3 normal = (beyond_mantle_m * radial_unit + beyond_cap_m * cap_unit) / distance_m;
    return {distance_m, normal};
  }
  if (beyond_mantle_m > beyond_cap_m) {
    return {beyond_mantle_m, radial_unit};
  }
  return {beyond_cap_m, cap_unit};
}

Vec3 CylinderSurface::any_radial_direction() const {
  const Vec3 helper = std::abs(unit_axis_.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return unit_axis_.cross(helper).normalized();
}

std::string CylinderSurface::describe() const {
  return "solid cylinder from " + detail::format_vec3(axis_start_m_) + " to " +
         detail::format_vec3(axis_end_m_) + " with radius " + std::to_string(radius_m_) + " m";
}

bool CylinderSurface::may_be_within(const Vec3 &point_body_m, double radius_m) const {
  // Bounding sphere of the cylinder dilated by the query radius.
  const double reach_m = std::hypot(half_length_m_, radius_m_) + radius_m;
  return (point_body_m - centre_m_).squaredNorm() < reach_m * reach_m;
}

} // namespace fsi::geometry
