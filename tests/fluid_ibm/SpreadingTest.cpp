// Spreading (Eq. 8) on a uniform mesh, away from the boundary, conserves the total force and
// the torque about any point to round-off; spreading and kernel interpolation are adjoint.
// Near a boundary force is lost unless the weights are normalised.

#include "TestMeshes.hpp"
#include "fluid_adapter/ibm/KernelStencil.hpp"
#include "fluid_adapter/ibm/NearestCells.hpp"
#include "fluid_adapter/ibm/PeskinKernel.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace fsi::fluid::ibm {
namespace {

constexpr double round_off = 1e-13; // relative to the magnitudes summed

struct Coupling {
  EulerianCells cells;
  CellIndex index;
  PointArray points_m;
  NearestCells nearest;
  KernelStencil stencil;
  Coupling(EulerianCells mesh, PointArray points)
      : cells(std::move(mesh)), index(cells), points_m(std::move(points)), nearest(index, points_m),
        stencil(index, points_m, nearest.kernel_width_m()) {}
};

Vec3 total_cell_force_n(const EulerianCells &cells, const PointArray &force_density_n_per_m3) {
  return (force_density_n_per_m3.array().colwise() * cells.volumes_m3().array()).colwise().sum().transpose();
}

Vec3 total_cell_torque_nm(const EulerianCells &cells, const PointArray &force_density_n_per_m3, const Vec3 &about_m) {
  Vec3 torque = Vec3::Zero();
  for (CellId c = 0; c < cells.n_cells(); ++c)
    torque += (cells.centre_m(c) - about_m).cross(force_density_n_per_m3.row(c).transpose() * cells.volume_m3(c));
  return torque;
}

TEST(KernelStencilWeights, AreDeltaTimesVolumeBitForBitOnUniformAndStretchedMeshes) {
  // The stencil evaluates phi once per distinct centre coordinate of a support (hexahedral
  // meshes repeat them); every weight must still be delta_h(x_c - X) V_c exactly.
  for (const EulerianCells &mesh : {testing::uniform_grid(20, 1.0), testing::stretched_grid(20, 1.0, 0.5)}) {
    const CellIndex index(mesh);
    const PointArray points = testing::random_points(200, 0.05, 0.95, 7);
    const NearestCells nearest(index, points);
    const KernelStencil stencil(index, points, nearest.kernel_width_m());
    ASSERT_GT(stencil.n_pairs(), 200u * 27u);
    for (Eigen::Index k = 0; k < points.rows(); ++k) {
      const Vec3 x = points.row(k).transpose();
      const double h = nearest.kernel_width_m()[k];
      for (std::size_t p = stencil.offsets()[static_cast<std::size_t>(k)];
           p < stencil.offsets()[static_cast<std::size_t>(k) + 1]; ++p) {
        const CellId c = stencil.cells()[p];
        ASSERT_EQ(stencil.weights()[p], PeskinKernel::delta_per_m3(mesh.centre_m(c) - x, h) * mesh.volume_m3(c))
            << "point " << k << ", cell " << c;
      }
    }
  }
}

TEST(KernelStencilWeights, ARebuiltStencilEqualsANewOne) {
  // The fluid rebuilds one stencil every step, keeping its arrays: the next step's points (more
  // of them, then fewer) must give exactly the stencil built from scratch.
  const EulerianCells mesh = testing::stretched_grid(16, 1.0, 0.5);
  const CellIndex index(mesh);
  const PointArray first = testing::random_points(300, 0.05, 0.95, 3);
  KernelStencil stencil(index, first, NearestCells(index, first).kernel_width_m());
  for (const int n : {500, 40}) {
    const PointArray next = testing::random_points(n, 0.0, 1.0, static_cast<unsigned>(n));
    const Eigen::VectorXd widths = NearestCells(index, next).kernel_width_m();
    stencil.rebuild(index, next, widths);
    const KernelStencil fresh(index, next, widths);
    EXPECT_EQ(stencil.n_points(), n);
    EXPECT_EQ(stencil.offsets(), fresh.offsets());
    EXPECT_EQ(stencil.cells(), fresh.cells());
    EXPECT_EQ(stencil.weights(), fresh.weights());
  }
  const EulerianCells other = testing::uniform_grid(4, 1.0);
  const CellIndex other_index(other);
  EXPECT_THROW(stencil.rebuild(other_index, first, Eigen::VectorXd::Constant(300, 0.1)), std::invalid_argument);
}

TEST(KernelStencilWeights, SkippedPointsHaveNoPairsAndTheOthersTheirOwn) {
  // A feed's rags out of the scene are skipped: no pairs (so U_ib = 0 and nothing is spread,
  // at no cost), whatever their width (zero here), and every other point keeps exactly the
  // pairs it has without them.
  const EulerianCells mesh = testing::uniform_grid(16, 1.0);
  const CellIndex index(mesh);
  const PointArray points = testing::random_points(200, 0.1, 0.9, 5);
  Eigen::VectorXd widths = NearestCells(index, points).kernel_width_m();
  std::vector<bool> skip(200, false);
  for (int k = 50; k < 120; ++k) {
    skip[static_cast<std::size_t>(k)] = true;
    widths[k] = 0.0;
  }
  KernelStencil stencil(index, PointArray(0, 3), Eigen::VectorXd(0));
  stencil.rebuild(index, points, widths, skip);
  const KernelStencil all(index, points, NearestCells(index, points).kernel_width_m());
  ASSERT_EQ(stencil.n_points(), 200);
  std::size_t pairs_kept = 0;
  for (std::size_t k = 0; k < 200; ++k) {
    const auto n = stencil.offsets()[k + 1] - stencil.offsets()[k];
    if (skip[k]) {
      EXPECT_EQ(n, 0u) << k;
      continue;
    }
    ASSERT_EQ(n, all.offsets()[k + 1] - all.offsets()[k]) << k;
    for (std::size_t j = 0; j < n; ++j) {
      EXPECT_EQ(stencil.cells()[stencil.offsets()[k] + j], all.cells()[all.offsets()[k] + j]);
      EXPECT_EQ(stencil.weights()[stencil.offsets()[k] + j], all.weights()[all.offsets()[k] + j]);
    }
    pairs_kept += n;
  }
  EXPECT_EQ(stencil.n_pairs(), pairs_kept);
  const PointArray u = stencil.interpolate(PointArray::Ones(mesh.n_cells(), 3));
  EXPECT_EQ(u.middleRows(50, 70).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NEAR(u.row(10).norm(), std::sqrt(3.0), 1e-12); // a kept point far from walls: sum w = 1
  EXPECT_THROW(stencil.rebuild(index, points, widths, std::vector<bool>(3, true)), std::invalid_argument);
}

TEST(Spreading, ConservesForceAndTorqueOnAUniformMesh) {
  // A sheet-like load: densities in N/m^2 times point areas in m^2.
  const Coupling s(testing::uniform_grid(20, 1.0), testing::random_points(150, 0.25, 0.75, 11));
  const PointArray density_n_per_m2 = testing::random_points(150, -50.0, 50.0, 12);
  const Eigen::VectorXd area_m2 = (testing::random_points(150, 1e-4, 4e-4, 13).col(0));
  const PointArray spread_n_per_m3 = s.stencil.spread(density_n_per_m2, area_m2);

  const PointArray point_forces_n = density_n_per_m2.array().colwise() * area_m2.array();
  const Vec3 force_n = point_forces_n.colwise().sum().transpose();
  const double scale_n = point_forces_n.cwiseAbs().sum();
  EXPECT_LT((total_cell_force_n(s.cells, spread_n_per_m3) - force_n).norm(), round_off * scale_n);

  for (const Vec3 &about_m : {Vec3(0.0, 0.0, 0.0), Vec3(0.4, 1.3, -0.7)}) {
    Vec3 torque_nm = Vec3::Zero();
    for (Eigen::Index k = 0; k < 150; ++k)
      torque_nm += (s.points_m.row(k).transpose() - about_m).cross(point_forces_n.row(k).transpose());
    const double error = (total_cell_torque_nm(s.cells, spread_n_per_m3, about_m) - torque_nm).norm();
    std::printf("force error %.2e N, torque error %.2e N m (scale %.2e N)\n",
                (total_cell_force_n(s.cells, spread_n_per_m3) - force_n).norm(), error, scale_n);
    EXPECT_LT(error, round_off * scale_n * 2.0);
  }
}

TEST(Spreading, IsTheAdjointOfKernelInterpolation) {
  // sum_c f_c . u_c V_c = sum_k F_k dA_k . U(X_k), on a stretched mesh too.
  for (double stretching : {0.0, 0.5}) {
    const Coupling s(testing::stretched_grid(18, 1.0, stretching), testing::random_points(120, 0.1, 0.9, 21));
    const PointArray point_forces_n = testing::random_points(120, -1.0, 1.0, 22);
    const PointArray cell_velocity_m_per_s = testing::random_points(s.cells.n_cells(), -2.0, 2.0, 23);
    const PointArray f_n_per_m3 = s.stencil.spread_point_forces(point_forces_n);
    const PointArray u_points = s.stencil.interpolate(cell_velocity_m_per_s);
    const double eulerian_power = ((f_n_per_m3.array() * cell_velocity_m_per_s.array()).rowwise().sum() *
                                   s.cells.volumes_m3().array()).sum();
    const double lagrangian_power = (point_forces_n.array() * u_points.array()).sum();
    std::printf("stretching %.1f: power %.15e vs %.15e\n", stretching, eulerian_power, lagrangian_power);
    EXPECT_NEAR(eulerian_power, lagrangian_power, round_off * point_forces_n.cwiseAbs().sum() * 2.0);
  }
}

TEST(Spreading, LosesForceNearAWallUnlessTheWeightsAreNormalised) {
  // A point 0.5 h from the wall x = 0: its support reaches 1.5 h beyond it, where there are no cells.
  const double h = 1.0 / 20;
  PointArray points_m(1, 3);
  points_m << 0.5 * h + 1e-3 * h, 0.5, 0.5;
  Coupling s(testing::uniform_grid(20, 1.0), points_m);
  const PointArray force_n = PointArray::Constant(1, 3, 1.0);
  const double kept = total_cell_force_n(s.cells, s.stencil.spread_point_forces(force_n)).x();
  // Along x the cells at r = (x_c - X)/h = -0.001, 0.999, 1.999 exist; the one at r = -1.001
  // would lie beyond the wall, so its share phi(1.001) (about a quarter) is lost.
  std::printf("force kept near the wall: %.6f of 1\n", kept);
  EXPECT_NEAR(kept, 1.0 - PeskinKernel::phi(1.001), 1e-12);
  s.stencil.normalise_weights(s.stencil.weight_sums());
  EXPECT_NEAR(total_cell_force_n(s.cells, s.stencil.spread_point_forces(force_n)).x(), 1.0, 1e-14);
}

} // namespace
} // namespace fsi::fluid::ibm
