#pragma once
// One moving rigid body at one time, as the coupler sends it (RigidBodyPose): its pose (body
// frame -> world) and its rigid velocity field v(x) = v_o + omega x (x - o), o the body origin
// in the world. SI units.

#include "Protocol.hpp"
#include "common/Types.hpp"

#include <Eigen/Geometry>

#include <string>

namespace fsi::proto {

struct BodyPose {
  std::string name;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Vec3 origin_velocity_m_per_s = Vec3::Zero();
  Vec3 angular_velocity_rad_per_s = Vec3::Zero();
};

void write_body_pose(const BodyPose &pose, v2::RigidBodyPose &out);
/// Throws MalformedMessageError for a field of the wrong size or a rotation that is not one.
BodyPose read_body_pose(const v2::RigidBodyPose &in);

} // namespace fsi::proto
