#include "structure_solver/output/ResultsReader.hpp"

#include "hdf5/H5Attributes.hpp"
#include "hdf5/H5Error.hpp"
#include "hdf5/H5FileAccess.hpp"
#include "structure_solver/output/ResultsPaths.hpp"

#include <algorithm>
#include <stdexcept>

namespace fsi::structure::output {
namespace {

hdf5::H5Handle open_file(const std::filesystem::path &h5_path) {
  hdf5::silence_hdf5_error_printing();
  const std::string what = "cannot open the results file '" + h5_path.string() + "'";
  const hdf5::H5Handle access = hdf5::file_access_without_locking(what);
  return hdf5::H5Handle::file(H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, access.get()), what);
}

herr_t collect_link_name(hid_t, const char *name, const H5L_info_t *, void *names) {
  static_cast<std::vector<std::string> *>(names)->emplace_back(name);
  return 0;
}

/// Selects rows [first_row, first_row + n_rows) of a dataset in its file space.
hdf5::H5Handle select_rows(hid_t dataset_id, hsize_t first_row, hsize_t n_rows,
                     std::vector<hsize_t> &count, const std::string &what) {
  hdf5::H5Handle space = hdf5::H5Handle::dataspace(H5Dget_space(dataset_id), what);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  count.assign(static_cast<std::size_t>(std::max(rank, 0)), 0);
  H5Sget_simple_extent_dims(space.get(), count.data(), nullptr);
  std::vector<hsize_t> start(count.size(), 0);
  start[0] = first_row;
  count[0] = n_rows;
  hdf5::check_hdf5(H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                                 nullptr),
             what);
  return space;
}

} // namespace

ResultsReader::ResultsReader(const std::filesystem::path &h5_path)
    : h5_path_(h5_path), file_(open_file(h5_path_)) {}

long ResultsReader::n_saved() const {
  // The rows the writer has marked complete (files without the marker: all of /time_s).
  const auto rows = static_cast<std::int64_t>(dataset_shape(std::string("/") + paths::time_s).at(0));
  return static_cast<long>(std::min(rows, hdf5::read_int64_attribute(file_.get(), "complete_steps", rows)));
}

std::vector<double> ResultsReader::time_s() const {
  return leading_doubles(std::string("/") + paths::time_s, static_cast<hsize_t>(n_saved()));
}

std::vector<std::int64_t> ResultsReader::steps() const {
  const std::string what = context("cannot read /step");
  if (n_saved() == 0) {
    return {};
  }
  hdf5::H5Handle dataset = open_dataset(std::string("/") + paths::step);
  std::vector<hsize_t> count;
  hdf5::H5Handle file_space = select_rows(dataset.get(), 0, static_cast<hsize_t>(n_saved()), count, what);
  hdf5::H5Handle memory_space = hdf5::H5Handle::dataspace(H5Screate_simple(1, count.data(), nullptr), what);
  std::vector<std::int64_t> values(count[0]);
  hdf5::check_hdf5(H5Dread(dataset.get(), H5T_NATIVE_INT64, memory_space.get(), file_space.get(),
                     H5P_DEFAULT, values.data()),
             what);
  return values;
}

std::vector<std::string> ResultsReader::structure_names() const {
  return group_members(std::string("/") + paths::structures_group);
}

std::vector<std::string> ResultsReader::probe_names() const {
  const std::string group = std::string("/") + paths::probes_group;
  if (H5Lexists(file_.get(), group.c_str(), H5P_DEFAULT) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    return {};
  }
  return group_members(group);
}

PointArray ResultsReader::probe_series(const std::string &probe, const std::string &dataset) const {
  const std::string path = paths::probe_dataset(probe, dataset);
  const std::string what = context("cannot read " + path);
  const auto n_rows = static_cast<hsize_t>(n_saved());
  PointArray rows(static_cast<Eigen::Index>(n_rows), 3);
  if (n_rows == 0) {
    return rows;
  }
  hdf5::H5Handle data = open_dataset(path);
  std::vector<hsize_t> count;
  hdf5::H5Handle file_space = select_rows(data.get(), 0, n_rows, count, what);
  if (count.size() != 2 || count[1] != 3) {
    throw std::runtime_error(what + ": expected a [n_saved, 3] dataset");
  }
  hdf5::H5Handle memory_space = hdf5::H5Handle::dataspace(H5Screate_simple(2, count.data(), nullptr), what);
  hdf5::check_hdf5(H5Dread(data.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                     H5P_DEFAULT, rows.data()),
             what);
  return rows;
}

std::vector<std::string> ResultsReader::group_members(const std::string &group_path) const {
  hdf5::H5Handle group = open_object(group_path);
  std::vector<std::string> names;
  hdf5::check_hdf5(
      H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_link_name, &names),
      context("cannot list " + group_path));
  return names;
}

StructureLayout ResultsReader::layout(const std::string &structure) const {
  require_structure(structure);
  const std::string group = paths::structure_group(structure);
  const std::vector<std::int64_t> shape = int_attribute(group, "grid_shape");
  if (shape.size() != 2) {
    throw std::runtime_error(context(group + ": grid_shape must hold 2 values"));
  }
  return {structure, string_attribute(group, "model"), static_cast<int>(shape[0]),
          static_cast<int>(shape[1])};
}

