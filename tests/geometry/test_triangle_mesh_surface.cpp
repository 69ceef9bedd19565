// TriangleMeshSurface against the brute-force oracle (every triangle, winding number) on
// thousands of random points around an icosphere and a torus: signed distance within 1e-9 m,
// identical inside/outside classification, with and without the voxel culling grid. Points
// crowded around vertices and edges (of spheres, a torus with saddle vertices, a cube and a
// sphere with a concave pit) check the pseudo-normal signs where they are most fragile.

#include "BruteForceMesh.hpp"
#include "TestGeometry.hpp"

#include "geometry/MeshErrors.hpp"
#include "geometry/TriangleMeshSurface.hpp"
#include "geometry/TriangleSoupChecks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace fsi::geometry {
namespace {

using testing::BruteForceMesh;
using FluidSide = TriangleMeshSurface::FluidSide;

constexpr double kDistanceTol_m = 1e-9;

/// Random points in the bounding box plus points within 2 cm of the surface.
std::vector<Vec3> oracle_test_points(const TriangleSoup &soup, const BruteForceMesh &oracle) {
  std::vector<Vec3> points = testing::random_points_around(soup, 1500, 0.3, 11);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> offset_m(-0.02, 0.02);
  for (const Vec3 &far : testing::random_points_around(soup, 500, 0.3, 13)) {
    const Vec3 closest = oracle.closest_point(far);
    points.push_back(closest + offset_m(rng) * (far - closest).normalized());
  }
  return points;
}

void expect_matches_oracle(const TriangleSoup &soup, FluidSide side, double culling_radius_m) {
  const auto surface = TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, side);
  if (culling_radius_m > 0.0)
    surface->prepare_culling(culling_radius_m);
  const BruteForceMesh oracle(soup);
  const bool fluid_outside = side == FluidSide::outside;
  for (const Vec3 &p : oracle_test_points(soup, oracle)) {
    const SurfaceDistance d = surface->distance(p);
    ASSERT_NEAR(d.signed_distance_m, oracle.signed_distance(p, fluid_outside), kDistanceTol_m)
        << "at " << p.transpose();
    ASSERT_EQ(surface->is_inside_mesh(p), oracle.is_inside(p)) << "at " << p.transpose();
    ASSERT_NEAR(d.normal_into_fluid.norm(), 1.0, 1e-12);
    // Walking back along the normal by the signed distance lands on the surface.
    const Vec3 foot = p - d.signed_distance_m * d.normal_into_fluid;
    ASSERT_LT(oracle.unsigned_distance(foot), kDistanceTol_m) << "at " << p.transpose();
  }
}

/// Points at distances from 1e-6 to 3e-2 m in 26 directions around a vertex, the midpoint
/// and a fifth of an edge of each listed triangle, kept only when clearly off the surface
/// (the oracle's winding number is ill-conditioned on it).
std::vector<Vec3> feature_points(const TriangleSoup &soup, const BruteForceMesh &oracle,
                                 const std::vector<Eigen::Index> &triangles) {
  std::vector<Vec3> anchors;
  for (const Eigen::Index t : triangles) {
    const Vec3 a = soup.vertices_m.row(soup.triangles(t, 0)).transpose();
    const Vec3 b = soup.vertices_m.row(soup.triangles(t, 1)).transpose();
    anchors.insert(anchors.end(), {a, 0.5 * (a + b), 0.8 * a + 0.2 * b});
  }
  std::vector<Vec3> points;
  for (const Vec3 &anchor : anchors) {
    for (int d = 0; d < 27; ++d) {
      const Vec3 direction(d % 3 - 1.0, (d / 3) % 3 - 1.0, d / 9 - 1.0);
      if (d == 13)
        continue; // the zero direction
      for (const double offset_m : {1e-6, 1e-3, 3e-2}) {
        const Vec3 p = anchor + offset_m * direction.normalized();
        if (oracle.unsigned_distance(p) > 1e-3 * offset_m)
          points.push_back(p);
      }
    }
  }
  return points;
}

