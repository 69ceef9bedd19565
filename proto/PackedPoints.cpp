#include "PackedPoints.hpp"

#include "TransportError.hpp"

#include <string>

namespace fsi::proto {

namespace {

using RowMajorMatrix3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

void write_values(const double *values, int n_values, PackedDoubles &field) {
  field.Clear();
  field.Add(values, values + n_values);
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
