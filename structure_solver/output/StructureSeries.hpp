#pragma once
// The group `/structures/<name>` of the results file: layout attributes, the connectivity,
// and the per-step datasets (positions, velocities, stretch, energies) of one structure. Its
// life in the scene is in two attributes: release_time_s, and exit_time_s (NaN while it stays).

#include "hdf5/ExtendableDataset.hpp"
#include "hdf5/H5Handle.hpp"
#include "structure_solver/output/ResultsRecords.hpp"
#include "structure_solver/output/StructureTopology.hpp"

namespace fsi::structure::output {

class StructureSeries {
public:
  /// Creates the group under `structures_group_id` with its attributes and connectivity.
  StructureSeries(hid_t structures_group_id, const StructureLayout &layout,
                  const Connectivity &connectivity);

  /// Throws std::invalid_argument naming the structure when `state` cannot be appended
  /// (missing arrays, wrong number of points). Writes nothing.
  void check(const StructureState &state) const;

  /// Appends one row to every per-step dataset; call check() first.
  void append(const StructureState &state);

  /// Sets the group's `exit_time_s` attribute (NaN until the structure is removed) and
  /// `exit_reason` ("" until then; "past_plane", "torn").
  void set_exit(double time_s, const std::string &reason);

  const StructureLayout &layout() const { return layout_; }

private:
  void write_group_attributes();
  void write_connectivity(const Connectivity &connectivity);
  hdf5::ExtendableDataset point_series(const char *name, const char *units) const;
  hdf5::ExtendableDataset scalar_series(const char *name, const char *units) const;

  StructureLayout layout_;
  hdf5::H5Handle group_;
  hdf5::ExtendableDataset position_m_;
  hdf5::ExtendableDataset velocity_m_per_s_;
  hdf5::ExtendableDataset max_stretch_ratio_;
  hdf5::ExtendableDataset kinetic_energy_j_;
  hdf5::ExtendableDataset elastic_energy_j_;
  hdf5::ExtendableDataset potential_energy_j_;
};

} // namespace fsi::structure::output
