// The coupling-law registry: laws are found by name, unknown names are rejected with the valid
// ones, and the penalty law's stability limit is the one its relaxation map predicts.

#include "coupler/CouplingLawRegistry.hpp"
#include "coupler/PenaltyCouplingLaw.hpp"
#include "coupler/PenaltyLawConfig.hpp"
#include "common/ConfigReader.hpp"
#include "LawHarness.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::coupler {
namespace {

TEST(CouplingLawRegistry, BuildsThePenaltyLawByName) {
  auto config = CouplingLawRegistry::builtin().make_config("penalty");
  auto law = config->build();
  EXPECT_EQ(law->name(), "penalty");
}

TEST(CouplingLawRegistry, UnknownLawListsTheValidOnes) {
  try {
    CouplingLawRegistry::builtin().make_config("penality");
    FAIL() << "no error for an unknown law";
  } catch (const common::ConfigError &e) {
    EXPECT_NE(std::string(e.what()).find("Did you mean 'penalty'? Valid laws: penalty"), std::string::npos) << e.what();
  }
}

// The relaxation map of one point, U - V^{n+1} = (1 - a)(U - V^n) with a = K dt^2 / rho_1, run
// through the law itself: it decays just below the limit stable_time_step_s and grows above it.
double relaxation_after(double dt, double rho, double k, int steps) {
  PenaltyCouplingLaw law(k);
  return testing::free_point_after(law, dt, rho, steps).slip(dt); // |U - V|
}

TEST(PenaltyLawConfig, StabilityLimitMatchesTheRelaxationMap) {
  PenaltyLawConfig config;
  config.stiffness_n_per_m_per_measure = 1.0e5;
  const double rho = 0.08, limit = config.stable_time_step_s(rho);
  EXPECT_NEAR(limit, std::sqrt(2.0 * rho / 1.0e5), 1e-15);
  EXPECT_LT(relaxation_after(0.99 * limit, rho, 1.0e5, 2000), 1.0);
  EXPECT_GT(relaxation_after(1.01 * limit, rho, 1.0e5, 2000), 1.0e3);
}

TEST(PenaltyLawConfig, TheFormerKeyOfKIsAnsweredWithItsNewName) {
  // K_fsi is N/m^3 for a sheet and N/m^2 for a filament: the key no longer says m^3.
  common::ConfigReader reader(YAML::Load("stiffness_n_per_m3: 2.5e5"), "case.yaml", "coupling");
  PenaltyLawConfig config;
  try {
    config.visit(reader);
    FAIL() << "the former key was accepted";
  } catch (const common::ConfigError &e) {
    EXPECT_NE(std::string(e.what()).find("coupling.stiffness_n_per_m3 was renamed stiffness_n_per_m_per_measure"),
              std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace fsi::coupler
