// The feedback law of Huang, Shin & Sung: a free sheet released at rest in a uniform flow
// follows the exact discrete solution of FeedbackCouplingLaw.hpp,
// I^{n+1} = (2 - A - B) I^n - (1 - B) I^{n-1}, I^{-1} = 0, I^0 = U dt, V^n = U - (I^n - I^{n-1}) / dt
// (checked with the real membrane solver of Eq. 4); alpha = 0 is the penalty law's drag with
// beta = K dt; the stability limit A + 2B < 4 is where the map turns.

#include "coupler/FeedbackCouplingLaw.hpp"
#include "coupler/FeedbackLawConfig.hpp"
#include "coupler/PenaltyCouplingLaw.hpp"
#include "LawHarness.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::coupler {
namespace {

TEST(FeedbackCouplingLaw, AFreeSheetFollowsTheExactDiscreteSolution) {
  // Delta s / Delta t = 100, the paper's rule: at 25 (dt = 2e-4 s) the explicit drag B = 0.2
  // destabilised the sheet's own fastest mode (roots of (2 - A - A_mode - B) need
  // A + A_mode + 2B < 4, a margin the law's damping takes from the membrane).
  const double rho = 0.03, alpha = 3e5, beta = 30.0, dt = 5e-5, flow = 0.4;
  const double A = alpha * dt * dt / rho, B = beta * dt / rho;
  const auto made = testing::flat_sheet(9, 0.04, rho, 10.0, 1e-8, dt);
  structure::LagrangianSheet &sheet = *made;
  FeedbackCouplingLaw law(alpha, beta);
  law.start(sheet.positions_m());
  PointArray x_prev = sheet.positions_m() - dt * sheet.velocities_m_per_s();
  const PointArray u = PointArray::Zero(sheet.n_points(), 3).rowwise() + Eigen::RowVector3d(flow, 0.0, 0.0);
  double i_prev = 0.0, i_now = flow * dt; // I^{-1}, I^0
  double worst = 0.0, worst_integral = 0.0;
  const int n_steps = 1000;
  for (int n = 0; n < n_steps; ++n) {
    const PointArray x_now = sheet.positions_m();
    const CouplingInputs in{&x_now, &x_prev, &u, dt};
    const CouplingOutputs out = law.compute(in);
    law.accept(out);
    worst_integral = std::max(worst_integral, std::abs(law.integral_m()(0, 0) - i_now));
    x_prev = x_now;
    sheet.advance(-out.force_density_n_per_measure);
    const double i_next = (2.0 - A - B) * i_now - (1.0 - B) * i_prev;
    // V^{n+1} = U - W^{n+1} = U - (I^{n+1} - I^n) / dt
    const double v_expected = flow - (i_next - i_now) / dt;
    worst = std::max(worst, (sheet.velocities_m_per_s().col(0).array() - v_expected).abs().maxCoeff());
    i_prev = i_now;
    i_now = i_next;
  }
  std::printf("feedback: A = %.3f, B = %.3f, V at the end %.6f m/s (U = %.3f), worst deviation %.3g m/s\n", A, B,
              sheet.velocities_m_per_s().col(0).mean(), flow, worst);
  EXPECT_LT(worst, 1e-11);
  EXPECT_LT(worst_integral, 1e-13); // I ~ U dt = 2e-5 m: 5e-9 relative, round-off of X / dt over 1000 steps
  EXPECT_NEAR(sheet.velocities_m_per_s().col(0).mean(), flow, 1e-6 * flow);
}

TEST(FeedbackCouplingLaw, WithoutTheIntegralItIsThePenaltyDrag) {
  const double k = 2.5e5, dt = 4e-5;
  FeedbackCouplingLaw feedback(0.0, k * dt);
  PenaltyCouplingLaw penalty(k);
  PointArray x(3, 3), x_prev(3, 3), u(3, 3);
  x.setRandom();
  x_prev = x + 1e-4 * PointArray::Random(3, 3);
  u.setRandom();
  feedback.start(x);
  const CouplingInputs in{&x, &x_prev, &u, dt};
  const PointArray difference =
      feedback.compute(in).force_density_n_per_measure - penalty.compute(in).force_density_n_per_measure;
  EXPECT_LT(difference.cwiseAbs().maxCoeff(), 1e-9);
}

// |U - V| after `steps` of one free point under the law alone.
double slip_after(double dt, double rho, double alpha, double beta, int steps) {
  FeedbackCouplingLaw law(alpha, beta);
  return testing::free_point_after(law, dt, rho, steps).slip(dt);
}

TEST(FeedbackLawConfig, StabilityLimitIsWhereAPlusTwoBReachesFour) {
  const double rho = 0.03;
  for (const auto &[alpha, beta] : {std::pair{1e5, 50.0}, std::pair{0.0, 50.0}, std::pair{1e5, 0.5}}) {
    FeedbackLawConfig config;
    config.alpha_n_per_m_per_measure = alpha;
    config.beta_n_s_per_m_per_measure = beta;
    const double limit = config.stable_time_step_s(rho);
    EXPECT_NEAR(alpha * limit * limit / rho + 2.0 * beta * limit / rho, 4.0, 1e-9) << alpha << " " << beta;
    EXPECT_LT(slip_after(0.99 * limit, rho, alpha, beta, 20000), 1.0) << alpha << " " << beta;
    EXPECT_FALSE(slip_after(1.01 * limit, rho, alpha, beta, 20000) < 1e3) << alpha << " " << beta; // or NaN
  }
}

TEST(FeedbackCouplingLaw, GainsMustBeNonNegativeAndNotBothZero) {
  EXPECT_THROW(FeedbackCouplingLaw(-1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(FeedbackCouplingLaw(0.0, 0.0), std::invalid_argument);
}

} // namespace
} // namespace fsi::coupler
