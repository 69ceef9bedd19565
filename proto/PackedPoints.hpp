#pragma once
// Views of N x 3 row-major point arrays (fsi::PointArray, x0 y0 z0 x1 y1 z1 ...) as the
// protocol's array frames hold them (Message), and the small packed fields of the protocol
// (vectors, rotations) <-> Eigen. A field of the wrong size is the sender's fault: the checks
// throw MalformedMessageError naming the field, as the caller spells it.

#include "common/Types.hpp"

#include <google/protobuf/repeated_field.h>

#include <string_view>

namespace fsi::proto {

using PackedDoubles = google::protobuf::RepeatedField<double>;
using PointsView = Eigen::Map<const PointArray>;
using MutablePointsView = Eigen::Map<PointArray>;

/// A 3-vector (translation_m, force_n, ...) into and out of a field of exactly 3 values.
void write_vector3(const Vec3 &vector, PackedDoubles &field);
Vec3 read_vector3(const PackedDoubles &field, std::string_view field_name);

/// A 3 x 3 matrix (RigidBodyPose.rotation) as 9 values, row-major.
void write_matrix3(const Eigen::Matrix3d &matrix, PackedDoubles &field);
Eigen::Matrix3d read_matrix3(const PackedDoubles &field, std::string_view field_name);

} // namespace fsi::proto
