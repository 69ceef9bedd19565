#pragma once
// The rigid bodies' fields of the step messages <-> the models' domain types: the poses the
// coupler sends (RigidBodyPose) and the loads the fluid answers (RigidBodyLoad).

#include "FluidModel.hpp"
#include "proto/Protocol.hpp"

#include <vector>

namespace fsi::participant {

/// Throws MalformedMessageError for a field of the wrong size or a rotation that is not one.
std::vector<proto::BodyPose> read_poses(const google::protobuf::RepeatedPtrField<proto::v2::RigidBodyPose> &poses);
void write_loads(const std::vector<BodyLoad> &loads, google::protobuf::RepeatedPtrField<proto::v2::RigidBodyLoad> &out);

} // namespace fsi::participant
