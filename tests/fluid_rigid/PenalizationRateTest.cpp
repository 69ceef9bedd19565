// The penalization coefficient per unit density and the slip an implicit step leaves.

#include "fluid_adapter/rigid/PenalizationRate.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fsi::fluid::rigid {
namespace {

TEST(PenalizationRate, PermeabilityReadingIsNuOverK) {
  const auto rate = PenalizationRate::from_permeability(1e-6, 1e-6); // water, K = 1e-6 m^2
  EXPECT_DOUBLE_EQ(rate.per_s(), 1.0);
  EXPECT_DOUBLE_EQ(rate.dynamic_per_s(1000.0), 1000.0); // mu/K = 1e-3 / 1e-6
  EXPECT_GT(rate.slip_left_after_step(1e-4), 0.999);    // a weak sponge: see the header
}

TEST(PenalizationRate, RelaxationTimeReadingEnforcesTheBodyVelocity) {
  const auto rate = PenalizationRate::from_relaxation_time(1e-6);
  EXPECT_DOUBLE_EQ(rate.per_s(), 1e6);
  EXPECT_LT(rate.slip_left_after_step(1e-4), 1e-2);
  EXPECT_NEAR(rate.slip_left_after_step(1e-4), 1.0 / 101.0, 1e-15);
}

TEST(PenalizationRate, NonPositiveInputsAreRejected) {
  EXPECT_THROW(PenalizationRate::from_permeability(0.0, 1e-6), std::invalid_argument);
  EXPECT_THROW(PenalizationRate::from_permeability(1e-6, -1.0), std::invalid_argument);
  EXPECT_THROW(PenalizationRate::from_relaxation_time(0.0), std::invalid_argument);
}

} // namespace
} // namespace fsi::fluid::rigid