Connectivity ResultsReader::connectivity(const std::string &structure) const {
  require_structure(structure);
  const std::string path = paths::structure_dataset(structure, paths::connectivity);
  const std::string what = context("cannot read " + path);
  hdf5::H5Handle dataset = open_dataset(path);
  const std::vector<hsize_t> shape = dataset_shape(path);
  if (shape.size() != 2) {
    throw std::runtime_error(what + ": expected a 2-D dataset");
  }
  Connectivity cells{std::vector<std::int64_t>(shape[0] * shape[1]), static_cast<int>(shape[1])};
  hdf5::check_hdf5(H5Dread(dataset.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                     cells.node_indices.data()),
             what);
  return cells;
}

PointArray ResultsReader::position_m(const std::string &structure, long saved_index) const {
  require_structure(structure);
  return point_row(paths::structure_dataset(structure, paths::position_m), saved_index);
}

PointArray ResultsReader::velocity_m_per_s(const std::string &structure, long saved_index) const {
  require_structure(structure);
  return point_row(paths::structure_dataset(structure, paths::velocity_m_per_s), saved_index);
}

std::vector<double> ResultsReader::structure_series(const std::string &structure,
                                                    const std::string &dataset) const {
  require_structure(structure);
  return leading_doubles(paths::structure_dataset(structure, dataset),
                         static_cast<hsize_t>(n_saved()));
}

std::vector<hsize_t> ResultsReader::dataset_shape(const std::string &dataset_path) const {
  const std::string what = context("cannot read the shape of " + dataset_path);
  hdf5::H5Handle dataset = open_dataset(dataset_path);
  hdf5::H5Handle space = hdf5::H5Handle::dataspace(H5Dget_space(dataset.get()), what);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) {
    hdf5::throw_hdf5_error(what);
  }
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

std::string ResultsReader::string_attribute(const std::string &object_path,
                                            const std::string &name) const {
  try {
    return hdf5::read_string_attribute(open_object(object_path).get(), name);
  } catch (const std::runtime_error &error) {
    throw std::runtime_error(context(error.what()));
  }
}

std::vector<std::int64_t> ResultsReader::int_attribute(const std::string &object_path,
                                                       const std::string &name) const {
  try {
    return hdf5::read_int64_array_attribute(open_object(object_path).get(), name);
  } catch (const std::runtime_error &error) {
    throw std::runtime_error(context(error.what()));
  }
}

void ResultsReader::require_structure(const std::string &structure) const {
  const std::string group = paths::structure_group(structure);
  if (H5Lexists(file_.get(), group.c_str(), H5P_DEFAULT) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    std::string known;
    for (const std::string &name : structure_names()) {
      known += (known.empty() ? "" : ", ") + name;
    }
    throw std::out_of_range(context("no structure '" + structure + "'; the file has: " + known));
  }
}

hdf5::H5Handle ResultsReader::open_dataset(const std::string &dataset_path) const {
  return hdf5::H5Handle::dataset(H5Dopen2(file_.get(), dataset_path.c_str(), H5P_DEFAULT),
                           context("cannot open dataset " + dataset_path));
}

hdf5::H5Handle ResultsReader::open_object(const std::string &object_path) const {
  return {H5Oopen(file_.get(), object_path.c_str(), H5P_DEFAULT), H5Oclose,
          context("cannot open " + object_path)};
}

PointArray ResultsReader::point_row(const std::string &dataset_path, long saved_index) const {
  const std::string what =
      context("cannot read row " + std::to_string(saved_index) + " of " + dataset_path);
  if (saved_index < 0 || saved_index >= n_saved()) {
    throw std::out_of_range(what + ": the file holds " + std::to_string(n_saved()) + " steps");
  }
  hdf5::H5Handle dataset = open_dataset(dataset_path);
  std::vector<hsize_t> count;
  hdf5::H5Handle file_space =
      select_rows(dataset.get(), static_cast<hsize_t>(saved_index), 1, count, what);
  if (count.size() != 3 || count[2] != 3) {
    throw std::runtime_error(what + ": expected a [n_saved, n_points, 3] dataset");
  }
  hdf5::H5Handle memory_space = hdf5::H5Handle::dataspace(H5Screate_simple(3, count.data(), nullptr), what);
  PointArray points(static_cast<Eigen::Index>(count[1]), 3);
  hdf5::check_hdf5(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                     H5P_DEFAULT, points.data()),
             what);
  return points;
}

std::vector<double> ResultsReader::leading_doubles(const std::string &dataset_path,
                                                   hsize_t n_values) const {
  const std::string what = context("cannot read " + dataset_path);
  if (n_values == 0) {
    return {};
  }
  hdf5::H5Handle dataset = open_dataset(dataset_path);
  std::vector<hsize_t> count;
  hdf5::H5Handle file_space = select_rows(dataset.get(), 0, n_values, count, what);
  hdf5::H5Handle memory_space = hdf5::H5Handle::dataspace(H5Screate_simple(1, &n_values, nullptr), what);
  std::vector<double> values(n_values);
  hdf5::check_hdf5(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(),
                     H5P_DEFAULT, values.data()),
             what);
  return values;
}

std::string ResultsReader::context(const std::string &what) const {
  return "results file '" + h5_path_.string() + "': " + what;
}

} // namespace fsi::structure::output
