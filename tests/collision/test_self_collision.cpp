// Self-collision: the spatial hash finds exactly the pairs an O(N^2) loop finds; two facing
// patches of one folded sheet end d_t apart with each pair's centroid unchanged; material
// neighbours of a flat sheet are never moved.

#include "TestGeometry.hpp"

#include "structure_solver/collision/SelfCollision.hpp"
#include "geometry/SpatialHashGrid.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fsi::structure::collision {
namespace {

using namespace fsi::geometry;

/// n x n points spaced spacing_m in the plane z = height_m, starting at x = x0_m.
PointArray square_patch(int n, double spacing_m, double x0_m, double height_m) {
  PointArray patch(n * n, 3);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      patch.row(i * n + j) << x0_m + i * spacing_m, j * spacing_m, height_m;
  }
  return patch;
}

PointArray stack(const PointArray &a, const PointArray &b) {
  PointArray both(a.rows() + b.rows(), 3);
  both << a, b;
  return both;
}

TEST(SpatialHashGrid, FindsTheSamePairsAsAllPairsLoop) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
  PointArray points(2000, 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    points.row(i) << coordinate(rng), coordinate(rng), coordinate(rng);
  const double radius_m = 0.012;
  std::vector<SpatialHashGrid::IndexPair> expected;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    for (Eigen::Index j = i + 1; j < points.rows(); ++j) {
      if ((points.row(i) - points.row(j)).norm() < radius_m)
        expected.emplace_back(i, j);
    }
  }
  EXPECT_EQ(SpatialHashGrid(points, radius_m).pairs_within(radius_m), expected);
  EXPECT_FALSE(expected.empty());
}

TEST(SelfCollision, FacingPatchesEndAtTargetDistanceWithPairCentroidsFixed) {
  const int n = 5;
  const double spacing_m = 0.01, threshold_m = 0.006, target_m = 0.008, gap_m = 0.004;
  // Rest: two patches side by side in one flat sheet. Now: the second folded over the first.
  const PointArray rest =
      stack(square_patch(n, spacing_m, 0.0, 0.0), square_patch(n, spacing_m, 0.2, 0.0));
  PointArray now =
      stack(square_patch(n, spacing_m, 0.0, 0.0), square_patch(n, spacing_m, 0.0, gap_m));
  const PointArray before = now;
  const SelfCollision self(rest, threshold_m, target_m);
  EXPECT_EQ(self.correct(now), static_cast<std::size_t>(n * n));
  for (Eigen::Index i = 0; i < n * n; ++i) {
    const Eigen::Index partner = i + n * n;
    EXPECT_NEAR((now.row(partner) - now.row(i)).norm(), target_m, 1e-12);
    const Eigen::RowVector3d centroid_before = 0.5 * (before.row(i) + before.row(partner));
    const Eigen::RowVector3d centroid_after = 0.5 * (now.row(i) + now.row(partner));
    EXPECT_LT((centroid_after - centroid_before).norm(), 1e-12);
  }
}

TEST(SelfCollision, NeighboursOfAFlatSheetAreNotMoved) {
  const PointArray sheet = square_patch(20, 0.004, 0.0, 0.0); // spacing below d_c
  PointArray now = sheet;
  const SelfCollision self(sheet, 0.006, 0.008);
  EXPECT_GT(self.n_excluded_pairs(), 0u);
  EXPECT_EQ(self.correct(now), 0u);
  EXPECT_EQ(now, sheet);
}

TEST(SelfCollision, CrumpledSheetKeepsItsCentroid) {
  const PointArray rest = square_patch(30, 0.004, 0.0, 0.0);
  PointArray now = rest;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> fold_m(-0.01, 0.01);
  for (Eigen::Index i = 0; i < now.rows(); ++i)
    now.row(i) = 0.25 * now.row(i) + Eigen::RowVector3d(fold_m(rng), fold_m(rng), fold_m(rng));
  const Eigen::RowVector3d centroid_before = now.colwise().mean();
  const SelfCollision self(rest, 0.006, 0.008);
  EXPECT_GT(self.correct(now), 0u);
  EXPECT_LT((now.colwise().mean() - centroid_before).norm(), 1e-15);
}

TEST(SelfCollision, CoincidentPointsSeparateAlongTheirRestDirection) {
  PointArray rest(2, 3);
  rest << 0, 0, 0, 0, 1, 0;
  PointArray now(2, 3);
  now << 0.5, 0.5, 0.5, 0.5, 0.5, 0.5;
  const SelfCollision self(rest, 0.01, 0.02);
  EXPECT_EQ(self.correct(now), 1u);
  EXPECT_NEAR(now(0, 1), 0.49, 1e-15);
  EXPECT_NEAR(now(1, 1), 0.51, 1e-15);
}

TEST(SelfCollision, RejectsWrongPointCountAndBadParameters) {
  const PointArray rest = square_patch(3, 0.01, 0.0, 0.0);
  const SelfCollision self(rest, 0.006, 0.008);
  PointArray wrong(2, 3);
  wrong.setZero();
  EXPECT_THROW(self.correct(wrong), std::invalid_argument);
  EXPECT_THROW(SelfCollision(rest, 0.01, 0.005), std::invalid_argument);
}

} // namespace
} // namespace fsi::structure::collision
