#include "hdf5/ExtendableDataset.hpp"

#include "hdf5/H5Attributes.hpp"
#include "hdf5/H5Error.hpp"

#include <algorithm>
#include <stdexcept>

namespace fsi::hdf5 {
namespace {

hid_t file_type_of(ExtendableDataset::ElementType element_type) {
  return element_type == ExtendableDataset::ElementType::float64 ? H5T_IEEE_F64LE : H5T_STD_I64LE;
}

std::vector<hsize_t> with_leading(hsize_t leading, const std::vector<hsize_t> &row_dims) {
  std::vector<hsize_t> dims{leading};
  dims.insert(dims.end(), row_dims.begin(), row_dims.end());
  return dims;
}

// Rows are appended in order, so only the chunk being filled is worth caching. HDF5's default
// (1 MiB a dataset) kept every chunk written: a coupler writing 12 series a step grew by 1.2 MiB
// per 10^4 steps (measured by the soak test) until each dataset's cache was full.
constexpr std::size_t append_cache_bytes = 64 * 1024;
constexpr std::size_t append_cache_slots = 101; // a prime, as HDF5 asks

H5Handle append_access(const std::string &what) {
  H5Handle access = H5Handle::plist(H5Pcreate(H5P_DATASET_ACCESS), what);
  check_hdf5(H5Pset_chunk_cache(access.get(), append_cache_slots, append_cache_bytes, 1.0), what);
  return access;
}

H5Handle create_extendable(hid_t parent_id, const std::string &name, hid_t file_type_id,
                           const std::vector<hsize_t> &row_dims, hsize_t rows_per_chunk) {
  const std::string what = "cannot create dataset '" + name + "' in " + hdf5_object_name(parent_id);
  const std::vector<hsize_t> initial = with_leading(0, row_dims);
  const std::vector<hsize_t> maximum = with_leading(H5S_UNLIMITED, row_dims);
  const std::vector<hsize_t> chunk = with_leading(rows_per_chunk, row_dims);
  const int rank = static_cast<int>(initial.size());
  H5Handle space =
      H5Handle::dataspace(H5Screate_simple(rank, initial.data(), maximum.data()), what);
  H5Handle properties = H5Handle::plist(H5Pcreate(H5P_DATASET_CREATE), what);
  check_hdf5(H5Pset_chunk(properties.get(), rank, chunk.data()), what);
  const H5Handle access = append_access(what);
  return H5Handle::dataset(H5Dcreate2(parent_id, name.c_str(), file_type_id, space.get(),
                                      H5P_DEFAULT, properties.get(), access.get()),
                           what);
}

} // namespace

ExtendableDataset::ExtendableDataset(hid_t parent_id, const std::string &name,
                                     ElementType element_type, std::vector<hsize_t> row_dims,
                                     hsize_t rows_per_chunk, const std::string &units)
    : dataset_(
          create_extendable(parent_id, name, file_type_of(element_type), row_dims, rows_per_chunk)),
      element_type_(element_type), row_dims_(std::move(row_dims)) {
  write_string_attribute(dataset_.get(), "units", units);
}

ExtendableDataset::ExtendableDataset(hid_t parent_id, const std::string &name, ElementType element_type,
                                     hsize_t keep_rows)
    : element_type_(element_type) {
  const std::string what = "cannot open dataset '" + name + "' in " + hdf5_object_name(parent_id) + " to append";
  const H5Handle access = append_access(what);
  dataset_ = H5Handle::dataset(H5Dopen2(parent_id, name.c_str(), access.get()), what);
  H5Handle space = H5Handle::dataspace(H5Dget_space(dataset_.get()), what);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1)
    throw std::runtime_error(what + ": it is not an array");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check_hdf5(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), what);
  row_dims_.assign(dims.begin() + 1, dims.end());
  n_rows_ = std::min(dims[0], keep_rows);
  dims[0] = n_rows_;
  check_hdf5(H5Dset_extent(dataset_.get(), dims.data()), what);
}

void ExtendableDataset::append_row(const double *values) {
  if (element_type_ != ElementType::float64) {
    throw std::logic_error("append_row(double) on int64 dataset " + path());
  }
  append_raw(values, H5T_NATIVE_DOUBLE);
}

void ExtendableDataset::append_row(const std::int64_t *values) {
  if (element_type_ != ElementType::int64) {
    throw std::logic_error("append_row(int64) on float64 dataset " + path());
  }
  append_raw(values, H5T_NATIVE_INT64);
}

std::string ExtendableDataset::path() const { return hdf5_object_name(dataset_.get()); }

void ExtendableDataset::append_raw(const void *values, hid_t memory_type_id) {
  const std::string what = "cannot append row " + std::to_string(n_rows_) + " to " + path();
  const std::vector<hsize_t> extent = with_leading(n_rows_ + 1, row_dims_);
  check_hdf5(H5Dset_extent(dataset_.get(), extent.data()), what);
  H5Handle file_space = row_selection_in_file(what);
  const std::vector<hsize_t> row_shape = with_leading(1, row_dims_);
  H5Handle memory_space = H5Handle::dataspace(
      H5Screate_simple(static_cast<int>(row_shape.size()), row_shape.data(), nullptr), what);
  check_hdf5(H5Dwrite(dataset_.get(), memory_type_id, memory_space.get(), file_space.get(),
                      H5P_DEFAULT, values),
             what);
  ++n_rows_;
}

H5Handle ExtendableDataset::row_selection_in_file(const std::string &what) const {
  H5Handle file_space = H5Handle::dataspace(H5Dget_space(dataset_.get()), what);
  const std::vector<hsize_t> start =
      with_leading(n_rows_, std::vector<hsize_t>(row_dims_.size(), 0));
  const std::vector<hsize_t> count = with_leading(1, row_dims_);
  check_hdf5(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                 count.data(), nullptr),
             what);
  return file_space;
}

} // namespace fsi::hdf5
