// RegionSurface::split_caps on a tetrahedron whose edge 0-1 carries a midpoint: one face is
// split at it and the other face keeps the edge whole, which leaves a cap (0, 1, m) of zero area
// closing the surface, as gmsh leaves one where a CAD edge is split differently on its two faces.
#include "pump/RegionSurface.hpp"

#include <gtest/gtest.h>

namespace {

using fsi::Vec3;
using fsi::pump::RegionSurface;

RegionSurface tetrahedron_with_a_cap() {
  RegionSurface s;
  s.region_names = {"split", "whole", "cap", "rest"};
  s.vertices_m = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.5, 0, 0)};
  // Outward: the faces of the tetrahedron (0, 1, 2, 3) counter-clockwise from outside.
  s.triangles = {{0, 2, 4}, {4, 2, 1}, // z = 0 face (0, 2, 1) split at m = 4
                 {0, 1, 3},            // y = 0 face keeps the edge 0-1 whole
                 {1, 0, 4},            // the cap: 1 -> 0 pairs with 0 -> 1, then 0 -> 4 and 4 -> 1
                 {0, 3, 2},            // x = 0
                 {1, 2, 3}};           // the slanted face
  s.triangle_regions = {0, 0, 1, 2, 3, 3};
  return s;
}

double smallest_doubled_area(const RegionSurface &s) {
  double smallest = 1e300;
  for (const auto &t : s.triangles)
    smallest = std::min(
        smallest, (s.vertices_m[t[1]] - s.vertices_m[t[0]]).cross(s.vertices_m[t[2]] - s.vertices_m[t[0]]).norm());
  return smallest;
}

TEST(RegionSurface, ACapIsRemovedByASplitOfItsNeighbourKeepingTheSurfaceClosedAndOutward) {
  RegionSurface s = tetrahedron_with_a_cap();
  ASSERT_NO_THROW(s.check_closed_and_outward("tetrahedron")); // closed, but with a cap
  EXPECT_EQ(smallest_doubled_area(s), 0.0);
  const double volume = s.enclosed_volume_m3();
  EXPECT_EQ(s.split_caps(), 1);
  EXPECT_NO_THROW(s.check_closed_and_outward("tetrahedron"));
  EXPECT_EQ(s.triangles.size(), 6u);                  // the cap became half of its neighbour
  EXPECT_NEAR(smallest_doubled_area(s), 0.5, 1e-15);  // each half of the y = 0 face: area 1/4
  EXPECT_NEAR(s.enclosed_volume_m3(), volume, 1e-15); // 1/6: the shape is unchanged
  EXPECT_NEAR(s.region_area_m2(1), 0.5, 1e-15);       // the y = 0 face keeps its region
  EXPECT_EQ(s.region_area_m2(2), 0.0);                // and the cap's is gone
  EXPECT_EQ(s.split_caps(), 0);                       // nothing left to do
}

TEST(RegionSurface, ATriangleWithTwoCoincidentVerticesIsNotTakenForACap) {
  RegionSurface s = tetrahedron_with_a_cap();
  s.vertices_m[4] = s.vertices_m[0]; // the "midpoint" on vertex 0
  EXPECT_EQ(s.split_caps(), 0);
}

} // namespace
