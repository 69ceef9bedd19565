#include "CoupledMotion.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::motion {

void CoupledMotion::set(double time_s, const Eigen::Isometry3d &pose, const Vec3 &origin_velocity_m_per_s,
                        const Vec3 &angular_velocity_rad_per_s) {
  time_s_ = time_s;
  pose_ = pose;
  origin_velocity_m_per_s_ = origin_velocity_m_per_s;
  angular_velocity_rad_per_s_ = angular_velocity_rad_per_s;
  has_pose_ = true;
}

void CoupledMotion::check_time(double time_s) const {
  if (!has_pose_)
    throw std::logic_error("rigid body '" + name_ + "' is used at t = " + std::to_string(time_s) +
                           " s before the coupler sent its pose");
  // Both sides compute t = n dt in their own way: equal to round-off.
  if (std::abs(time_s - time_s_) > 1e-9 * std::max(1.0, std::abs(time_s_)))
    throw std::logic_error("rigid body '" + name_ + "' is used at t = " + std::to_string(time_s) +
                           " s, but the coupler sent its pose for t = " + std::to_string(time_s_) + " s");
}

Eigen::Isometry3d CoupledMotion::pose_at(double time_s) const {
  check_time(time_s);
  return pose_;
}

Eigen::Vector3d CoupledMotion::velocity_at(const Eigen::Vector3d &world_point_m, double time_s) const {
  check_time(time_s);
  return origin_velocity_m_per_s_ + angular_velocity_rad_per_s_.cross(world_point_m - pose_.translation());
}

} // namespace fsi::motion
