#pragma once
// Cells of a structure's Lagrangian grid, as stored in `/structures/<name>/connectivity` and
// referenced by the XDMF Topology: quadrilaterals for a membrane (n2 > 1), line segments for a
// filament (or a membrane one point wide).

#include "structure_solver/output/ResultsRecords.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace fsi::structure::output {

struct Connectivity {
  std::vector<std::int64_t> node_indices; ///< n_cells * nodes_per_cell point indices, C order
  int nodes_per_cell = 0;                 ///< 4 (quadrilateral) or 2 (segment)

  std::size_t n_cells() const {
    return nodes_per_cell == 0 ? 0 : node_indices.size() / static_cast<std::size_t>(nodes_per_cell);
  }
};

/// Throws std::invalid_argument naming the structure when the layout cannot be written:
/// bad name characters, unknown model, n1 < 2, n2 < 1, a filament with n2 != 1.
void check_layout(const StructureLayout &layout);

/// Cells of the grid. Quad (i1, i2) is (i1,i2), (i1+1,i2), (i1+1,i2+1), (i1,i2+1): counter-
/// clockwise in the (s1, s2) parameter plane; quads are ordered row-major over (i1, i2).
/// Segment i1 is (i1, i1+1).
Connectivity connectivity_of(const StructureLayout &layout);

/// XDMF TopologyType for the cells: "Quadrilateral" or "Polyline".
std::string xdmf_topology_type(const Connectivity &connectivity);

} // namespace fsi::structure::output
