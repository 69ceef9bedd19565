#include "AxisRotation.hpp"

#include <stdexcept>

namespace fsi::motion {

AxisRotation::AxisRotation(const Vec3 &axis_point_m, const Vec3 &axis_direction, AngleHistory angle_rad,
                           AngleHistory rate_rad_per_s)
    : point_(axis_point_m), axis_(axis_direction), angle_(std::move(angle_rad)), rate_(std::move(rate_rad_per_s)) {
  if (axis_.norm() == 0.0)
    throw std::invalid_argument("rotation axis direction must not be the zero vector");
  axis_.normalize();
}

Eigen::Isometry3d AxisRotation::pose_at(double time_s) const {
  const Eigen::AngleAxisd rotation(angle_(time_s), axis_);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation.toRotationMatrix();
  pose.translation() = point_ - pose.linear() * point_;
  return pose;
}

Eigen::Vector3d AxisRotation::velocity_at(const Eigen::Vector3d &world_point_m, double time_s) const {
  return rate_(time_s) * axis_.cross(world_point_m - point_);
}

} // namespace fsi::motion
