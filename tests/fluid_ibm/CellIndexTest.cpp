// CellIndex against a brute-force oracle on an irregular cloud of cell centres, and its
// locality: the cells a query visits do not grow with the size of the mesh.

#include "TestMeshes.hpp"
#include "fluid_adapter/ibm/CellIndex.hpp"
#include "fluid_adapter/ibm/KernelStencil.hpp"
#include "fluid_adapter/ibm/NearestCells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace fsi::fluid::ibm {
namespace {

/// A stretched grid whose centres are jittered by up to 30 % of the cell size.
EulerianCells perturbed_grid(int n) {
  const EulerianCells grid = testing::stretched_grid(n, 1.0, 0.4);
  const PointArray jitter = testing::random_points(grid.n_cells(), -0.3, 0.3, 7);
  PointArray centres_m = grid.centres_m() + (jitter.array().colwise() * grid.sizes_m().array()).matrix();
  return EulerianCells(centres_m, grid.volumes_m3());
}

std::vector<CellId> brute_force_box(const EulerianCells &cells, const Vec3 &point_m, double half_width_m) {
  std::vector<CellId> found;
  for (CellId c = 0; c < cells.n_cells(); ++c)
    if ((cells.centre_m(c) - point_m).cwiseAbs().maxCoeff() < half_width_m)
      found.push_back(c);
  return found;
}

TEST(CellIndex, BoxQueriesMatchABruteForceSearch) {
  const EulerianCells cells = perturbed_grid(14);
  const CellIndex index(cells);
  const PointArray points_m = testing::random_points(200, -0.1, 1.1, 3);
  std::vector<CellId> found;
  for (Eigen::Index k = 0; k < points_m.rows(); ++k) {
    const Vec3 point_m = points_m.row(k).transpose();
    const double half_width_m = 0.02 + 0.15 * (k % 7) / 6.0;
    index.cells_in_box(point_m, half_width_m, found);
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, brute_force_box(cells, point_m, half_width_m)) << "point " << k;
  }
}

TEST(CellIndex, NearestCellMatchesABruteForceSearch) {
  const EulerianCells cells = perturbed_grid(14);
  const CellIndex index(cells);
  const PointArray points_m = testing::random_points(300, -0.2, 1.2, 4);
  for (Eigen::Index k = 0; k < points_m.rows(); ++k) {
    const Vec3 point_m = points_m.row(k).transpose();
    double best_m = std::numeric_limits<double>::infinity();
    for (CellId c = 0; c < cells.n_cells(); ++c)
      best_m = std::min(best_m, (cells.centre_m(c) - point_m).norm());
    const CellIndex::Nearest nearest = index.nearest(point_m);
    ASSERT_NEAR(nearest.distance_m, best_m, 1e-15);
    ASSERT_NEAR((cells.centre_m(nearest.cell) - point_m).norm(), best_m, 1e-15);
  }
}

TEST(CellIndex, RankWithoutCellsFindsNothing) {
  const EulerianCells cells(PointArray(0, 3), Eigen::VectorXd(0));
  const CellIndex index(cells);
  std::vector<CellId> found{1, 2};
  index.cells_in_box(Vec3(0.5, 0.5, 0.5), 1.0, found);
  EXPECT_TRUE(found.empty());
  EXPECT_EQ(index.nearest(Vec3::Zero()).cell, -1);
  const NearestCells nearest(index, testing::random_points(3, 0, 1, 1));
  EXPECT_FALSE(nearest.owns(0));
}

TEST(CellIndex, StencilSizeDependsOnTheKernelNotOnTheMeshSize) {
  // 4^3 = 64 cells per point on a uniform mesh, whatever the number of cells.
  for (int n : {16, 48}) {
    const EulerianCells cells = testing::uniform_grid(n, 1.0);
    const CellIndex index(cells);
    const PointArray points_m = testing::random_points(100, 0.3, 0.7, 5);
    const NearestCells nearest(index, points_m);
    const KernelStencil stencil(index, points_m, nearest.kernel_width_m());
    EXPECT_EQ(stencil.n_pairs(), 64u * 100u) << n << "^3 cells";
  }
}

TEST(EulerianCells, RejectsInconsistentInput) {
  EXPECT_THROW(EulerianCells(PointArray::Zero(3, 3), Eigen::VectorXd::Ones(2)), std::invalid_argument);
  EXPECT_THROW(EulerianCells(PointArray::Zero(2, 3), Eigen::VectorXd::Zero(2)), std::invalid_argument);
  const EulerianCells cells(PointArray::Zero(1, 3), Eigen::VectorXd::Constant(1, 8e-9));
  EXPECT_NEAR(cells.size_m(0), 2e-3, 1e-18);
}

} // namespace
} // namespace fsi::fluid::ibm
