#include "geometry/PlaneSurface.hpp"

#include "geometry/VectorFormat.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::geometry {

PlaneSurface::PlaneSurface(const Vec3 &point_m, const Vec3 &normal) : point_m_(point_m) {
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw std::invalid_argument("PlaneSurface: the normal " + detail::format_vec3(normal) +
                                " must be non-zero and finite; give the direction of the fluid.");
  }
  unit_normal_ = normal / length;
}

SurfaceDistance PlaneSurface::distance(const Vec3 &point_body_m) const {
  return {unit_normal_.dot(point_body_m - point_m_), unit_normal_};
}

std::string PlaneSurface::describe() const {
  return "plane through " + detail::format_vec3(point_m_) + " with fluid-side normal " +
         detail::format_vec3(unit_normal_);
}

bool PlaneSurface::may_be_within(const Vec3 &point_body_m, double radius_m) const {
  return unit_normal_.dot(point_body_m - point_m_) < radius_m;
}

} // namespace fsi::geometry
