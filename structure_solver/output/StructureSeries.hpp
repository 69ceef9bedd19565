#pragma once
// The group `/structures/<name>` of the results file: layout attributes, the connectivity,
// and the per-step datasets (positions, velocities, stretch, energies) of one structure.

#include "structure_solver/output/ExtendableDataset.hpp"
#include "structure_solver/output/H5Handle.hpp"
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

  const StructureLayout &layout() const { return layout_; }

private:
  void write_group_attributes();
  void write_connectivity(const Connectivity &connectivity);
  ExtendableDataset point_series(const char *name, const char *units) const;
  ExtendableDataset scalar_series(const char *name, const char *units) const;

  StructureLayout layout_;
  H5Handle group_;
  ExtendableDataset position_m_;
  ExtendableDataset velocity_m_per_s_;
  ExtendableDataset max_stretch_ratio_;
  ExtendableDataset kinetic_energy_j_;
  ExtendableDataset elastic_energy_j_;
  ExtendableDataset potential_energy_j_;
};

} // namespace fsi::structure::output
