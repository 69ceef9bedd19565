// The parts behind TriangleMeshSurface's fast queries, each against brute force: the
// per-cell candidate lists give the exact closest triangle, the feature regions hold every
// point whose closest point lies on their feature, the BVH finds the exact closest triangle,
// the angle-weighted pseudo-normals and the cone spreads have their closed-form values.

#include "BruteForceMesh.hpp"
#include "TestGeometry.hpp"

#include "geometry/ConeSpread.hpp"
#include "geometry/FeatureRegions.hpp"
#include "geometry/NearTriangleLists.hpp"
#include "geometry/PseudoNormals.hpp"
#include "geometry/TriangleBvh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace fsi::geometry {
namespace {

using testing::BruteForceMesh;

std::vector<VoxelSideGrid::Triangle> corners_of(const TriangleSoup &soup) {
  std::vector<VoxelSideGrid::Triangle> corners(static_cast<std::size_t>(soup.triangles.rows()));
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k)
      corners[static_cast<std::size_t>(t)][k] =
          soup.vertices_m.row(soup.triangles(t, k)).transpose();
  }
  return corners;
}

/// Points within max_offset_m of the surface (along the direction to a random far point).
std::vector<Vec3> points_near(const TriangleSoup &soup, const BruteForceMesh &oracle,
                              double max_offset_m, int n_points, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset_m(-max_offset_m, max_offset_m);
  std::vector<Vec3> points;
  for (const Vec3 &far : testing::random_points_around(soup, n_points, 0.3, seed + 1)) {
    const Vec3 closest = oracle.closest_point(far);
    points.push_back(closest + offset_m(rng) * (far - closest).normalized());
  }
  return points;
}

/// Index of the closest triangle and its closest point, by brute force.
std::pair<std::int32_t, TrianglePoint>
closest_triangle(const std::vector<VoxelSideGrid::Triangle> &corners, const Vec3 &p) {
  std::pair<std::int32_t, TrianglePoint> best{-1, {}};
  double best_sq = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < corners.size(); ++t) {
    const TrianglePoint q =
        closest_point_on_triangle(p, corners[t][0], corners[t][1], corners[t][2]);
    if ((q.point_m - p).squaredNorm() < best_sq) {
      best_sq = (q.point_m - p).squaredNorm();
      best = {static_cast<std::int32_t>(t), q};
    }
  }
  return best;
}

void expect_lists_exact(const TriangleSoup &soup, double radius_m) {
  const BruteForceMesh oracle(soup);
  const auto corners = corners_of(soup);
  const VoxelSideGrid grid(corners, radius_m, [&](const Vec3 &p) { return oracle.is_inside(p); });
  const FeatureRegions regions(soup.vertices_m, soup.triangles);
  const NearTriangleLists lists(grid, corners, regions);
  EXPECT_EQ(lists.n_cut_lists(), 0u);
  for (const Vec3 &p : points_near(soup, oracle, 2.0 * radius_m, 3000, 3)) {
    const NearTriangleLists::Hit hit = lists.nearest(p);
    const double expected_m = oracle.unsigned_distance(p);
    if (expected_m <= radius_m) { // uncut lists settle every point within the radius
      ASSERT_TRUE(hit.exact) << "at " << p.transpose();
    }
    if (hit.exact) {
      ASSERT_NEAR(std::sqrt(hit.distance_sq_m2), expected_m, 1e-12) << "at " << p.transpose();
    }
  }
}

TEST(NearTriangleLists, GiveTheExactClosestTriangleNearATorus) {
  expect_lists_exact(testing::test_torus(), 0.02);
}

TEST(NearTriangleLists, GiveTheExactClosestTriangleAtSharpAndConcaveFeatures) {
  expect_lists_exact(testing::test_cube(), 0.02);
  expect_lists_exact(testing::test_blade(), 0.01);
  expect_lists_exact(testing::test_crater(), 0.02);
}

TEST(NearTriangleLists, CutListsAnswerExactlyWhereTheyClaimTo) {
  const TriangleSoup torus = testing::test_torus();
  const BruteForceMesh oracle(torus);
  const auto corners = corners_of(torus);
  const VoxelSideGrid grid(corners, 0.02, [&](const Vec3 &p) { return oracle.is_inside(p); });
  const FeatureRegions regions(torus.vertices_m, torus.triangles);
  for (const std::size_t max_entries : {std::size_t{1} << 20, std::size_t{20000}}) {
    const NearTriangleLists lists(grid, corners, regions, 3, max_entries);
    EXPECT_GT(lists.n_cut_lists(), 0u);
    EXPECT_LE(lists.n_entries(), std::max<std::size_t>(max_entries, 3 * grid.n_near_cells()));
    std::size_t n_exact = 0, n_points = 0;
    for (const Vec3 &p : points_near(torus, oracle, 0.02, 2000, 5)) {
      const NearTriangleLists::Hit hit = lists.nearest(p);
      ASSERT_EQ(lists.state_at(p), grid.state_at(p));
      ++n_points;
      if (!hit.exact)
        continue;
      ++n_exact;
      ASSERT_NEAR(std::sqrt(hit.distance_sq_m2), oracle.unsigned_distance(p), 1e-12)
          << "at " << p.transpose();
    }
    EXPECT_GT(n_exact, 0u);
    EXPECT_LT(n_exact, n_points);
  }
}

