#pragma once
// A chunked HDF5 dataset of shape [n_rows, row_dims...] whose first dimension is unlimited:
// one row is appended per saved step. Carries a `units` attribute.

#include "hdf5/H5Handle.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace fsi::hdf5 {

class ExtendableDataset {
public:
  enum class ElementType { float64, int64 };

  /// Creates `name` under `parent_id` with zero rows. `rows_per_chunk` rows form one chunk.
  ExtendableDataset(hid_t parent_id, const std::string &name, ElementType element_type,
                    std::vector<hsize_t> row_dims, hsize_t rows_per_chunk,
                    const std::string &units);

  /// Opens the existing dataset `name` under `parent_id` (written by the constructor above) to
  /// append to it, keeping its first `keep_rows` rows (fewer if it has fewer): a restart's
  /// results continue after the checkpoint's step.
  ExtendableDataset(hid_t parent_id, const std::string &name, ElementType element_type, hsize_t keep_rows);

  /// Appends one row of doubles (product(row_dims) values, C order).
  void append_row(const double *values);
  /// Appends one row of int64 values.
  void append_row(const std::int64_t *values);

  hsize_t n_rows() const { return n_rows_; }
  std::string path() const;

private:
  void append_raw(const void *values, hid_t memory_type_id);
  H5Handle row_selection_in_file(const std::string &what) const;

  H5Handle dataset_;
  ElementType element_type_;
  std::vector<hsize_t> row_dims_;
  hsize_t n_rows_ = 0;
};

} // namespace fsi::hdf5
