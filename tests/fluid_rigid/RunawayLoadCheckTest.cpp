// The runaway check of the rigid bodies' loads: a load multiplied by a constant factor every
// step is caught after RunawayLoadCheck::kSteps steps, naming the body, the load and the step;
// physical histories (a start from rest like t^2 or t^3, an oscillation, a decay, a shedding
// onset growing by 2 % a step) never are; a repeated step counts once.

#include "fluid_adapter/rigid/RunawayLoadCheck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace fsi::fluid::rigid {
namespace {

const std::vector<std::string> kNames = {"impeller", "rotor"};
constexpr double kDt_s = 1e-3;

/// Steps 1..n_steps with body "rotor"'s force |F| = force(k) (the impeller's loads steady):
/// the first step whose check fails, or 0.
long first_failure(const std::function<double(long)> &force, long n_steps, std::string *message = nullptr) {
  RunawayLoadCheck check;
  for (long k = 1; k <= n_steps; ++k) {
    BodyLoad steady, rotor;
    steady.force_n = Vec3(0.1, 0.0, 0.0);
    steady.torque_n_m = Vec3(0.0, 0.0, -0.2);
    rotor.force_n = Vec3(0.0, force(k), 0.0);
    rotor.torque_n_m = Vec3(0.0, 0.0, -1e-5);
    const std::string problem = check.observe(k, k * kDt_s, kNames, {steady, rotor});
    if (!problem.empty()) {
      if (message)
        *message = problem;
      return k;
    }
  }
  return 0;
}

TEST(RunawayLoadCheck, CatchesAForceGrowingByAConstantFactorAfterThirtySteps) {
  // The case: 3.7 times every 10 steps (1.14 a step) from 1e-4 N.
  std::string message;
  EXPECT_EQ(first_failure([](long k) { return 1e-4 * std::pow(1.14, k - 1); }, 200, &message),
            RunawayLoadCheck::kSteps + 1);
  EXPECT_NE(message.find("step 31 (t = 0.031 s)"), std::string::npos) << message;
  EXPECT_NE(message.find("the force on rigid body 'rotor' grows without bound"), std::string::npos) << message;
  // Slower than 10 % a step is left to the speed limit of the flow.
  EXPECT_EQ(first_failure([](long k) { return 1e-4 * std::pow(1.09, k - 1); }, 200), 0);
}

TEST(RunawayLoadCheck, LeavesPhysicalHistoriesAlone) {
  EXPECT_EQ(first_failure([](long k) { return 1e-3 * k * k; }, 2000), 0);      // start from rest, t^2
  EXPECT_EQ(first_failure([](long k) { return 1e-6 * k * k * k; }, 2000), 0);  // t^3
  EXPECT_EQ(first_failure([](long k) { return std::pow(1.0 * k, 6.0); }, 2000), 0); // t^6
  EXPECT_EQ(first_failure([](long k) { return 1.0 + std::sin(0.3 * k); }, 2000), 0);
  EXPECT_EQ(first_failure([](long k) { return std::exp(-0.5 * k); }, 2000), 0);
  // The onset of vortex shedding: exponential from round-off, 2 % a step, then saturated.
  EXPECT_EQ(first_failure([](long k) { return std::min(1e-12 * std::exp(0.02 * k), 1.0); }, 2000), 0);
}

TEST(RunawayLoadCheck, CountsARepeatedStepOnce) {
  // Implicit coupling takes a step several times: the repeats replace its record.
  RunawayLoadCheck check;
  std::string problem;
  long k = 1;
  for (; k <= 100 && problem.empty(); ++k) {
    for (int repeat = 0; repeat < 3 && problem.empty(); ++repeat) {
      BodyLoad load;
      load.force_n = Vec3(1e-4 * std::pow(1.14, k - 1) * (repeat == 0 ? 0.5 : 1.0), 0.0, 0.0);
      problem = check.observe(k, k * kDt_s, {"rotor"}, {load});
    }
  }
  EXPECT_EQ(k - 1, RunawayLoadCheck::kSteps + 1) << problem;
}

} // namespace
} // namespace fsi::fluid::rigid
