// Spalding's law of the wall solved for the wall shear (fluid_adapter/rigid/SpaldingLaw):
// its two limits and the law itself at the solution.

#include "fluid_adapter/rigid/SpaldingLaw.hpp"

#include <gtest/gtest.h>

#include <cmath>

using fsi::fluid::rigid::SpaldingLaw;

// The viscous sublayer: at y+ << 1 the law is u+ = y+, so tau_w / rho = nu U / y (to the
// law's next term, (kappa u+)^4 / (24 E), 4e-9 of u+ at u+ = 0.03).
TEST(SpaldingLaw, ViscousSublayerIsLinear) {
  const SpaldingLaw law;
  const double nu = 1e-6, y = 1e-6, u = 1e-3; // Re_y = 1e-3: y+ = 0.03
  EXPECT_NEAR(law.wall_shear_per_density(u, y, nu) / (nu * u / y), 1.0, 1e-8);
  // The laminar rotating-disc case: nu = 2.5e-5, h/2 = 0.25 mm, U = 0.05 m/s: Re_y = 0.5.
  EXPECT_NEAR(law.wall_shear_per_density(0.05, 2.5e-4, 2.5e-5) / (2.5e-5 * 0.05 / 2.5e-4), 1.0, 1e-4);
}

// The log layer: at y+ = 1000 the law is within 0.3 % of u+ = ln(E y+) / kappa.
TEST(SpaldingLaw, LogLayer) {
  const SpaldingLaw law;
  const double nu = 1e-6, u_tau = 0.5, y_plus = 1000.0;
  const double y = y_plus * nu / u_tau;
  const double u = u_tau * std::log(law.e * y_plus) / law.kappa;
  EXPECT_NEAR(std::sqrt(law.wall_shear_per_density(u, y, nu)) / u_tau, 1.0, 3e-3);
}

// The solution satisfies the law to round-off over twelve decades of Re_y, and tau_w grows
// with U.
TEST(SpaldingLaw, SolvesTheLaw) {
  const SpaldingLaw law;
  const double nu = 1e-6, y = 1e-3;
  double last = 0.0;
  for (double u = 1e-9; u < 1e4; u *= 3.7) {
    const double tau = law.wall_shear_per_density(u, y, nu);
    const double u_tau = std::sqrt(tau);
    EXPECT_NEAR(law.y_plus(u / u_tau) / (y * u_tau / nu), 1.0, 1e-9) << "U = " << u;
    EXPECT_GT(tau, last);
    last = tau;
  }
  EXPECT_EQ(law.wall_shear_per_density(0.0, y, nu), 0.0);
  EXPECT_THROW(law.wall_shear_per_density(1.0, 0.0, nu), std::invalid_argument);
}
