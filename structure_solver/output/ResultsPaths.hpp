#pragma once
// Names of the groups, datasets and attributes of the results file, shared by the writer,
// the reader and the XDMF index so that they cannot drift apart.

#include <string>

namespace fsi::structure::output::paths {

inline constexpr const char *time_s = "time_s";
inline constexpr const char *step = "step";
inline constexpr const char *structures_group = "structures";
inline constexpr const char *connectivity = "connectivity";
inline constexpr const char *position_m = "position_m";
inline constexpr const char *velocity_m_per_s = "velocity_m_per_s";
inline constexpr const char *max_stretch_ratio = "max_stretch_ratio";
inline constexpr const char *kinetic_energy_j = "kinetic_energy_j";
inline constexpr const char *elastic_energy_j = "elastic_energy_j";
inline constexpr const char *potential_energy_j = "potential_energy_j";

inline constexpr const char *probes_group = "probes";

inline constexpr const char *point_order = "row-major over (s1, s2): index = i1 * n2 + i2";

/// "/structures/<name>"
inline std::string structure_group(const std::string &structure_name) {
  return std::string("/") + structures_group + "/" + structure_name;
}

/// "/structures/<name>/<dataset>"
inline std::string structure_dataset(const std::string &structure_name,
                                     const std::string &dataset) {
  return structure_group(structure_name) + "/" + dataset;
}

/// "/probes/<name>/<dataset>"
inline std::string probe_dataset(const std::string &probe_name, const std::string &dataset) {
  return std::string("/") + probes_group + "/" + probe_name + "/" + dataset;
}

} // namespace fsi::structure::output::paths