std::vector<Eigen::Index> every_nth_triangle(const TriangleSoup &soup, Eigen::Index stride) {
  std::vector<Eigen::Index> triangles;
  for (Eigen::Index t = 0; t < soup.triangles.rows(); t += stride)
    triangles.push_back(t);
  return triangles;
}

void expect_feature_points_match_oracle(const TriangleSoup &soup,
                                        const std::vector<Eigen::Index> &triangles) {
  const BruteForceMesh oracle(soup);
  const std::vector<Vec3> points = feature_points(soup, oracle, triangles);
  std::vector<double> expected_m;
  std::vector<bool> expected_inside;
  for (const Vec3 &p : points) {
    expected_m.push_back(oracle.signed_distance(p, true));
    expected_inside.push_back(oracle.is_inside(p));
  }
  for (const double culling_radius_m : {0.0, 0.004}) {
    const auto surface =
        TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, FluidSide::outside);
    if (culling_radius_m > 0.0)
      surface->prepare_culling(culling_radius_m);
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_NEAR(surface->distance(points[k]).signed_distance_m, expected_m[k], kDistanceTol_m)
          << "at " << points[k].transpose() << ", culling radius " << culling_radius_m;
      ASSERT_EQ(surface->is_inside_mesh(points[k]), expected_inside[k])
          << "at " << points[k].transpose() << ", culling radius " << culling_radius_m;
    }
  }
}

TEST(TriangleMeshSurface, PointsAroundIcosphereVerticesAndEdgesMatchOracle) {
  const TriangleSoup sphere = testing::test_icosphere();
  expect_feature_points_match_oracle(sphere, every_nth_triangle(sphere, 53));
}

TEST(TriangleMeshSurface, PointsAroundTorusVerticesAndEdgesMatchOracle) {
  const TriangleSoup torus = testing::test_torus(); // saddle vertices on the inner side
  expect_feature_points_match_oracle(torus, every_nth_triangle(torus, 41));
}

TEST(TriangleMeshSurface, PointsAroundCubeCornersAndEdgesMatchOracle) {
  const TriangleSoup cube = testing::test_cube();
  expect_feature_points_match_oracle(cube, every_nth_triangle(cube, 1));
}

TEST(TriangleMeshSurface, PointsAroundAKnifeEdgeMatchOracle) {
  const TriangleSoup blade = testing::test_blade();
  expect_feature_points_match_oracle(blade, every_nth_triangle(blade, 1));
  expect_matches_oracle(blade, FluidSide::outside, 0.01);
}

TEST(TriangleMeshSurface, PointsInAConcavePitMatchOracle) {
  const TriangleSoup crater = testing::test_crater();
  std::vector<Eigen::Index> walls; // triangles joining the pit's floor to the rim
  for (Eigen::Index t = 0; t < crater.triangles.rows(); ++t) {
    const double r0 = crater.vertices_m.row(crater.triangles(t, 0)).norm();
    const double r1 = crater.vertices_m.row(crater.triangles(t, 1)).norm();
    const double r2 = crater.vertices_m.row(crater.triangles(t, 2)).norm();
    if (std::max({r0, r1, r2}) - std::min({r0, r1, r2}) > 0.1 && t % 2 == 0)
      walls.push_back(t);
  }
  ASSERT_GT(walls.size(), 10u);
  expect_feature_points_match_oracle(crater, walls);
  expect_matches_oracle(crater, FluidSide::outside, 0.01);
}

TEST(TriangleMeshSurface, IcosphereMatchesBruteForceOracle) {
  expect_matches_oracle(testing::test_icosphere(), FluidSide::outside, 0.0);
}

TEST(TriangleMeshSurface, TorusMatchesBruteForceOracle) {
  expect_matches_oracle(testing::test_torus(), FluidSide::outside, 0.0);
}

