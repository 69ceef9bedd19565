#pragma once
// A finite solid cylinder with flat end caps and the fluid outside: the pole of a water
// tunnel, a shaft.

#include "geometry/RigidSurface.hpp"

namespace fsi::geometry {

class CylinderSurface final : public RigidSurface {
public:
  /// The axis runs from axis_start_m to axis_end_m (the cap centres). Throws
  /// std::invalid_argument for a zero-length axis or a non-positive radius.
  CylinderSurface(const Vec3 &axis_start_m, const Vec3 &axis_end_m, double radius_m);

  SurfaceDistance distance(const Vec3 &point_body_m) const override;
  std::string describe() const override;
  bool may_be_within(const Vec3 &point_body_m, double radius_m) const override;

private:
  /// A unit vector perpendicular to the axis, used for points exactly on the axis.
  Vec3 any_radial_direction() const;

  Vec3 axis_start_m_;
  Vec3 axis_end_m_;
  Vec3 centre_m_;
  Vec3 unit_axis_;
  double half_length_m_;
  double radius_m_;
};

} // namespace fsi::geometry
