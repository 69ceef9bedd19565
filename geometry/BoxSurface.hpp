#pragma once
// An axis-aligned box with the fluid INSIDE: a channel or tank seen from within. The walls are
// the six faces; everything outside the box is solid.

#include "geometry/RigidSurface.hpp"

namespace fsi::geometry {

class BoxSurface final : public RigidSurface {
public:
  /// Throws std::invalid_argument unless min_m < max_m on every axis.
  BoxSurface(const Vec3 &min_m, const Vec3 &max_m);

  SurfaceDistance distance(const Vec3 &point_body_m) const override;
  std::string describe() const override;
  bool may_be_within(const Vec3 &point_body_m, double radius_m) const override;

private:
  /// Inside the box: the nearest of the six walls, normal pointing inwards.
  SurfaceDistance distance_from_inside(const Vec3 &point_m) const;
  /// Outside the box (in the solid): distance to the box, normal towards the box.
  SurfaceDistance distance_from_outside(const Vec3 &point_m) const;

  Vec3 min_m_;
  Vec3 max_m_;
};

} // namespace fsi::geometry
