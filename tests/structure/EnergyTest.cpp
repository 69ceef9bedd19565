// Energy behaviour of the time schemes on a large-amplitude, nonlinear motion: a sheet
// pinned along one edge, released horizontally, swinging down under gravity (no damping).
// - energy_conserving: H applied to (X^{n+1} + X^{n-1}) / 2 conserves the energy of the
//   linearised system exactly; on this nonlinear motion the total energy must stay within
//   1 % of the potential energy released.
// - paper (Eq. 4 as printed): first-order dissipative; halving dt must about halve the
//   energy lost (ratio in [1.6, 2.5]).

#include "CaseFixture.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace fsi::structure {
namespace {

struct EnergyHistory {
  double max_drift_j = 0.0;    ///< max |E(t) - E(0)|
  double released_j = 0.0;     ///< max potential energy released
  double final_drift_j = 0.0;  ///< E(end) - E(0)
};

EnergyHistory swing(const std::string &scheme, double dt, double end_time_s) {
  const std::string yaml =
      "run: {end_time_s: 1, time_step_s: " + std::to_string(dt) + ", output_interval_s: 0.01}\n"
      "gravity_m_per_s2: [0, 0, -9.81]\n"
      "structures:\n  - name: flap\n    model: membrane\n    size_m: [0.2, 0.1]\n    n_points: [21, 11]\n"
      "    material:\n      mass_per_area_kg_per_m2: 0.08\n"
      "      coefficients: {tension_coefficient_n_per_m: 100, bending_rigidity_n_m: 1.0e-4}\n"
      "    edges: {s1_min: pinned}\n    solver: {time_scheme: " + scheme + "}\n";
  Scene scene(testing::load_case(yaml));
  const auto &s = *scene.structures().front();
  const StructureEnergy e0 = s.energy();
  EnergyHistory h;
  const long steps = std::lround(end_time_s / dt);
  for (long k = 0; k < steps; ++k) {
    scene.advance();
    const StructureEnergy e = s.energy();
    h.max_drift_j = std::max(h.max_drift_j, std::abs(e.total() - e0.total()));
    h.released_j = std::max(h.released_j, e0.potential_j - e.potential_j);
    h.final_drift_j = e.total() - e0.total();
  }
  return h;
}

TEST(Energy, EnergyConservingSchemeKeepsTotalEnergyOfALargeSwing) {
  const EnergyHistory h = swing("energy_conserving", 5e-5, 0.25);
  std::printf("energy_conserving: max drift %.3e J of %.3e J released (%.3f %%)\n", h.max_drift_j, h.released_j,
              100 * h.max_drift_j / h.released_j);
  ASSERT_GT(h.released_j, 1e-4);
  EXPECT_LT(h.max_drift_j / h.released_j, 0.01);
}

TEST(Energy, PaperSchemeDissipatesAtFirstOrderInTheTimeStep) {
  const EnergyHistory coarse = swing("paper", 1e-4, 0.25);
  const EnergyHistory fine = swing("paper", 5e-5, 0.25);
  const double ratio = coarse.final_drift_j / fine.final_drift_j;
  std::printf("paper scheme: energy lost %.3e J (dt = 1e-4 s), %.3e J (dt = 5e-5 s), ratio %.2f\n",
              -coarse.final_drift_j, -fine.final_drift_j, ratio);
  EXPECT_LT(coarse.final_drift_j, 0.0); // dissipative, never creates energy
  EXPECT_LT(fine.final_drift_j, 0.0);
  EXPECT_GT(ratio, 1.6);
  EXPECT_LT(ratio, 2.5);
}

} // namespace
} // namespace fsi::structure
