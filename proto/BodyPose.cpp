#include "BodyPose.hpp"

#include "TransportError.hpp"
#include "PackedPoints.hpp"

namespace fsi::proto {

void write_body_pose(const BodyPose &pose, v2::RigidBodyPose &out) {
  out.set_name(pose.name);
  write_matrix3(pose.pose.linear(), *out.mutable_rotation());
  write_vector3(pose.pose.translation(), *out.mutable_translation_m());
  write_vector3(pose.angular_velocity_rad_per_s, *out.mutable_angular_velocity_rad_per_s());
  write_vector3(pose.origin_velocity_m_per_s, *out.mutable_linear_velocity_m_per_s());
}

BodyPose read_body_pose(const v2::RigidBodyPose &in) {
  BodyPose pose;
  pose.name = in.name();
  const Eigen::Matrix3d rotation = read_matrix3(in.rotation(), "RigidBodyPose.rotation");
  if (!((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9))
    throw MalformedMessageError("RigidBodyPose.rotation of '" + in.name() + "' is not a rotation matrix");
  pose.pose.linear() = rotation;
  pose.pose.translation() = read_vector3(in.translation_m(), "RigidBodyPose.translation_m");
  pose.angular_velocity_rad_per_s = read_vector3(in.angular_velocity_rad_per_s(), "RigidBodyPose.angular_velocity_rad_per_s");
  pose.origin_velocity_m_per_s = read_vector3(in.linear_velocity_m_per_s(), "RigidBodyPose.linear_velocity_m_per_s");
  return pose;
}

} // namespace fsi::proto
