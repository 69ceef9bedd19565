#pragma once
// One entry of the case's optional `probes` list: a named place on a structure (its centroid,
// the centre of one edge, or one grid point) whose position and velocity are saved at every
// saved step, in structure.h5 (/probes/<name>) and in probes.csv. For example
//   probes:
//     - {name: free_edge_centre, structure: flag, at: edge_centre, edge: s1_max}
//     - {name: tip, structure: chain, at: edge_centre, edge: end}
//     - {name: corner, structure: rag, at: point, index: [0, 25]}

#include "common/ConfigDocWriter.hpp"
#include "common/ConfigReader.hpp"

#include <string>
#include <vector>

namespace fsi::structure {

struct StructureConfig;

enum class ProbeLocation { centroid, edge_centre, point };

struct ProbeConfig {
  std::string name;
  std::string structure;
  ProbeLocation at = ProbeLocation::centroid;
  std::string edge;       ///< with at: edge_centre
  std::vector<int> index; ///< with at: point

  template <class V> void visit(V &v) {
    constexpr bool documenting = std::is_same_v<V, common::ConfigDocWriter>;
    v.text("name", name,
           "Unique probe name (letters, digits, '_', '-'): the HDF5 group /probes/<name> and the columns "
           "<name>.x_m ... <name>.w_m_per_s of probes.csv.");
    v.text("structure", structure, "The structure it follows: a name from `structures`.");
    v.choice("at", at,
             {{"centroid", ProbeLocation::centroid}, {"edge_centre", ProbeLocation::edge_centre},
              {"point", ProbeLocation::point}},
             "centroid: mean of all points weighted by the area (length) each carries, i.e. the centre of mass; "
             "edge_centre: mean of one edge's points weighted by the trapezoid rule along the edge as it is "
             "now; point: one grid point.");
    if (documenting || at == ProbeLocation::edge_centre)
      v.text("edge", edge,
             "With `at: edge_centre`: s1_min, s1_max, s2_min or s2_max (membrane); start or end (filament: that "
             "end point).");
    if (documenting || at == ProbeLocation::point)
      v.integer_list("index", index, common::Range::non_negative("1"),
                     "With `at: point`: grid indices [i1, i2] (membrane) or [i] (filament), from 0.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      validate(v);
  }

  /// Checks what needs the other structures of the case: `structure` names one of them, `edge`
  /// is an edge of its model, `index` lies on its grid. `v` reads this probe's list item.
  void check_against(const std::vector<StructureConfig> &structures, const common::ConfigReader &v) const;

  /// The edge names a probe may use on a grid with n2 points along s2 (n2 == 1: a filament).
  static std::vector<std::string> edge_names(int n2);

private:
  void validate(const common::ConfigReader &v) const;
  void check_edge(int n2, const std::string &structure_kind, const common::ConfigReader &v) const;
  void check_index(int n1, int n2, const common::ConfigReader &v) const;
};

} // namespace fsi::structure
