// Eqs. 6-7: the 4-point kernel is continuous where its branches meet and satisfies its
// discrete moment conditions for every shift s (to round-off).

#include "fluid_adapter/ibm/PeskinKernel.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::fluid::ibm {
namespace {

constexpr double round_off = 1e-14;

/// sum over j of f(s - j), over every j where phi(s - j) may be non-zero.
template <class F> double sum_over_shifts(double s, F f) {
  double sum = 0.0;
  for (int j = -3; j <= 3; ++j)
    sum += f(s - j);
  return sum;
}

TEST(PeskinKernel, IsContinuousWhereItsBranchesMeet) {
  // Just below |r| = 1 the inner branch is used, at 1 the outer one; at 2 phi drops to zero.
  for (double sign : {1.0, -1.0}) {
    EXPECT_NEAR(PeskinKernel::phi(sign * std::nextafter(1.0, 0.0)), PeskinKernel::phi(sign * 1.0), round_off);
    EXPECT_NEAR(PeskinKernel::phi(sign * 1.0), 0.25, round_off);
    EXPECT_NEAR(PeskinKernel::phi(sign * std::nextafter(2.0, 0.0)), 0.0, round_off);
    EXPECT_EQ(PeskinKernel::phi(sign * 2.0), 0.0);
  }
  EXPECT_NEAR(PeskinKernel::phi(0.0), 0.5, round_off);
}

TEST(PeskinKernel, SatisfiesItsMomentConditionsForEveryShift) {
  for (int i = 0; i < 1000; ++i) {
    const double s = i / 1000.0 + 1e-4 * std::sin(i); // in [0, 1), not only grid values
    const double zeroth = sum_over_shifts(s, [](double r) { return PeskinKernel::phi(r); });
    const double first = sum_over_shifts(s, [](double r) { return r * PeskinKernel::phi(r); });
    const double square = sum_over_shifts(s, [](double r) { return std::pow(PeskinKernel::phi(r), 2); });
    ASSERT_NEAR(zeroth, 1.0, round_off) << "s = " << s;
    ASSERT_NEAR(first, 0.0, round_off) << "s = " << s;
    ASSERT_NEAR(square, 0.375, round_off) << "s = " << s;
  }
}

TEST(PeskinKernel, EvenAndZeroOutsideItsSupport) {
  for (double r : {0.3, 1.0, 1.7, 1.999})
    EXPECT_EQ(PeskinKernel::phi(r), PeskinKernel::phi(-r));
  for (double r : {2.0, 2.5, 1e9})
    EXPECT_EQ(PeskinKernel::phi(r), 0.0);
}

TEST(PeskinKernel, DeltaIsTheScaledTensorProductAndIntegratesToOne) {
  const double h = 0.02;
  const Vec3 offset(0.013, -0.021, 0.005);
  const double expected = PeskinKernel::phi(0.65) * PeskinKernel::phi(-1.05) * PeskinKernel::phi(0.25) / (h * h * h);
  EXPECT_NEAR(PeskinKernel::delta_per_m3(offset, h), expected, 1e-12 * expected);
  // Sum over a lattice of spacing h shifted by an arbitrary point: 1 (Eq. 6 times h^3).
  const Vec3 point(0.0037, 0.0121, -0.0088);
  double sum = 0.0;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = -4; k <= 4; ++k)
        sum += PeskinKernel::delta_per_m3(h * Vec3(i, j, k) - point, h) * h * h * h;
  EXPECT_NEAR(sum, 1.0, round_off);
}

} // namespace
} // namespace fsi::fluid::ibm
