#pragma once
// Meshes and point sets for the tests of fsi::fluid::ibm: hexahedral grids on the cube
// [0, L]^3, described as OpenFOAM would (cell centres and volumes), and random points.

#include "fluid_adapter/ibm/EulerianCells.hpp"

#include <vector>

namespace fsi::fluid::ibm::testing {


/// n^3 cubic cells of edge L/n.
EulerianCells uniform_grid(int n, double length_m);
/// n^3 boxes: face i along each axis at L g(i/n), g(s) = s + a sin(2 pi s) / (2 pi), so the
/// spacing varies smoothly by the factor (1 + a) / (1 - a) across the cube (0 <= a < 1).
EulerianCells stretched_grid(int n, double length_m, double stretching);
/// The cells of `cells` listed in `keep`, in that order.
EulerianCells subset(const EulerianCells &cells, const std::vector<CellId> &keep);
/// n points uniformly random in [lo, hi]^3 (reproducible for a given seed).
PointArray random_points(int n, double lo_m, double hi_m, unsigned seed);

} // namespace fsi::fluid::ibm::testing
