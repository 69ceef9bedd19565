// The penalty law of Eq. (5): values and signs, and the relaxation of a free sheet to a uniform
// flow when the immersed-boundary points are the structure points: V^{n+1} = V^n +
// a (U - V^n), a = K dt^2 / rho_1, i.e. the time constant tau = rho_1 / (K dt) (derivation in
// PenaltyCouplingLaw.hpp), checked with the real membrane solver of Eq. (4).

#include "coupler/PenaltyCouplingLaw.hpp"
#include "LawHarness.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::coupler {
namespace {

TEST(PenaltyCouplingLaw, MatchesEquationFiveAndPullsTheStructureTowardTheFluid) {
  PenaltyCouplingLaw law(2e5);
  PointArray x_now(1, 3), x_prev(1, 3), u(1, 3);
  x_now << 1.0, 2.0, 3.0;
  x_prev << 1.0, 2.0, 3.0;      // structure at rest
  u << 0.5, 0.0, -0.25;         // fluid moving
  const double dt = 1e-3;
  const CouplingOutputs out = law.compute({&x_now, &x_prev, &u, dt});
  EXPECT_DOUBLE_EQ(out.x_ib_next_m(0, 0), 1.0 + 0.5 * dt);
  // F_fsi = -K (X_ib^{n+1} - 2 X^n + X^{n-1}) = -K dt u; the structure feels -F_fsi = +K dt u.
  EXPECT_NEAR(out.force_density_n_per_measure(0, 0), -2e5 * dt * 0.5, 1e-9);
  EXPECT_NEAR(out.force_density_n_per_measure(0, 2), +2e5 * dt * 0.25, 1e-9);
  EXPECT_THROW(PenaltyCouplingLaw(0.0), std::invalid_argument);
}

TEST(PenaltyCouplingLaw, FreeSheetRelaxesToAUniformFlowWithTauRhoOverKDt) {
  const double rho = 0.08, k = 2e5, dt = 5e-5, flow = 0.3;
  const auto made = testing::flat_sheet(11, 0.04, rho, 100.0, 1e-4, dt);
  structure::LagrangianSheet &sheet = *made;
  PenaltyCouplingLaw law(k);
  PointArray x_prev = sheet.positions_m() - dt * sheet.velocities_m_per_s();
  const PointArray u = PointArray::Zero(sheet.n_points(), 3).rowwise() + Eigen::RowVector3d(flow, 0.0, 0.0);
  const double a = k * dt * dt / rho, tau = rho / (k * dt);
  const int n_steps = 200; // 2.5 tau
  for (int n = 0; n < n_steps; ++n) {
    const PointArray x_now = sheet.positions_m();
    const CouplingOutputs out = law.compute({&x_now, &x_prev, &u, dt});
    x_prev = x_now;
    sheet.advance(-out.force_density_n_per_measure); // Eq. (3): the structure feels -F_fsi
  }
  const double v = sheet.velocities_m_per_s().col(0).mean();
  const double discrete = flow * (1.0 - std::pow(1.0 - a, n_steps));
  const double continuous = flow * (1.0 - std::exp(-n_steps * dt / tau));
  std::printf("relaxation: v = %.6f m/s, discrete law %.6f, exp(-t/tau) %.6f (tau = %.4g s)\n", v, discrete,
              continuous, tau);
  EXPECT_NEAR(v, discrete, 1e-9 * flow);        // exact for a rigidly translating sheet
  EXPECT_NEAR(v, continuous, 0.01 * flow);      // O(dt / tau) = 1.25 % per step away from the ODE
  EXPECT_LT(sheet.velocities_m_per_s().col(0).maxCoeff() - sheet.velocities_m_per_s().col(0).minCoeff(), 1e-9);
}

} // namespace
} // namespace fsi::coupler
