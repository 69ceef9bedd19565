#pragma once
// Reading and writing the small attributes of the results file: UTF-8 strings (stored as
// variable-length strings, so h5py reads them as str and they may grow, e.g. `status`) and
// int64 arrays (`grid_shape`). Errors throw std::runtime_error naming object and attribute.

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace fsi::hdf5 {

/// Creates the attribute, or overwrites it when it exists.
void write_string_attribute(hid_t object_id, const std::string &name, const std::string &value);

/// Reads a string attribute (variable- or fixed-length).
std::string read_string_attribute(hid_t object_id, const std::string &name);

/// Creates a 1-D int64 attribute.
void write_int64_array_attribute(hid_t object_id, const std::string &name,
                                 const std::vector<std::int64_t> &values);

/// Creates a scalar int64 attribute, or overwrites it when it exists (a counter such as
/// `complete_steps`, rewritten after every flush).
void write_int64_attribute(hid_t object_id, const std::string &name, std::int64_t value);

/// Creates a scalar float64 attribute, or overwrites it when it exists (a time set when an
/// event happens, such as a structure's exit).
void write_double_attribute(hid_t object_id, const std::string &name, double value);

/// Reads a scalar integer attribute; `fallback` when there is none.
std::int64_t read_int64_attribute(hid_t object_id, const std::string &name, std::int64_t fallback);

/// Reads a 1-D integer attribute, converted to int64.
std::vector<std::int64_t> read_int64_array_attribute(hid_t object_id, const std::string &name);

} // namespace fsi::hdf5
