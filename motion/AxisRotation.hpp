#pragma once
// Rigid rotation about a fixed axis with a prescribed angle history theta(t):
// x_world = p + R(theta(t)) (x_body - p). The body frame coincides with the world frame at
// theta = 0. All prescribed motions of this project (constant rate, harmonic oscillation,
// free pendulum, tabulated angle) are of this kind; they differ only in theta(t).

#include "RigidMotion.hpp"
#include "common/Types.hpp"

#include <functional>

namespace fsi::motion {

class AxisRotation final : public RigidMotion {
public:
  using AngleHistory = std::function<double(double time_s)>;

  /// `angle_rad(t)` and its derivative `rate_rad_per_s(t)`; `axis_direction` need not be unit.
  AxisRotation(const Vec3 &axis_point_m, const Vec3 &axis_direction, AngleHistory angle_rad,
               AngleHistory rate_rad_per_s);

  Eigen::Isometry3d pose_at(double time_s) const override;
  Eigen::Vector3d velocity_at(const Eigen::Vector3d &world_point_m, double time_s) const override;

  double angle_rad(double time_s) const { return angle_(time_s); }
  double rate_rad_per_s(double time_s) const { return rate_(time_s); }
  const Vec3 &axis_point_m() const { return point_; }
  const Vec3 &axis_direction() const { return axis_; }

private:
  Vec3 point_;
  Vec3 axis_;
  AngleHistory angle_;
  AngleHistory rate_;
};

} // namespace fsi::motion
