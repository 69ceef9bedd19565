#pragma once
// A prescribed rigid-body motion: the pose that maps body-frame coordinates to world
// coordinates as a function of time. Used for clamped edges that follow a rigid part
// (the pendulum of section 3.1) and for moving collision surfaces (an impeller).

#include <Eigen/Geometry>

namespace fsi::motion {

class RigidMotion {
public:
  virtual ~RigidMotion() = default;

  /// Pose at time t: x_world = pose * x_body (SI: metres, seconds).
  virtual Eigen::Isometry3d pose_at(double time_s) const = 0;

  /// Velocity (m/s) at time t of the body-fixed point that is at world position x at t.
  /// The default differentiates pose_at() with a central difference; subclasses with a
  /// closed form override it.
  virtual Eigen::Vector3d velocity_at(const Eigen::Vector3d &world_point_m, double time_s) const;

  /// True when the pose never changes (lets callers skip per-step work).
  virtual bool is_static() const { return false; }
};

/// A body that does not move: pose is the identity (or a fixed placement).
class StaticPose final : public RigidMotion {
public:
  explicit StaticPose(Eigen::Isometry3d pose = Eigen::Isometry3d::Identity()) : pose_(pose) {}
  Eigen::Isometry3d pose_at(double) const override { return pose_; }
  Eigen::Vector3d velocity_at(const Eigen::Vector3d &, double) const override {
    return Eigen::Vector3d::Zero();
  }
  bool is_static() const override { return true; }

private:
  Eigen::Isometry3d pose_;
};

} // namespace fsi::motion
