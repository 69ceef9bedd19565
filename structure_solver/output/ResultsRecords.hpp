#pragma once
// Plain records exchanged with the results writer: what a run is, how each structure's points
// are laid out, and what one saved step holds. All quantities are SI (m, s, m/s, J).

#include "common/Types.hpp"

#include <string>
#include <vector>

namespace fsi::structure::output {

/// Describes the run; stored as attributes of the HDF5 root group.
struct RunMetadata {
  std::string config_yaml;  ///< effective configuration (defaults included), as YAML text
  std::string code_version; ///< e.g. a git describe string
};

/// Lagrangian grid of one structure. Points are ordered row-major over (s1, s2):
/// index = i1 * n2 + i2.
struct StructureLayout {
  std::string name;  ///< HDF5 group name: letters, digits, '_', '-', '.'
  std::string model; ///< "membrane" or "filament"
  int n1 = 0;        ///< points along s1 (>= 2)
  int n2 = 1;        ///< points along s2; a filament has n2 == 1
  double release_time_s = 0.0; ///< when it entered the scene (structures[].release_time_s)

  int n_points() const { return n1 * n2; }
};

/// State of one structure at a saved step. The arrays are borrowed for the call only.
struct StructureState {
  const PointArray *position_m = nullptr;       ///< [n_points, 3]
  const PointArray *velocity_m_per_s = nullptr; ///< [n_points, 3]
  double max_stretch_ratio = 1.0;
  double kinetic_energy_j = 0.0;
  double elastic_energy_j = 0.0;
  double potential_energy_j = 0.0;
};

/// A probe (a tracked place of a structure) at a saved step.
struct ProbeState {
  Vec3 position_m = Vec3::Zero();
  Vec3 velocity_m_per_s = Vec3::Zero();
};

/// One saved step; `structures` is in the order of ResultsWriter::add_structure(), `probes` in
/// the order of ResultsWriter::add_probe().
struct StepRecord {
  long step = 0;
  double time_s = 0.0;
  std::vector<StructureState> structures;
  std::vector<ProbeState> probes;
};

} // namespace fsi::structure::output
