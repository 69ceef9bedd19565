// The paper's two-point-set law of Eq. (5): the IB points advected by the fluid, the structure
// held to them. A free sheet released at rest in a uniform flow U follows the exact discrete
// solution of TwoPointSetsCouplingLaw.hpp, e^{n+1} = (1 - a)(2 e^n - e^{n-1}) for the gap
// e = X - X_ib, e^0 = 0, e^1 = -(1 - a) U dt (checked with the real membrane solver of Eq. 4),
// the stability limit a < 4/3 is where the map turns, and the law's state changes only when a
// step is accepted (what implicit coupling and restart rely on).

#include "coupler/TwoPointSetsCouplingLaw.hpp"
#include "coupler/TwoPointSetsLawConfig.hpp"
#include "LawHarness.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::coupler {
namespace {

TEST(TwoPointSetsCouplingLaw, AFreeSheetFollowsTheExactDiscreteSpringAboutItsAdvectedPoints) {
  const double rho = 0.03, k = 1e5, dt = 2e-4, flow = 0.4;
  const double a = k * dt * dt / rho; // 0.133: oscillating, damped by sqrt(1 - a) per step
  const auto made = testing::flat_sheet(9, 0.04, rho, 10.0, 1e-8, dt);
  structure::LagrangianSheet &sheet = *made;
  TwoPointSetsCouplingLaw law(k);
  law.start(sheet.positions_m());
  PointArray x_prev = sheet.positions_m() - dt * sheet.velocities_m_per_s();
  const PointArray u = PointArray::Zero(sheet.n_points(), 3).rowwise() + Eigen::RowVector3d(0.0, 0.0, flow);
  double e_prev = flow * dt, e = 0.0; // e^{-1} = X^{-1} - (X_ib^0 - U dt) = U dt, e^0 = 0 (z components)
  double worst = 0.0;
  const int n_steps = 300;
  for (int n = 0; n < n_steps; ++n) {
    const PointArray x_now = sheet.positions_m();
    const CouplingInputs in{&x_now, &x_prev, &u, dt};
    const CouplingOutputs out = law.compute(in);
    law.accept(out);
    x_prev = x_now;
    sheet.advance(-out.force_density_n_per_measure);
    const double e_next = (1.0 - a) * (2.0 * e - e_prev);
    e_prev = e;
    e = e_next;
    const PointArray gap = sheet.positions_m() - law.ib_points_m();
    worst = std::max(worst, (gap.col(2).array() - e).abs().maxCoeff());
    worst = std::max(worst, gap.leftCols(2).cwiseAbs().maxCoeff());
  }
  // The IB points went with the flow exactly; the gap is the recurrence's, to round-off.
  EXPECT_NEAR(law.ib_points_m().col(2).mean(), flow * dt * n_steps, 1e-12);
  std::printf("two point sets: a = %.3f, |e| at the end %.3g m (start %.3g m), worst deviation %.3g m\n", a,
              std::abs(e), (1 - a) * flow * dt, worst);
  EXPECT_LT(worst, 1e-14);
  EXPECT_LT(std::abs(e), 1e-6 * flow * dt); // damped by (1 - a)^{n/2}
}

// |X - X_ib| after `steps` of one free point under the law alone, from rest in a flow of 1 m/s.
double gap_after(double dt, double rho, double k, int steps) {
  TwoPointSetsCouplingLaw law(k);
  return (testing::free_point_after(law, dt, rho, steps).x - law.ib_points_m()).norm() / dt;
}

TEST(TwoPointSetsLawConfig, StabilityLimitIsFourThirdsOfRhoOverKDtSquared) {
  TwoPointSetsLawConfig config;
  config.stiffness_n_per_m_per_measure = 1.0e5;
  const double rho = 0.03, limit = config.stable_time_step_s(rho);
  EXPECT_NEAR(limit * limit * 1.0e5 / rho, 4.0 / 3.0, 1e-12);
  EXPECT_LT(gap_after(0.99 * limit, rho, 1.0e5, 2000), 1e-6);
  EXPECT_GT(gap_after(1.01 * limit, rho, 1.0e5, 2000), 1e6);
}

TEST(TwoPointSetsCouplingLaw, StateMovesOnlyWhenAStepIsAcceptedAndSurvivesACheckpoint) {
  TwoPointSetsCouplingLaw law(1e5);
  PointArray x = PointArray::Zero(2, 3), u = PointArray::Ones(2, 3);
  law.start(x);
  const CouplingInputs in{&x, &x, &u, 1e-3};
  const CouplingOutputs first = law.compute(in), again = law.compute(in);
  EXPECT_TRUE((first.force_density_n_per_measure.array() == again.force_density_n_per_measure.array()).all());
  EXPECT_EQ(&law.interpolation_points(x), &law.ib_points_m());
  law.accept(first);
  EXPECT_DOUBLE_EQ(law.ib_points_m()(1, 2), 1e-3);
  checkpoint::StateArchive archive;
  law.save_state(archive);
  TwoPointSetsCouplingLaw resumed(1e5);
  resumed.start(x);
  resumed.load_state(archive, 2);
  EXPECT_TRUE((resumed.ib_points_m().array() == law.ib_points_m().array()).all());
  EXPECT_FALSE(law.allows_implicit());
}

} // namespace
} // namespace fsi::coupler
