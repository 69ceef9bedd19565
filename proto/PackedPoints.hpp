#pragma once
// Packed double arrays of the protocol <-> N x 3 row-major point arrays (fsi::PointArray).
// Both are x0 y0 z0 x1 y1 z1 ..., so a field is filled with one memcpy and read through an
// Eigen::Map without copying. A field of the wrong size is the sender's fault: the checks
// throw MalformedMessageError naming the field, as the caller spells it.

#include "common/Types.hpp"

#include <google/protobuf/repeated_field.h>

#include <string_view>

namespace fsi::proto {

using PackedDoubles = google::protobuf::RepeatedField<double>;
using PointsView = Eigen::Map<const PointArray>;
using MutablePointsView = Eigen::Map<PointArray>;

/// Replaces the field's values by the points (one copy, no zero-fill).
void write_points(const PointArray &points, PackedDoubles &field);

/// Resizes the field to n_points x 3 and returns a view to fill in place (values undefined).
MutablePointsView resize_points(PackedDoubles &field, Eigen::Index n_points);

/// The field as n x 3 points without copying; throws unless it holds a multiple of 3 values.
/// The view is valid while the field is alive and not resized.
PointsView view_points(const PackedDoubles &field, std::string_view field_name);
/// As above, and throws unless it holds exactly expected_n_points points.
PointsView view_points(const PackedDoubles &field, Eigen::Index expected_n_points,
                       std::string_view field_name);

/// Copies the field into points (resized if needed), with the checks of view_points.
void read_points(const PackedDoubles &field, std::string_view field_name, PointArray &points);
void read_points(const PackedDoubles &field, Eigen::Index expected_n_points,
                 std::string_view field_name, PointArray &points);

/// A 3-vector (translation_m, force_n, ...) into and out of a field of exactly 3 values.
void write_vector3(const Vec3 &vector, PackedDoubles &field);
Vec3 read_vector3(const PackedDoubles &field, std::string_view field_name);

/// A 3 x 3 matrix (RigidBodyPose.rotation) as 9 values, row-major.
void write_matrix3(const Eigen::Matrix3d &matrix, PackedDoubles &field);
Eigen::Matrix3d read_matrix3(const PackedDoubles &field, std::string_view field_name);

} // namespace fsi::proto
