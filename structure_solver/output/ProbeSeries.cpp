#include "structure_solver/output/ProbeSeries.hpp"

#include "hdf5/H5Error.hpp"
#include "structure_solver/output/ResultsPaths.hpp"

namespace fsi::structure::output {
namespace {

/// A probe row is 3 doubles; 256 rows (6 KiB) per chunk.
constexpr hsize_t probe_rows_per_chunk = 256;

hdf5::H5Handle create_group(hid_t parent_id, const std::string &name) {
  return hdf5::H5Handle::group(H5Gcreate2(parent_id, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         "cannot create group '" + name + "' in " + hdf5::hdf5_object_name(parent_id));
}

} // namespace

ProbeSeries::ProbeSeries(hid_t probes_group_id, const std::string &name)
    : name_(name), group_(create_group(probes_group_id, name)),
      position_m_(vector_series(paths::position_m, "m")),
      velocity_m_per_s_(vector_series(paths::velocity_m_per_s, "m/s")) {}

void ProbeSeries::append(const ProbeState &state) {
  position_m_.append_row(state.position_m.data());
  velocity_m_per_s_.append_row(state.velocity_m_per_s.data());
}

hdf5::ExtendableDataset ProbeSeries::vector_series(const char *dataset, const char *units) const {
  return hdf5::ExtendableDataset(group_.get(), dataset, hdf5::ExtendableDataset::ElementType::float64, {3},
                           probe_rows_per_chunk, units);
}

} // namespace fsi::structure::output
