#include "structure_solver/output/StructureSeries.hpp"

#include "hdf5/H5Attributes.hpp"
#include "hdf5/H5Error.hpp"
#include "structure_solver/output/ResultsPaths.hpp"

#include <limits>
#include <stdexcept>

namespace fsi::structure::output {
namespace {

/// Scalar series grow by one value per saved step; 1024 values (8 KiB) per chunk.
constexpr hsize_t scalar_rows_per_chunk = 1024;

hdf5::H5Handle create_group(hid_t parent_id, const std::string &name) {
  return hdf5::H5Handle::group(H5Gcreate2(parent_id, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         "cannot create group '" + name + "' in " + hdf5::hdf5_object_name(parent_id));
}

void check_points(const PointArray *points, const char *name, const StructureLayout &layout) {
  const std::string where = "structure '" + layout.name + "': " + name;
  if (points == nullptr) {
    throw std::invalid_argument(where + " is missing (null pointer)");
  }
  if (points->rows() != layout.n_points()) {
    throw std::invalid_argument(where + " has " + std::to_string(points->rows()) +
                                " points, the grid has " + std::to_string(layout.n_points()));
  }
}

} // namespace

StructureSeries::StructureSeries(hid_t structures_group_id, const StructureLayout &layout,
                                 const Connectivity &connectivity)
    : layout_(layout), group_(create_group(structures_group_id, layout.name)),
      position_m_(point_series(paths::position_m, "m")),
      velocity_m_per_s_(point_series(paths::velocity_m_per_s, "m/s")),
      max_stretch_ratio_(scalar_series(paths::max_stretch_ratio, "1")),
      kinetic_energy_j_(scalar_series(paths::kinetic_energy_j, "J")),
      elastic_energy_j_(scalar_series(paths::elastic_energy_j, "J")),
      potential_energy_j_(scalar_series(paths::potential_energy_j, "J")) {
  write_group_attributes();
  write_connectivity(connectivity);
}

void StructureSeries::check(const StructureState &state) const {
  check_points(state.position_m, paths::position_m, layout_);
  check_points(state.velocity_m_per_s, paths::velocity_m_per_s, layout_);
}

void StructureSeries::append(const StructureState &state) {
  position_m_.append_row(state.position_m->data());
  velocity_m_per_s_.append_row(state.velocity_m_per_s->data());
  max_stretch_ratio_.append_row(&state.max_stretch_ratio);
  kinetic_energy_j_.append_row(&state.kinetic_energy_j);
  elastic_energy_j_.append_row(&state.elastic_energy_j);
  potential_energy_j_.append_row(&state.potential_energy_j);
}

void StructureSeries::write_group_attributes() {
  hdf5::write_string_attribute(group_.get(), "model", layout_.model);
  hdf5::write_int64_array_attribute(group_.get(), "grid_shape", {layout_.n1, layout_.n2});
  hdf5::write_string_attribute(group_.get(), "point_order", paths::point_order);
  hdf5::write_double_attribute(group_.get(), "release_time_s", layout_.release_time_s);
  set_exit(std::numeric_limits<double>::quiet_NaN(), "");
}

void StructureSeries::set_exit(double time_s, const std::string &reason) {
  hdf5::write_double_attribute(group_.get(), "exit_time_s", time_s);
  hdf5::write_string_attribute(group_.get(), "exit_reason", reason);
}

void StructureSeries::write_connectivity(const Connectivity &connectivity) {
  const std::string what =
      "cannot write " + paths::structure_dataset(layout_.name, paths::connectivity);
  const hsize_t dims[2] = {connectivity.n_cells(),
                           static_cast<hsize_t>(connectivity.nodes_per_cell)};
  hdf5::H5Handle space = hdf5::H5Handle::dataspace(H5Screate_simple(2, dims, nullptr), what);
  hdf5::H5Handle dataset =
      hdf5::H5Handle::dataset(H5Dcreate2(group_.get(), paths::connectivity, H5T_STD_I64LE, space.get(),
                                   H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                        what);
  hdf5::check_hdf5(H5Dwrite(dataset.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                      connectivity.node_indices.data()),
             what);
  hdf5::write_string_attribute(dataset.get(), "units", "1");
}

/// [n_saved, n_points, 3] doubles, one chunk per saved step.
hdf5::ExtendableDataset StructureSeries::point_series(const char *name, const char *units) const {
  const auto n_points = static_cast<hsize_t>(layout_.n_points());
  return hdf5::ExtendableDataset(group_.get(), name, hdf5::ExtendableDataset::ElementType::float64,
                           {n_points, 3}, 1, units);
}

hdf5::ExtendableDataset StructureSeries::scalar_series(const char *name, const char *units) const {
  return hdf5::ExtendableDataset(group_.get(), name, hdf5::ExtendableDataset::ElementType::float64, {},
                           scalar_rows_per_chunk, units);
}

} // namespace fsi::structure::output
