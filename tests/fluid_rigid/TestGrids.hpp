#pragma once
// Helpers of the fsi::fluid::rigid tests: uniform grids of cell centres and a brute-force
// oracle that tests every point against the surface placed in the world (CGAL's
// Side_of_triangle_mesh on the transformed vertices, independent of the library's path).

#include "common/Types.hpp"
#include "geometry/TriangleSoup.hpp"

#include <Eigen/Geometry>

#include <vector>

namespace fsi::fluid::rigid::testing {

/// Centres of the n^3 cubic cells of edge (hi - lo) / n filling the cube [lo, hi]^3.
PointArray uniform_centres(double lo_m, double hi_m, int n);

/// 1 for every point strictly inside the soup placed by `pose`, else 0 (every point tested).
std::vector<int> brute_force_inside(const geometry::TriangleSoup &body_soup,
                                    const Eigen::Isometry3d &pose, const PointArray &points_m);

/// Volume enclosed by a closed, outward-oriented soup (divergence theorem).
double enclosed_volume(const geometry::TriangleSoup &soup);

} // namespace fsi::fluid::rigid::testing
