// Multi-solid ASCII STL: the `solid NAME` blocks become regions (named, in order, blocks of
// one name merged), binary STL is one unnamed region, and writing by region reads back equal.

#include "TestGeometry.hpp"

#include "geometry/MeshGenerators.hpp"
#include "geometry/StlIo.hpp"
#include "geometry/TriangleSoupChecks.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fsi::geometry {
namespace {

std::string temp_path(const std::string &name) {
  const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
  return (std::filesystem::temp_directory_path() / ("fsi_regions_" + std::string(info->name()) + "_" + name)).string();
}

/// A box whose six faces are three regions: "bottom_top" (z faces), "sides_x", "sides_y".
RegionSoup box_with_regions() {
  RegionSoup regions{make_box(Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1)), {"bottom_top", "sides_y", "sides_x"}, {}};
  // make_box's faces two triangles each: z- z+ y- y+ x- x+.
  regions.region_of_triangle = {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2};
  return regions;
}

TEST(StlRegions, MultiSolidAsciiRoundTripKeepsRegionsAndClosedness) {
  const RegionSoup original = box_with_regions();
  const std::string file = temp_path("box.stl");
  write_stl_regions(file, original);
  const RegionSoup loaded = read_stl_regions(file);
  std::filesystem::remove(file);
  EXPECT_EQ(loaded.region_names, original.region_names);
  EXPECT_EQ(loaded.region_of_triangle, original.region_of_triangle);
  EXPECT_EQ(loaded.soup.vertices_m.rows(), 8); // shared corners welded across regions
  EXPECT_EQ(count_border_edges(loaded.soup.triangles), 0u);
  EXPECT_EQ(loaded.region_name_of(11), "sides_x");
  EXPECT_NEAR(signed_volume_m3(loaded.soup), 0.3 * 0.2 * 0.1, 1e-15);
}

TEST(StlRegions, BlocksOfTheSameNameFormOneRegionAndNamesMayHoldSpaces) {
  const std::string file = temp_path("blocks.stl");
  std::ofstream(file) << "solid  blade pressure side \n facet normal 0 0 1\n outer loop\n"
                         "  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\n endfacet\nendsolid\n"
                         "solid hub\n facet normal 0 0 1\n outer loop\n"
                         "  vertex 0 0 1\n  vertex 1 0 1\n  vertex 0 1 1\n endloop\n endfacet\nendsolid hub\n"
                         "solid blade pressure side\n facet normal 0 0 1\n outer loop\n"
                         "  vertex 0 0 2\n  vertex 1 0 2\n  vertex 0 1 2\n endloop\n endfacet\nendsolid\n";
  const RegionSoup loaded = read_stl_regions(file);
  std::filesystem::remove(file);
  ASSERT_EQ(loaded.region_names, (std::vector<std::string>{"blade pressure side", "hub"}));
  EXPECT_EQ(loaded.region_of_triangle, (std::vector<int>{0, 1, 0}));
}

TEST(StlRegions, BinaryFileIsOneUnnamedRegionAndPlainReadIgnoresRegions) {
  const TriangleSoup soup = testing::test_icosphere();
  const std::string file = temp_path("sphere.stl");
  write_stl(file, soup, StlFormat::binary);
  const RegionSoup loaded = read_stl_regions(file);
  EXPECT_EQ(read_stl(file).triangles, loaded.soup.triangles);
  std::filesystem::remove(file);
  EXPECT_EQ(loaded.region_names, std::vector<std::string>{""});
  EXPECT_EQ(loaded.region_of_triangle, std::vector<int>(static_cast<std::size_t>(soup.triangles.rows()), 0));
}

TEST(StlRegions, WritingRefusesRegionsThatDoNotMatchTheTriangles) {
  RegionSoup regions = box_with_regions();
  regions.region_of_triangle.pop_back();
  EXPECT_THROW(write_stl_regions(temp_path("short.stl"), regions), std::invalid_argument);
  regions = box_with_regions();
  regions.region_of_triangle[0] = 3;
  EXPECT_THROW(write_stl_regions(temp_path("bad.stl"), regions), std::invalid_argument);
}

TEST(SoupChecks, BorderEdgesMisorientedEdgesAndSignedVolumeOfABox) {
  TriangleSoup box = make_box(Vec3(-0.1, 0, 0), Vec3(0.2, 0.1, 0.4));
  EXPECT_NEAR(signed_volume_m3(box), 0.3 * 0.1 * 0.4, 1e-15);
  EXPECT_EQ(count_misoriented_edges(box.triangles), 0u);
  TriangleSoup inverted = box;
  inverted.triangles.col(1).swap(inverted.triangles.col(2));
  EXPECT_NEAR(signed_volume_m3(inverted), -0.3 * 0.1 * 0.4, 1e-15);
  EXPECT_EQ(count_misoriented_edges(inverted.triangles), 0u);
  std::swap(box.triangles(0, 1), box.triangles(0, 2)); // one triangle flipped: its 3 edges disagree
  EXPECT_EQ(count_misoriented_edges(box.triangles), 3u);
  box.triangles.conservativeResize(11, 3);
  const auto border = border_edges(box.triangles);
  ASSERT_EQ(border.size(), 3u);
  EXPECT_EQ(border, (std::vector<std::array<int, 2>>{{1, 5}, {1, 7}, {5, 7}}));
}

TEST(MeshGenerators, RingAndDiscAreClosedOutwardPrisms) {
  const int n = 48;
  const double polygon = 0.5 * n * std::sin(2.0 * M_PI / n); // area of the unit n-gon
  const TriangleSoup ring = make_ring(Vec3(0.1, 0, -0.2), 0.03, 0.05, 0.02, n);
  const TriangleSoup disc = make_ring(Vec3::Zero(), 0.0, 0.05, 0.02, n);
  for (const TriangleSoup *soup : {&ring, &disc}) {
    EXPECT_EQ(count_border_edges(soup->triangles), 0u);
    EXPECT_EQ(count_misoriented_edges(soup->triangles), 0u);
  }
  EXPECT_NEAR(signed_volume_m3(ring), polygon * (0.05 * 0.05 - 0.03 * 0.03) * 0.02, 1e-15);
  EXPECT_NEAR(signed_volume_m3(disc), polygon * 0.05 * 0.05 * 0.02, 1e-15);
  EXPECT_EQ(disc.vertices_m.rows(), 2 * n + 2);
  const TriangleSoup both = append_soup(ring, make_box(Vec3(1, 1, 1), Vec3(2, 2, 2)));
  EXPECT_NEAR(signed_volume_m3(both), signed_volume_m3(ring) + 1.0, 1e-12);
  EXPECT_EQ(count_border_edges(both.triangles), 0u);
}

} // namespace
} // namespace fsi::geometry
