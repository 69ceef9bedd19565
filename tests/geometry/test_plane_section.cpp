// Plane sections of closed meshes against exact areas: a box cut straight and obliquely, a
// polygonal cylinder across and along its axis (vertices on the plane), a ring's two loops,
// and the half-plane restriction on a volute-like rectangular section.

#include "geometry/MeshGenerators.hpp"
#include "geometry/PlaneSection.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::geometry {
namespace {

constexpr double kExact = 1e-14; // m^2: round-off only

/// Area of the regular n-gon of circumradius r.
double polygon_area(int n, double r) { return 0.5 * n * r * r * std::sin(2.0 * M_PI / n); }

TEST(PlaneSection, BoxCutAcrossIsItsFootprintAndObliquelyAStrip) {
  const TriangleSoup box = make_box(Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1));
  const PlaneSection across = plane_section(box, {Vec3(0, 0, 0.05), Vec3::UnitZ()});
  EXPECT_NEAR(across.area_m2, 0.3 * 0.2, kExact);
  ASSERT_EQ(across.loops_m.size(), 1u);
  EXPECT_EQ(across.n_open_chains, 0u);
  // x + y = 0.25 crosses the footprint from (0.05, 0.2) to (0.25, 0): a strip 0.2 sqrt(2) by 0.1.
  const PlaneSection oblique = plane_section(box, {Vec3(0.15, 0.1, 0.0), Vec3(1, 1, 0)});
  EXPECT_NEAR(oblique.area_m2, 0.2 * std::sqrt(2.0) * 0.1, kExact);
  EXPECT_NEAR(plane_section(box, {Vec3(0, 0, 0.05), -Vec3::UnitZ()}).area_m2, 0.06, kExact); // either normal
}

TEST(PlaneSection, HalfPlaneKeepsOnlyItsSide) {
  const TriangleSoup box = make_box(Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1));
  const PlaneSection half =
      plane_section(box, {Vec3(0, 0, 0.05), Vec3::UnitZ()}, HalfPlaneLimit{Vec3(0.1, 0.0, 0.7), Vec3(1, 0, 0.3)});
  EXPECT_NEAR(half.area_m2, 0.2 * 0.2, kExact);
  ASSERT_EQ(half.loop_areas_m2.size(), 1u);
  EXPECT_NEAR(half.loop_areas_m2[0], half.area_m2, kExact);
  ASSERT_EQ(half.loops_m[0].size(), 8u); // the whole section: two triangles on each side
}

TEST(PlaneSection, CylinderAcrossIsThePolygonAndAlongTheAxisARectangle) {
  const int n = 64;
  const double r = 0.05, height = 0.12;
  const TriangleSoup cylinder = make_ring(Vec3(0, 0, -0.02), 0.0, r, height, n);
  EXPECT_NEAR(plane_section(cylinder, {Vec3(0, 0, 0.01), Vec3::UnitZ()}).area_m2, polygon_area(n, r), kExact);
  // The plane y = 0 holds two corners of each circle and the cap centres: zero-length pieces.
  const PlaneSection along = plane_section(cylinder, {Vec3::Zero(), Vec3::UnitY()});
  EXPECT_NEAR(along.area_m2, 2.0 * r * height, kExact);
  EXPECT_EQ(along.loops_m.size(), 1u);
  EXPECT_EQ(along.n_open_chains, 0u);
}

TEST(PlaneSection, RingGivesAnOuterLoopAndANegativeHole) {
  const int n = 40;
  const TriangleSoup ring = make_ring(Vec3::Zero(), 0.03, 0.05, 0.02, n);
  const PlaneSection section = plane_section(ring, {Vec3(0, 0, 0.01), Vec3::UnitZ()});
  ASSERT_EQ(section.loop_areas_m2.size(), 2u);
  const double outer = std::max(section.loop_areas_m2[0], section.loop_areas_m2[1]);
  const double hole = std::min(section.loop_areas_m2[0], section.loop_areas_m2[1]);
  EXPECT_NEAR(outer, polygon_area(n, 0.05), kExact);
  EXPECT_NEAR(hole, -polygon_area(n, 0.03), kExact);
  EXPECT_NEAR(section.area_m2, outer + hole, kExact);
}

/// The throat of a volute-like casing: a rectangular ring section (r from r_in to r_out, z
/// from 0 to b) in the half-plane through the axis at angle phi, beyond radius r3.
double ring_throat_area(const TriangleSoup &ring, double phi, double r3) {
  const Vec3 radial(std::cos(phi), std::sin(phi), 0.0);
  return plane_section(ring, {Vec3::Zero(), Vec3::UnitZ().cross(radial)}, HalfPlaneLimit{r3 * radial, radial}).area_m2;
}

TEST(PlaneSection, VoluteLikeRectangleSectionBeyondTheBaseCircle) {
  const int n = 72;
  const double r_in = 0.08, r_out = 0.16, b = 0.05;
  const TriangleSoup ring = make_ring(Vec3::Zero(), r_in, r_out, b, n);
  const double at_corner = 2.0 * M_PI * 5 / n, mid_edge = 2.0 * M_PI * 5.5 / n;
  EXPECT_NEAR(ring_throat_area(ring, at_corner, 0.0), (r_out - r_in) * b, kExact); // one side only
  EXPECT_NEAR(ring_throat_area(ring, at_corner, 0.1), (r_out - 0.1) * b, kExact);
  EXPECT_NEAR(ring_throat_area(ring, mid_edge, 0.05), (r_out - r_in) * std::cos(M_PI / n) * b, kExact);
}

TEST(PlaneSection, InvertedMeshGivesANegativeAreaAndAnOpenOneOpenChains) {
  TriangleSoup box = make_box(Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1));
  TriangleSoup inverted = box;
  inverted.triangles.col(1).swap(inverted.triangles.col(2));
  EXPECT_NEAR(plane_section(inverted, {Vec3(0, 0, 0.05), Vec3::UnitZ()}).area_m2, -0.06, kExact);
  box.triangles.conservativeResize(11, 3); // the last x+ triangle missing
  const PlaneSection open = plane_section(box, {Vec3(0, 0, 0.05), Vec3::UnitZ()});
  EXPECT_EQ(open.n_open_chains, 1u);
  EXPECT_TRUE(open.loops_m.empty());
}

} // namespace
} // namespace fsi::geometry
