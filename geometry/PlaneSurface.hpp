#pragma once
// An infinite plane wall; the fluid is on the side the normal points to.

#include "geometry/RigidSurface.hpp"

namespace fsi::geometry {

class PlaneSurface final : public RigidSurface {
public:
  /// point_m: any point of the plane; normal: points into the fluid (any non-zero length,
  /// normalised here). Throws std::invalid_argument for a zero or non-finite normal.
  PlaneSurface(const Vec3 &point_m, const Vec3 &normal);

  SurfaceDistance distance(const Vec3 &point_body_m) const override;
  std::string describe() const override;
  bool may_be_within(const Vec3 &point_body_m, double radius_m) const override;

private:
  Vec3 point_m_;
  Vec3 unit_normal_;
};

} // namespace fsi::geometry
