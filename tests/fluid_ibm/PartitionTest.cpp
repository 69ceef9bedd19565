// A decomposed mesh: each rank holds only its cells. The kernel widths merged over ranks
// equal the undecomposed ones, and the partial sums of the ranks (interpolation, weight sums,
// closest-cell interpolation) add up to the undecomposed result; each rank's spread equals
// the undecomposed spread on its cells. Checked by splitting a stretched mesh in two.

#include "TestMeshes.hpp"
#include "fluid_adapter/ibm/InterpolationScheme.hpp"
#include "fluid_adapter/ibm/PeskinKernel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace fsi::fluid::ibm {
namespace {

constexpr double round_off = 1e-13;

/// What one rank (or the whole mesh) builds each step.
struct Rank {
  EulerianCells cells;
  std::vector<CellId> global_cell; ///< global index of each local cell
  CellIndex index;
  NearestCells nearest;
  std::unique_ptr<KernelStencil> stencil; ///< built once the widths are merged
  Rank(EulerianCells mesh, std::vector<CellId> global, const PointArray &points_m, int rank)
      : cells(std::move(mesh)), global_cell(std::move(global)), index(cells), nearest(index, points_m, rank) {}
};

PointArray rows_of(const PointArray &values, const std::vector<CellId> &rows) {
  PointArray picked(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t i = 0; i < rows.size(); ++i)
    picked.row(static_cast<Eigen::Index>(i)) = values.row(rows[i]);
  return picked;
}

struct Split {
  PointArray points_m = testing::random_points(400, 0.05, 0.95, 41);
  EulerianCells mesh = testing::stretched_grid(20, 1.0, 0.5);
  std::unique_ptr<Rank> whole, ranks[2];

