#include "hdf5/H5Attributes.hpp"

#include "hdf5/H5Error.hpp"
#include "hdf5/H5Handle.hpp"

#include <memory>
#include <stdexcept>

namespace fsi::hdf5 {
namespace {

std::string describe(hid_t object_id, const std::string &name) {
  return "attribute '" + name + "' of " + hdf5_object_name(object_id);
}

H5Handle variable_length_utf8_type(const std::string &what) {
  H5Handle type = H5Handle::datatype(H5Tcopy(H5T_C_S1), what);
  check_hdf5(H5Tset_size(type.get(), H5T_VARIABLE), what);
  check_hdf5(H5Tset_cset(type.get(), H5T_CSET_UTF8), what);
  return type;
}

H5Handle open_or_create_attribute(hid_t object_id, const std::string &name, hid_t type_id,
                                  const std::string &what) {
  const htri_t exists = H5Aexists(object_id, name.c_str());
  if (exists < 0) {
    throw_hdf5_error(what);
  }
  if (exists > 0) {
    return H5Handle::attribute(H5Aopen(object_id, name.c_str(), H5P_DEFAULT), what);
  }
  H5Handle space = H5Handle::dataspace(H5Screate(H5S_SCALAR), what);
  return H5Handle::attribute(
      H5Acreate2(object_id, name.c_str(), type_id, space.get(), H5P_DEFAULT, H5P_DEFAULT), what);
}

std::string read_variable_length_string(hid_t attribute_id, const std::string &what) {
  H5Handle memory_type = variable_length_utf8_type(what);
  char *text = nullptr;
  check_hdf5(H5Aread(attribute_id, memory_type.get(), &text), what);
  const std::unique_ptr<char, herr_t (*)(void *)> owner(text, H5free_memory);
  return text == nullptr ? std::string() : std::string(text);
}

std::string read_fixed_length_string(hid_t attribute_id, hid_t file_type_id,
                                     const std::string &what) {
  const std::size_t size = H5Tget_size(file_type_id);
  H5Handle memory_type = H5Handle::datatype(H5Tcopy(H5T_C_S1), what);
  check_hdf5(H5Tset_size(memory_type.get(), size), what);
  std::string text(size, '\0');
  check_hdf5(H5Aread(attribute_id, memory_type.get(), text.data()), what);
  return text.substr(0, text.find('\0'));
}

} // namespace

void write_string_attribute(hid_t object_id, const std::string &name, const std::string &value) {
  const std::string what = "cannot write " + describe(object_id, name);
  H5Handle type = variable_length_utf8_type(what);
  H5Handle attribute = open_or_create_attribute(object_id, name, type.get(), what);
  const char *text = value.c_str();
  check_hdf5(H5Awrite(attribute.get(), type.get(), &text), what);
}

std::string read_string_attribute(hid_t object_id, const std::string &name) {
  const std::string what = "cannot read " + describe(object_id, name);
  H5Handle attribute = H5Handle::attribute(H5Aopen(object_id, name.c_str(), H5P_DEFAULT), what);
  H5Handle file_type = H5Handle::datatype(H5Aget_type(attribute.get()), what);
  if (H5Tget_class(file_type.get()) != H5T_STRING) {
    throw std::runtime_error(what + ": not a string");
  }
  const htri_t is_variable = H5Tis_variable_str(file_type.get());
  if (is_variable < 0) {
    throw_hdf5_error(what);
  }
  return is_variable > 0 ? read_variable_length_string(attribute.get(), what)
                         : read_fixed_length_string(attribute.get(), file_type.get(), what);
}

void write_int64_array_attribute(hid_t object_id, const std::string &name,
                                 const std::vector<std::int64_t> &values) {
  const std::string what = "cannot write " + describe(object_id, name);
  const hsize_t length = values.size();
  H5Handle space = H5Handle::dataspace(H5Screate_simple(1, &length, nullptr), what);
  H5Handle attribute = H5Handle::attribute(
      H5Acreate2(object_id, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      what);
  check_hdf5(H5Awrite(attribute.get(), H5T_NATIVE_INT64, values.data()), what);
}

namespace {
/// A scalar attribute of `file_type`, created or overwritten, from one value of `memory_type`.
void write_scalar_attribute(hid_t object_id, const std::string &name, hid_t file_type, hid_t memory_type,
                            const void *value) {
  const std::string what = "cannot write " + describe(object_id, name);
  const htri_t exists = H5Aexists(object_id, name.c_str());
  check_hdf5(static_cast<herr_t>(exists < 0 ? -1 : 0), what);
  H5Handle attribute;
  if (exists > 0) {
    attribute = H5Handle::attribute(H5Aopen(object_id, name.c_str(), H5P_DEFAULT), what);
  } else {
    H5Handle space = H5Handle::dataspace(H5Screate(H5S_SCALAR), what);
    attribute = H5Handle::attribute(
        H5Acreate2(object_id, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), what);
  }
  check_hdf5(H5Awrite(attribute.get(), memory_type, value), what);
}
} // namespace

void write_int64_attribute(hid_t object_id, const std::string &name, std::int64_t value) {
  write_scalar_attribute(object_id, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void write_double_attribute(hid_t object_id, const std::string &name, double value) {
  write_scalar_attribute(object_id, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

std::int64_t read_int64_attribute(hid_t object_id, const std::string &name, std::int64_t fallback) {
  if (H5Aexists(object_id, name.c_str()) <= 0)
    return fallback;
  const std::string what = "cannot read " + describe(object_id, name);
  H5Handle attribute = H5Handle::attribute(H5Aopen(object_id, name.c_str(), H5P_DEFAULT), what);
  std::int64_t value = fallback;
  check_hdf5(H5Aread(attribute.get(), H5T_NATIVE_INT64, &value), what);
  return value;
}

std::vector<std::int64_t> read_int64_array_attribute(hid_t object_id, const std::string &name) {
  const std::string what = "cannot read " + describe(object_id, name);
  H5Handle attribute = H5Handle::attribute(H5Aopen(object_id, name.c_str(), H5P_DEFAULT), what);
  H5Handle space = H5Handle::dataspace(H5Aget_space(attribute.get()), what);
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) {
    throw_hdf5_error(what);
  }
  std::vector<std::int64_t> values(static_cast<std::size_t>(count));
  check_hdf5(H5Aread(attribute.get(), H5T_NATIVE_INT64, values.data()), what);
  return values;
}

} // namespace fsi::hdf5