TEST(FeatureRegions, HoldEveryPointWhoseClosestPointIsOnTheirFeature) {
  for (const TriangleSoup &soup :
       {testing::test_torus(), testing::test_blade(), testing::test_crater()}) {
    const auto corners = corners_of(soup);
    const FeatureRegions regions(soup.vertices_m, soup.triangles);
    FeatureRegions::TriangleRegions triangle;
    for (const Vec3 &p : testing::random_points_around(soup, 1500, 0.2, 9)) {
      const auto [face, closest] = closest_triangle(corners, p);
      regions.regions_of(face, 0.0, 1e-12, triangle);
      ASSERT_TRUE(FeatureRegions::may_meet_cube(triangle, p)) << "at " << p.transpose();
      // Region index: face 0, edges ab, bc, ca 1-3, vertices a, b, c 4-6.
      const auto feature = static_cast<std::size_t>(closest.feature);
      const std::size_t region = feature == 6 ? 0 : feature >= 3 ? feature - 2 : feature + 4;
      const double distance_m = (p - closest.point_m).norm();
      ASSERT_TRUE(triangle.sweep_box(region, distance_m * (1.0 + 1e-9) + 1e-12).contains(p))
          << "at " << p.transpose() << ", region " << region;
    }
  }
}

TEST(TriangleBvh, FindsTheExactClosestTriangleFromAnyStart) {
  const TriangleSoup torus = testing::test_torus();
  const BruteForceMesh oracle(torus);
  const auto corners = corners_of(torus);
  const TriangleBvh bvh(corners);
  std::int32_t start = 0;
  for (const Vec3 &p : testing::random_points_around(torus, 2000, 0.5, 21)) {
    const double expected_m = oracle.unsigned_distance(p);
    ASSERT_NEAR(std::sqrt(bvh.nearest(p).distance_sq_m2), expected_m, 1e-12);
    ASSERT_NEAR(std::sqrt(bvh.nearest(p, start).distance_sq_m2), expected_m, 1e-12);
    start = (start + 97) % static_cast<std::int32_t>(corners.size()); // any triangle, near or not
  }
}

TEST(TriangleBvh, WithinABoundIsExactInsideItAndEmptyBeyond) {
  const TriangleSoup torus = testing::test_torus();
  const BruteForceMesh oracle(torus);
  const TriangleBvh bvh(corners_of(torus));
  std::size_t n_inside = 0, n_beyond = 0;
  for (const Vec3 &p : testing::random_points_around(torus, 2000, 0.5, 23)) {
    const double expected_m = oracle.unsigned_distance(p);
    const double bound_m = 0.1;
    const TriangleBvh::Nearest hit = bvh.nearest_within(p, bound_m);
    if (expected_m <= bound_m) {
      ++n_inside;
      ASSERT_GE(hit.face, 0) << "at " << p.transpose();
      ASSERT_NEAR(std::sqrt(hit.distance_sq_m2), expected_m, 1e-12);
      ASSERT_EQ(hit.face, bvh.nearest(p).face);
    } else {
      ++n_beyond;
      ASSERT_EQ(hit.face, -1) << "at " << p.transpose();
      ASSERT_TRUE(std::isinf(hit.distance_sq_m2));
    }
    // The bound is inclusive: exactly the distance finds the triangle, even a zero distance.
    ASSERT_EQ(bvh.nearest_within(p, std::sqrt(bvh.nearest(p).distance_sq_m2)).face, bvh.nearest(p).face);
  }
  EXPECT_GT(n_inside, 100u);
  EXPECT_GT(n_beyond, 100u);
  const Vec3 on_surface = torus.vertices_m.row(0).transpose();
  EXPECT_EQ(bvh.nearest_within(on_surface, 0.0).distance_sq_m2, 0.0);
}

TEST(PseudoNormals, AreAngleWeightedAtCubeCornersAndBisectEdges) {
  const TriangleSoup cube = testing::test_cube(Vec3::Zero()); // corner v at bits of v
  const PseudoNormals normals(cube.vertices_m, cube.triangles);
  EXPECT_EQ(normals.n_undefined_features(), 0u);
  const double third = 1.0 / std::sqrt(3.0), half = 1.0 / std::sqrt(2.0);
  // Triangle 1 is 0, 3, 1 on the face z = 0: corner 3 = (1, 1, 0) has two triangles of that
  // face but one of each other face; angle weights still give the diagonal.
  EXPECT_TRUE(normals.normal(1, TriangleFeature::vertex_b).isApprox(Vec3(third, third, -third)));
  EXPECT_TRUE(normals.normal(1, TriangleFeature::vertex_a).isApprox(Vec3(-third, -third, -third)));
  EXPECT_TRUE(normals.normal(1, TriangleFeature::face).isApprox(Vec3(0, 0, -1)));
  EXPECT_TRUE(normals.normal(1, TriangleFeature::edge_ab).isApprox(Vec3(0, 0, -1))); // diagonal
  EXPECT_TRUE(normals.normal(1, TriangleFeature::edge_ca).isApprox(Vec3(0, -half, -half)));
}

TEST(ConeSpread, MatchesTheConesClosedForms) {
  // No constraint: every direction; a half-space u.z <= 0 still holds the x and y axes.
  EXPECT_TRUE(cone_spread({}).isApprox(Vec3::Ones()));
  EXPECT_TRUE(cone_spread({Vec3::UnitZ()}).isApprox(Vec3::Ones()));
  // The octant x, y, z <= 0: each axis is reached.
  EXPECT_TRUE(cone_spread({Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()}).isApprox(Vec3::Ones()));
  // Six coplanar edges around a flat vertex in the plane z = 0: only the normal line is left.
  std::vector<Vec3> edges;
  for (int k = 0; k < 6; ++k)
    edges.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0.0);
  EXPECT_LT((cone_spread(edges) - Vec3(0, 0, 1)).cwiseAbs().maxCoeff(), 1e-5);
  // Edges spanning all of space: only u = 0.
  edges.emplace_back(0, 0, 1);
  edges.emplace_back(0, 0, -1);
  EXPECT_LT(cone_spread(edges).maxCoeff(), 1e-5);
}

} // namespace
} // namespace fsi::geometry