  Split() {
    std::vector<CellId> all(static_cast<std::size_t>(mesh.n_cells())), halves[2];
    for (CellId c = 0; c < mesh.n_cells(); ++c) {
      all[static_cast<std::size_t>(c)] = c;
      halves[mesh.centre_m(c).x() < 0.47 ? 0 : 1].push_back(c);
    }
    whole = std::make_unique<Rank>(mesh, all, points_m, 0);
    for (int r = 0; r < 2; ++r)
      ranks[r] = std::make_unique<Rank>(testing::subset(mesh, halves[r]), halves[r], points_m, r);
    exchange_widths();
    whole->stencil = std::make_unique<KernelStencil>(whole->index, points_m, whole->nearest.kernel_width_m());
    for (auto &rank : ranks)
      rank->stencil = std::make_unique<KernelStencil>(rank->index, points_m, rank->nearest.kernel_width_m());
  }
  /// What the MPI exchange does: each rank folds in the other's values as it found them.
  void exchange_widths() {
    const Eigen::VectorXd distance0 = ranks[0]->nearest.distance_m(), width0 = ranks[0]->nearest.kernel_width_m();
    ranks[0]->nearest.merge_other_rank(1, ranks[1]->nearest.distance_m(), ranks[1]->nearest.kernel_width_m());
    ranks[1]->nearest.merge_other_rank(0, distance0, width0);
  }
  PointArray velocity_on(const Rank &rank) const {
    PointArray u(rank.cells.n_cells(), 3);
    for (CellId c = 0; c < rank.cells.n_cells(); ++c) {
      const Vec3 x = rank.cells.centre_m(c);
      u.row(c) << std::sin(3 * x.x()) + x.y(), std::cos(2 * x.y() + x.z()), x.x() * x.z();
    }
    return u;
  }
};

TEST(Partition, MergedKernelWidthsEqualTheUndecomposedOnes) {
  const Split s;
  int n_owned[2] = {0, 0};
  for (Eigen::Index k = 0; k < s.points_m.rows(); ++k)
    for (int r = 0; r < 2; ++r) {
      ASSERT_EQ(s.ranks[r]->nearest.kernel_width_m()[k], s.whole->nearest.kernel_width_m()[k]);
      ASSERT_EQ(s.ranks[r]->nearest.distance_m()[k], s.whole->nearest.distance_m()[k]);
      if (s.ranks[r]->nearest.owns(k)) {
        ++n_owned[r];
        const CellId local = s.ranks[r]->nearest.cell()[static_cast<std::size_t>(k)];
        EXPECT_EQ(s.ranks[r]->global_cell[static_cast<std::size_t>(local)],
                  s.whole->nearest.cell()[static_cast<std::size_t>(k)]);
      }
    }
  EXPECT_EQ(n_owned[0] + n_owned[1], s.points_m.rows()); // each point has exactly one owner
  EXPECT_GT(n_owned[0], 0);
  EXPECT_GT(n_owned[1], 0);
}

TEST(Partition, PartialInterpolationsAndWeightSumsAddUp) {
  const Split s;
  const PointArray full = s.whole->stencil->interpolate(s.velocity_on(*s.whole));
  const PointArray summed = s.ranks[0]->stencil->interpolate(s.velocity_on(*s.ranks[0])) +
                            s.ranks[1]->stencil->interpolate(s.velocity_on(*s.ranks[1]));
  const Eigen::VectorXd weight_sums = s.ranks[0]->stencil->weight_sums() + s.ranks[1]->stencil->weight_sums();
  std::printf("two ranks: max |sum of partial U - U| = %.2e, max |sum of partial weight sums - sum| = %.2e\n",
              (summed - full).cwiseAbs().maxCoeff(),
              (weight_sums - s.whole->stencil->weight_sums()).cwiseAbs().maxCoeff());
  EXPECT_LT((summed - full).cwiseAbs().maxCoeff(), round_off);
  EXPECT_LT((weight_sums - s.whole->stencil->weight_sums()).cwiseAbs().maxCoeff(), round_off);
  EXPECT_EQ(s.ranks[0]->stencil->n_pairs() + s.ranks[1]->stencil->n_pairs(), s.whole->stencil->n_pairs());
}

TEST(Partition, NormalisedPartialInterpolationsAddUpWithTheGlobalWeightSums) {
  Split s;
  const Eigen::VectorXd global_sums = s.ranks[0]->stencil->weight_sums() + s.ranks[1]->stencil->weight_sums();
  s.whole->stencil->normalise_weights(s.whole->stencil->weight_sums());
  for (auto &rank : s.ranks)
    rank->stencil->normalise_weights(global_sums);
  const PointArray full = s.whole->stencil->interpolate(s.velocity_on(*s.whole));
  const PointArray summed = s.ranks[0]->stencil->interpolate(s.velocity_on(*s.ranks[0])) +
                            s.ranks[1]->stencil->interpolate(s.velocity_on(*s.ranks[1]));
  EXPECT_LT((summed - full).cwiseAbs().maxCoeff(), round_off);
}

TEST(Partition, EachRankSpreadsTheUndecomposedForceDensityOnItsCells) {
  const Split s;
  const PointArray point_forces_n = testing::random_points(400, -1.0, 1.0, 42);
  const PointArray full_n_per_m3 = s.whole->stencil->spread_point_forces(point_forces_n);
  const double scale = full_n_per_m3.cwiseAbs().maxCoeff();
  for (const auto &rank : s.ranks) {
    const PointArray mine = rank->stencil->spread_point_forces(point_forces_n);
    EXPECT_LT((mine - rows_of(full_n_per_m3, rank->global_cell)).cwiseAbs().maxCoeff(), round_off * scale);
  }
}

TEST(Partition, ClosestCellInterpolationsAddUp) {
  const Split s;
  auto interpolate = [&](const Rank &rank) {
    const ClosestCellLinear closest(rank.cells, rank.nearest);
    const CellGradientArray gradient = CellGradientArray::Constant(rank.cells.n_cells(), 9, 0.5);
    return interpolate_velocity(InterpolationScheme::closest_cell_linear, *rank.stencil, closest, s.points_m,
                                s.velocity_on(rank), gradient);
  };
  const PointArray summed = interpolate(*s.ranks[0]) + interpolate(*s.ranks[1]);
  EXPECT_LT((summed - interpolate(*s.whole)).cwiseAbs().maxCoeff(), round_off);
}

TEST(Partition, RanksFarFromAPointSkipItsSearchAndTheStencilsAreUnchanged) {
  // The rule of OpenFoamFluidModel::kernel_widths: a rank whose centres' box is farther than
  // sqrt(3) * support_radius * h_max from a point reports that box distance (cell -1) and its
  // largest cell size; the point goes to the rank of smallest distance (lowest on ties) and
  // takes its width. Points inside the mesh, near the cut and far outside it (where no
  // kernel reaches a cell at all) must give the undecomposed stencils exactly.
  Split s;
  PointArray points(s.points_m.rows() + 4, 3);
  points << s.points_m, -3.0, 0.5, 0.5, 4.0, 0.2, 0.3, 0.5, 0.5, 9.0, 0.47, 0.5, 0.5;
  const Eigen::Index n = points.rows();
  double h_max = 0.0;
  for (const auto &rank : s.ranks)
    h_max = std::max(h_max, rank->cells.sizes_m().maxCoeff());
  const double beyond_m = std::sqrt(3.0) * PeskinKernel::support_radius * h_max;
  Eigen::VectorXd distance[2], width[2];
  int n_skipped[2] = {0, 0};
  for (int r = 0; r < 2; ++r) {
    distance[r].resize(n);
    width[r].resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto nearest = s.ranks[r]->index.nearest_within(points.row(k).transpose(), beyond_m);
      distance[r][k] = nearest.distance_m;
      width[r][k] = nearest.cell >= 0 ? s.ranks[r]->cells.size_m(nearest.cell) : s.ranks[r]->cells.sizes_m().maxCoeff();
      n_skipped[r] += nearest.cell < 0;
    }
  }
  Eigen::VectorXd merged(n);
  for (Eigen::Index k = 0; k < n; ++k)
    merged[k] = distance[0][k] <= distance[1][k] ? width[0][k] : width[1][k];
  const NearestCells whole_nearest(s.whole->index, points);
  const KernelStencil whole(s.whole->index, points, whole_nearest.kernel_width_m());
  std::size_t n_pairs = 0;
  PointArray summed = PointArray::Zero(n, 3);
  for (const auto &rank : s.ranks) {
    const KernelStencil stencil(rank->index, points, merged);
    n_pairs += stencil.n_pairs();
    summed += stencil.interpolate(s.velocity_on(*rank));
  }
  EXPECT_GT(n_skipped[0], 40); // points at x > 0.47 + beyond (and the far ones)
  EXPECT_GT(n_skipped[1], 40);
  EXPECT_EQ(n_pairs, whole.n_pairs());
  EXPECT_LT((summed - whole.interpolate(s.velocity_on(*s.whole))).cwiseAbs().maxCoeff(), round_off);
  for (Eigen::Index k = s.points_m.rows(); k < n - 1; ++k) // far outside: no pairs at all
    EXPECT_EQ(whole.offsets()[static_cast<std::size_t>(k) + 1], whole.offsets()[static_cast<std::size_t>(k)]);
}

