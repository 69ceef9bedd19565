// One suite over every tension scheme (solver.tension, TensionSchemeRegistry) and, where it
// applies, both sheet-like models: the contract each scheme keeps (TensionSwing.hpp describes
// the swinging membrane flap and filament). Scheme-specific accuracy comparisons stay in
// StabilizedTensionTest.cpp.

#include "TensionSwing.hpp"
#include "common/ConfigError.hpp"
#include "structure_solver/StepSystemFactory.hpp"
#include "structure_solver/TensionSchemeRegistry.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <ostream>

namespace fsi::structure {
namespace {

using testing::swing;
using testing::Swing;

struct SchemeCase {
  std::string scheme;
  std::string model;
  /// Below the stretching-wave limit: max point difference from the frozen scheme per largest
  /// distance a point moved (ReproducesTheFrozenSchemeBelowTheStretchingWaveLimit).
  double tolerance_against_frozen = 0.0;
};

void PrintTo(const SchemeCase &c, std::ostream *os) { *os << c.scheme << " on a " << c.model; }

std::string case_name(const ::testing::TestParamInfo<SchemeCase> &info) {
  return info.param.scheme + "_" + info.param.model;
}

class TensionSchemeContract : public ::testing::TestWithParam<SchemeCase> {};

TEST_P(TensionSchemeContract, KeepsAStructureAtRestAtRest) {
  // No gravity, no initial velocity: the rest shape is an equilibrium of every scheme, at the
  // step of the reproduction test below and at one far beyond the frozen limit.
  const auto &[scheme, model, tolerance] = GetParam();
  (void)tolerance;
  for (const double dt : {2e-5, 4e-4}) {
    if (scheme == "frozen" && dt > 1e-4)
      continue; // beyond its stretching-wave limit (at rest it would still stay, but that is luck)
    const Swing at_rest = swing(model, scheme, dt, 200 * dt, /*gravity=*/false);
    const Swing start = swing(model, scheme, dt, 0.0, /*gravity=*/false);
    const double moved_m = (at_rest.x - start.x).cwiseAbs().maxCoeff();
    std::printf("%s %s dt = %.0e s: moved %.3e m in 200 steps\n", scheme.c_str(), model.c_str(), dt, moved_m);
    ASSERT_TRUE(at_rest.finite);
    EXPECT_LT(moved_m, 1e-11); // round-off: measured at most 1.1e-12 m (filament, 1 m long)
  }
}

TEST_P(TensionSchemeContract, ReproducesTheFrozenSchemeBelowTheStretchingWaveLimit) {
  // Below Delta s / (1.5 c) the stabilized scheme moves nothing to the implicit side (the
  // paper's step bit for bit); the linearized one differs by its O(dt^3) Newton term.
  const auto &[scheme, model, tolerance] = GetParam();
  const double dt = model == "membrane" ? 2e-5 : 1e-4;
  const double end = model == "membrane" ? 0.05 : 0.2;
  const Swing frozen = swing(model, "frozen", dt, end);
  const Swing other = swing(model, scheme, dt, end);
  ASSERT_TRUE(frozen.finite && other.finite);
  const double moved = (frozen.x - swing(model, "frozen", dt, 0.0).x).rowwise().norm().maxCoeff();
  const double difference = (other.x - frozen.x).rowwise().norm().maxCoeff();
  std::printf("%s %s dt = %.0e s, %.2g s: max point difference from frozen %.3e m (per distance moved %.3e)\n",
              scheme.c_str(), model.c_str(), dt, end, difference, difference / moved);
  ASSERT_GT(moved, 0.01);
  if (tolerance == 0.0)
    EXPECT_EQ(difference, 0.0);
  else
    EXPECT_LT(difference / moved, tolerance);
}

TEST_P(TensionSchemeContract, ReportsExplicitStretchingOnlyForTheFrozenScheme) {
  const auto &[scheme, model, tolerance] = GetParam();
  (void)tolerance;
  EXPECT_EQ(swing(model, scheme, 1e-4, 0.0).explicit_stretching, scheme == "frozen");
}

INSTANTIATE_TEST_SUITE_P(EverySchemeAndModel, TensionSchemeContract,
                         // linearized: measured 1.1e-7 (membrane, dt = 2e-5 s) and 9.6e-5 (filament,
                         // dt = 1e-4 s) of the distance moved.
                         ::testing::Values(SchemeCase{"frozen", "membrane", 0.0}, SchemeCase{"stabilized", "membrane", 0.0},
                                           SchemeCase{"linearized", "membrane", 1e-6},
                                           SchemeCase{"frozen", "filament", 0.0}, SchemeCase{"stabilized", "filament", 0.0},
                                           SchemeCase{"linearized", "filament", 1e-3}),
                         case_name);

/// The schemes that take the stretching implicitly, on the stiff membrane flap.
class ImplicitTensionScheme : public ::testing::TestWithParam<std::string> {};

TEST_P(ImplicitTensionScheme, StaysStableSixTimesBeyondTheStretchingWaveLimit) {
  // dt = 4e-4 s = 6.3 x Delta s / c: the frozen tension blows up within a few steps
  // (FrozenTension.BlowsUpSixTimesBeyondTheStretchingWaveLimit in StabilizedTensionTest.cpp).
  const Swing s = swing("membrane", GetParam(), 4e-4, 0.2);
  std::printf("%s, dt = 4e-4 s: max stretch %.5f, max energy gain %.2e J\n", GetParam().c_str(), s.max_stretch,
              s.max_energy_gain_j);
  ASSERT_TRUE(s.finite);
  EXPECT_LT(s.max_stretch, 1.01);
  EXPECT_LT(s.max_energy_gain_j, 1e-6); // dissipative: never above the initial energy
}

INSTANTIATE_TEST_SUITE_P(StabilizedAndLinearized, ImplicitTensionScheme, ::testing::Values("stabilized", "linearized"),
                         [](const ::testing::TestParamInfo<std::string> &info) { return info.param; });

TEST(TensionSchemeRegistry, NamesEverySchemeAndRefusesAnUnknownNameListingThem) {
  const auto &registry = TensionSchemeRegistry::builtin();
  EXPECT_EQ(registry.names(), (std::vector<std::string>{"frozen", "stabilized", "linearized"}));
  try {
    (void)registry.entry("implicit");
    FAIL() << "an unknown scheme name was accepted";
  } catch (const common::ConfigError &e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("unknown tension scheme 'implicit'"), std::string::npos) << message;
    EXPECT_NE(message.find("frozen, stabilized, linearized"), std::string::npos) << message;
  }
}

TEST(TensionSchemeRegistry, EverySchemeTheConfigurationOffersHasAStepSystemAndNoOther) {
  // The configuration's names (linked by the case alone) and the solver's step systems are two
  // lists: a scheme added to one only would be refused at run time, or never offered.
  EXPECT_EQ(StepSystemFactory::builtin().names(), TensionSchemeRegistry::builtin().names());
}

TEST(TensionSchemeRegistry, ACaseWithAnUnknownSchemeIsRefusedWithTheValidNames) {
  try {
    (void)testing::load_case(testing::swing_yaml("membrane", "implicit", 1e-4, true));
    FAIL() << "a case with tension: implicit was accepted";
  } catch (const common::ConfigError &e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("frozen, stabilized, linearized"), std::string::npos) << message;
  }
}

} // namespace
} // namespace fsi::structure
