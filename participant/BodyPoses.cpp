#include "BodyPoses.hpp"

#include "proto/PackedPoints.hpp"

namespace fsi::participant {

std::vector<proto::BodyPose> read_poses(const google::protobuf::RepeatedPtrField<proto::v2::RigidBodyPose> &poses) {
  std::vector<proto::BodyPose> out;
  out.reserve(static_cast<std::size_t>(poses.size()));
  for (const auto &pose : poses)
    out.push_back(proto::read_body_pose(pose));
  return out;
}

void write_loads(const std::vector<BodyLoad> &loads,
                 google::protobuf::RepeatedPtrField<proto::v2::RigidBodyLoad> &out) {
  out.Clear();
  for (const BodyLoad &load : loads) {
    auto *message = out.Add();
    message->set_name(load.name);
    proto::write_vector3(load.force_n, *message->mutable_force_n());
    proto::write_vector3(load.torque_n_m, *message->mutable_torque_n_m());
  }
}

} // namespace fsi::participant