TEST(Partition, TiesGoToTheLowestRankWhateverTheMergeOrder) {
  // Three ranks at the same distance from a point, with different widths.
  const EulerianCells one_cell(PointArray::Zero(1, 3), Eigen::VectorXd::Constant(1, 1.0));
  const CellIndex index(one_cell);
  const PointArray point_m = PointArray::Constant(1, 3, 0.5);
  const Eigen::VectorXd same_distance = Eigen::VectorXd::Constant(1, std::sqrt(0.75));
  std::array<NearestCells, 3> merged{NearestCells(index, point_m, 2), NearestCells(index, point_m, 2),
                                     NearestCells(index, point_m, 2)};
  merged[0].merge_other_rank(1, same_distance, Eigen::VectorXd::Constant(1, 0.1));
  merged[0].merge_other_rank(0, same_distance, Eigen::VectorXd::Constant(1, 0.2));
  merged[1].merge_other_rank(0, same_distance, Eigen::VectorXd::Constant(1, 0.2));
  merged[1].merge_other_rank(1, same_distance, Eigen::VectorXd::Constant(1, 0.1));
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(merged[i].owner_rank()[0], 0);
    EXPECT_EQ(merged[i].kernel_width_m()[0], 0.2);
    EXPECT_FALSE(merged[i].owns(0));
  }
  EXPECT_TRUE(merged[2].owns(0)); // unmerged: still its own
}

} // namespace
} // namespace fsi::fluid::ibm
