#include "PackedPoints.hpp"

#include "TransportError.hpp"

#include <climits>
#include <cstring>
#include <string>

namespace fsi::proto {

namespace {

constexpr Eigen::Index values_per_point = 3;
using RowMajorMatrix3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

int checked_value_count(Eigen::Index n_points) {
  if (n_points < 0 || n_points > INT_MAX / values_per_point) {
    throw TransportError("cannot pack " + std::to_string(n_points) +
                         " points: a Protobuf array holds at most " +
                         std::to_string(INT_MAX / values_per_point) + " points");
  }
  return static_cast<int>(n_points * values_per_point);
}

double *replace_values(PackedDoubles &field, int n_values) {
  field.Clear();
  field.Reserve(n_values);
  return n_values == 0 ? nullptr : field.AddNAlreadyReserved(n_values);
}

void write_values(const double *values, int n_values, PackedDoubles &field) {
  double *target = replace_values(field, n_values);
  if (n_values > 0) {
    std::memcpy(target, values, sizeof(double) * static_cast<std::size_t>(n_values));
  }
}

void require_size(const PackedDoubles &field, int n_values, std::string_view field_name,
                  const char *what) {
  if (field.size() != n_values) {
    throw MalformedMessageError(std::string(field_name) + " holds " + std::to_string(field.size()) +
                                " values, expected " + std::to_string(n_values) + " (" + what +
                                ")");
  }
}

} // namespace

void write_points(const PointArray &points, PackedDoubles &field) {
  write_values(points.data(), checked_value_count(points.rows()), field);
}

MutablePointsView resize_points(PackedDoubles &field, Eigen::Index n_points) {
  double *values = replace_values(field, checked_value_count(n_points));
  return MutablePointsView(values, n_points, values_per_point);
}

PointsView view_points(const PackedDoubles &field, std::string_view field_name) {
  if (field.size() % values_per_point != 0) {
    throw MalformedMessageError(std::string(field_name) + " holds " + std::to_string(field.size()) +
                                " values, not a multiple of 3 (x y z per point)");
  }
  return PointsView(field.data(), field.size() / values_per_point, values_per_point);
}

PointsView view_points(const PackedDoubles &field, Eigen::Index expected_n_points,
                       std::string_view field_name) {
  const std::string what = std::to_string(expected_n_points) + " points x 3";
  require_size(field, checked_value_count(expected_n_points), field_name, what.c_str());
  return PointsView(field.data(), expected_n_points, values_per_point);
}

void read_points(const PackedDoubles &field, std::string_view field_name, PointArray &points) {
  points = view_points(field, field_name);
}

void read_points(const PackedDoubles &field, Eigen::Index expected_n_points,
                 std::string_view field_name, PointArray &points) {
  points = view_points(field, expected_n_points, field_name);
}

void write_vector3(const Vec3 &vector, PackedDoubles &field) {
  write_values(vector.data(), 3, field);
}

Vec3 read_vector3(const PackedDoubles &field, std::string_view field_name) {
  require_size(field, 3, field_name, "x y z");
  return Vec3(field.Get(0), field.Get(1), field.Get(2));
}

void write_matrix3(const Eigen::Matrix3d &matrix, PackedDoubles &field) {
  const RowMajorMatrix3 row_major = matrix;
  write_values(row_major.data(), 9, field);
}

Eigen::Matrix3d read_matrix3(const PackedDoubles &field, std::string_view field_name) {
  require_size(field, 9, field_name, "3 x 3, row-major");
  return Eigen::Map<const RowMajorMatrix3>(field.data());
}

} // namespace fsi::proto
