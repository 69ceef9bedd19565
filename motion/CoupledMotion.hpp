#pragma once
// A prescribed rigid motion as a coupled participant sees it: not evaluated here, but the pose
// and velocity the coupler sent for the time the participant is about to use (section 2.3:
// the coupler "updates the position of internal immersed rigid surfaces"; it is the only
// process of a coupled run that evaluates a prescribed motion). Asking for another time is a
// programming error of the protocol (the participant and the coupler disagree about the step)
// and throws std::logic_error naming both times.

#include "RigidMotion.hpp"
#include "common/Types.hpp"

#include <string>

namespace fsi::motion {

class CoupledMotion final : public RigidMotion {
public:
  explicit CoupledMotion(std::string name) : name_(std::move(name)) {}

  /// The pose at time_s and the rigid velocity field v(x) = v_o + omega x (x - o), with o the
  /// pose's translation (the body origin in the world).
  void set(double time_s, const Eigen::Isometry3d &pose, const Vec3 &origin_velocity_m_per_s,
           const Vec3 &angular_velocity_rad_per_s);

  Eigen::Isometry3d pose_at(double time_s) const override;
  Eigen::Vector3d velocity_at(const Eigen::Vector3d &world_point_m, double time_s) const override;

  const std::string &name() const { return name_; }
  bool has_pose() const { return has_pose_; }

private:
  void check_time(double time_s) const;

  std::string name_;
  bool has_pose_ = false;
  double time_s_ = 0.0;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  Vec3 origin_velocity_m_per_s_ = Vec3::Zero();
  Vec3 angular_velocity_rad_per_s_ = Vec3::Zero();
};

} // namespace fsi::motion