TEST(TriangleMeshSurface, TorusWithCullingGridMatchesBruteForceOracle) {
  expect_matches_oracle(testing::test_torus(), FluidSide::outside, 0.01);
}

TEST(TriangleMeshSurface, CasingWithFluidInsideFlipsTheSign) {
  expect_matches_oracle(testing::test_icosphere(), FluidSide::inside, 0.03);
}

/// A sphere of radius 0.5 with a spherical cavity of radius 0.3 (inner shell facing inwards).
TriangleSoup hollow_sphere() {
  TriangleSoup inner = make_icosphere(Vec3(0.05, 0.0, 0.0), 0.3, 2);
  inner.triangles.col(1).swap(inner.triangles.col(2));
  return append_soup(make_icosphere(Vec3::Zero(), 0.5, 3), inner);
}

TEST(TriangleMeshSurface, HollowSphereCavityIsFluidWithCullingGrid) {
  expect_matches_oracle(hollow_sphere(), FluidSide::outside, 0.01);
  const TriangleSoup soup = hollow_sphere();
  const auto surface =
      TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, FluidSide::outside);
  surface->prepare_culling(0.01);
  EXPECT_FALSE(surface->may_be_within(Vec3(0.05, 0.0, 0.0), 0.01)); // cavity centre
  EXPECT_TRUE(surface->may_be_within(Vec3(0.0, 0.0, 0.4), 0.01));   // inside the shell wall
}

TEST(TriangleMeshSurface, CullingNeverHidesAPointThatNeedsCorrection) {
  const double radius_m = 0.02;
  for (FluidSide side : {FluidSide::outside, FluidSide::inside}) {
    const TriangleSoup soup = testing::test_torus();
    const auto surface = TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, side);
    surface->prepare_culling(radius_m);
    for (const Vec3 &p : testing::random_points_around(soup, 20000, 0.5, 17)) {
      if (!surface->may_be_within(p, radius_m)) {
        ASSERT_GE(surface->distance(p).signed_distance_m, radius_m) << "at " << p.transpose();
      }
    }
  }
}

TEST(TriangleMeshSurface, InconsistentTriangleOrientationIsRepaired) {
  TriangleSoup soup = testing::test_icosphere();
  for (Eigen::Index t = 0; t < soup.triangles.rows(); t += 3) {
    std::swap(soup.triangles(t, 1), soup.triangles(t, 2));
  }
  const auto surface =
      TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, FluidSide::outside);
  const SurfaceDistance centre = surface->distance(Vec3(0.1, -0.2, 0.3));
  EXPECT_LT(centre.signed_distance_m, -0.49);
  EXPECT_GT(surface->enclosed_volume_m3(), 0.0);
}

TEST(TriangleMeshSurface, VolumeMatchesPolyhedronFormula) {
  const TriangleSoup soup = testing::test_icosphere();
  const double volume_m3 = signed_volume_m3(soup); // divergence theorem over the generated triangles
  const auto surface =
      TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, FluidSide::outside);
  EXPECT_NEAR(surface->enclosed_volume_m3(), std::abs(volume_m3), 1e-12);
  EXPECT_EQ(surface->n_triangles(), 1280u);
}

TEST(TriangleMeshSurface, NonFinitePointGetsANaNDistance) {
  const TriangleSoup soup = testing::test_icosphere();
  const auto surface =
      TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, FluidSide::outside);
  const Vec3 nan_point = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(surface->distance(nan_point).signed_distance_m));
  surface->prepare_culling(0.01);
  EXPECT_TRUE(std::isnan(surface->distance(nan_point).signed_distance_m));
}

TEST(TriangleMeshSurface, FlatClosedMeshIsDegenerate) {
  PointArray vertices(3, 3);
  vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  TriangleArray triangles(2, 3);
  triangles << 0, 1, 2, 0, 2, 1;
  EXPECT_THROW(
      TriangleMeshSurface::from_triangles(vertices, triangles, FluidSide::outside, "pillow"),
      MeshDegenerateError);
}

} // namespace
} // namespace fsi::geometry
