// Cells of the Lagrangian grids: counts, orientation and rejected layouts.

#include "structure_solver/output/StructureTopology.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fsi::structure::output {
namespace {

/// Shoelace area of quad `cell` with point i1 * n2 + i2 placed at (s1, s2) = (i1, i2).
double signed_area_in_parameter_plane(const Connectivity &cells, std::size_t cell, int n2) {
  double twice_area = 0.0;
  for (int corner = 0; corner < 4; ++corner) {
    const auto a = cells.node_indices[4 * cell + corner];
    const auto b = cells.node_indices[4 * cell + (corner + 1) % 4];
    twice_area += double(a / n2) * double(b % n2) - double(b / n2) * double(a % n2);
  }
  return 0.5 * twice_area;
}

TEST(StructureTopology, EveryMembraneQuadIsAUnitCounterClockwiseCell) {
  const StructureLayout layout{"sheet", "membrane", 7, 5};
  const Connectivity cells = connectivity_of(layout);
  ASSERT_EQ(cells.nodes_per_cell, 4);
  ASSERT_EQ(cells.n_cells(), 6u * 4u);
  for (std::size_t cell = 0; cell < cells.n_cells(); ++cell) {
    EXPECT_DOUBLE_EQ(signed_area_in_parameter_plane(cells, cell, layout.n2), 1.0) << cell;
  }
  EXPECT_EQ(xdmf_topology_type(cells), "Quadrilateral");
}

TEST(StructureTopology, FilamentHasOneSegmentPerPairOfNeighbours) {
  const Connectivity cells = connectivity_of({"fiber", "filament", 9, 1});
  EXPECT_EQ(cells.nodes_per_cell, 2);
  EXPECT_EQ(cells.n_cells(), 8u);
  EXPECT_EQ(xdmf_topology_type(cells), "Polyline");
}

TEST(StructureTopology, InvalidLayoutsAreRejectedWithTheStructureName) {
  const StructureLayout invalid[] = {
      {"wide_fiber", "filament", 5, 2}, {"tiny", "membrane", 1, 3}, {"shell", "plate", 4, 4},
      {"a/b", "membrane", 4, 4},        {"", "membrane", 4, 4},
  };
  for (const StructureLayout &layout : invalid) {
    try {
      check_layout(layout);
      ADD_FAILURE() << "accepted " << layout.name;
    } catch (const std::invalid_argument &error) {
      EXPECT_NE(std::string(error.what()).find("'" + layout.name + "'"), std::string::npos)
          << error.what();
    }
  }
}

TEST(StructureTopology, UnknownModelMessageListsTheValidModels) {
  try {
    check_layout({"shell", "plate", 4, 4});
    FAIL() << "accepted model 'plate'";
  } catch (const std::invalid_argument &error) {
    EXPECT_NE(std::string(error.what()).find("membrane, filament"), std::string::npos);
  }
}

} // namespace
} // namespace fsi::structure::output
