// The spreading of a wall correction over a sheet's grid (CorrectionSpread): the strain a
// correction makes between neighbours falls from d_t / spacing to 1 / (n + 1) of it; a point
// between two corrected ones takes their mean; corrected points and points out of reach stay.

#include "structure_solver/collision/CorrectionSpread.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fsi::structure::collision {
namespace {

constexpr int kN1 = 15, kN2 = 7;
constexpr double kSpacing = 0.01;

PointArray flat_grid() {
  PointArray x(kN1 * kN2, 3);
  for (int i = 0; i < kN1; ++i)
    for (int j = 0; j < kN2; ++j)
      x.row(i * kN2 + j) << i * kSpacing, j * kSpacing, 0.0;
  return x;
}

/// Largest |strain| of the grid's edges (along s1 and s2) against the flat grid's spacing.
double max_edge_strain(const PointArray &x) {
  double worst = 0.0;
  for (int i = 0; i < kN1; ++i)
    for (int j = 0; j < kN2; ++j) {
      if (i + 1 < kN1)
        worst = std::max(worst, std::abs((x.row((i + 1) * kN2 + j) - x.row(i * kN2 + j)).norm() / kSpacing - 1.0));
      if (j + 1 < kN2)
        worst = std::max(worst, std::abs((x.row(i * kN2 + j + 1) - x.row(i * kN2 + j)).norm() / kSpacing - 1.0));
    }
  return worst;
}

TEST(CorrectionSpread, AnInPlaneCorrectionStrainsItsNeighboursByOneOverNPlusOneOfIt) {
  const double move = 0.004; // d_t: the edge point of a sheet pushed out of a wall along it
  for (int n : {1, 2, 3, 5}) {
    const PointArray before = flat_grid();
    PointArray after = before;
    after(0 * kN2 + 3, 0) += move;
    EXPECT_NEAR(max_edge_strain(after), move / kSpacing, 1e-12); // Eq. 11 alone: 40 %
    const CorrectionSpread spread(kN1, kN2, n);
    spread.apply(before, after);
    // Along s1 the moves fall linearly, move (1 - k / (n + 1)) at k points away: each edge on
    // that line shortens by move / (n + 1); the edges off it by less.
    EXPECT_NEAR(max_edge_strain(after), move / ((n + 1) * kSpacing), 1e-12) << "n = " << n;
    EXPECT_NEAR(after(0 * kN2 + 3, 0) - before(0 * kN2 + 3, 0), move, 1e-15); // the corrected point stays
    EXPECT_NEAR(after(n * kN2 + 3, 0) - before(n * kN2 + 3, 0), move / (n + 1), 1e-15);
    EXPECT_EQ(after((n + 1) * kN2 + 3, 0), before((n + 1) * kN2 + 3, 0)); // out of reach
  }
}

TEST(CorrectionSpread, NeighboursOnTheOtherFaceOfANoseTheRagIsFoldedRoundStay) {
  // Rows 0-7 lie 6 mm over a plate, rows 8-14 folded back 6 mm under it (a rag wrapped round the
  // plate's edge at x = 0.07 m). Point (6, 3) is pushed 4 mm up off the top face: its neighbours
  // on the top face follow, those under the plate (16 mm behind the top face's plane) do not:
  // moved up they would be pushed into the plate.
  PointArray before = flat_grid();
  for (int i = 0; i < kN1; ++i)
    for (int j = 0; j < kN2; ++j)
      before.row(i * kN2 + j) << (i <= 7 ? i : 15 - i) * kSpacing, j * kSpacing, i <= 7 ? 0.006 : -0.006;
  PointArray after = before;
  after(6 * kN2 + 3, 2) += 0.004;
  CorrectionSpread(kN1, kN2, 3).apply(before, after);
  EXPECT_NEAR(after(7 * kN2 + 3, 2) - before(7 * kN2 + 3, 2), 0.003, 1e-15); // w = 3/4
  EXPECT_NEAR(after(4 * kN2 + 3, 2) - before(4 * kN2 + 3, 2), 0.002, 1e-15); // w = 1/2
  for (int i : {8, 9})
    for (int j = 0; j < kN2; ++j)
      EXPECT_EQ(after(i * kN2 + j, 2), before(i * kN2 + j, 2)) << i << ", " << j;
}

TEST(CorrectionSpread, APointBetweenTwoCorrectedOnesTakesTheirMeanNotTheirSum) {
  const PointArray before = flat_grid();
  PointArray after = before;
  after(6 * kN2 + 3, 2) += 0.004;
  after(8 * kN2 + 3, 2) += 0.002;
  const CorrectionSpread spread(kN1, kN2, 3);
  const std::size_t moved = spread.apply(before, after);
  EXPECT_NEAR(after(7 * kN2 + 3, 2), 0.003, 1e-15); // weights 3/4 and 3/4: the mean
  EXPECT_NEAR(after(6 * kN2 + 3, 2), 0.004, 1e-15);
  EXPECT_NEAR(after(8 * kN2 + 3, 2), 0.002, 1e-15);
  // every point within 3 of either (grid distance under 4), the two corrected ones left out
  int within = 0;
  for (int i = 0; i < kN1; ++i)
    for (int j = 0; j < kN2; ++j)
      if ((std::hypot(i - 6, j - 3) < 4.0 || std::hypot(i - 8, j - 3) < 4.0) && i * kN2 + j != 6 * kN2 + 3 &&
          i * kN2 + j != 8 * kN2 + 3)
        ++within;
  EXPECT_EQ(moved, static_cast<std::size_t>(within));
}

TEST(CorrectionSpread, NothingCorrectedNothingMoved) {
  const PointArray before = flat_grid();
  PointArray after = before;
  EXPECT_EQ(CorrectionSpread(kN1, kN2, 2).apply(before, after), 0u);
  EXPECT_EQ((after - before).cwiseAbs().maxCoeff(), 0.0);
}

TEST(CorrectionSpread, BadGridsAndPointCountsAreRefused) {
  EXPECT_THROW(CorrectionSpread(kN1, kN2, 0), std::invalid_argument);
  EXPECT_THROW(CorrectionSpread(0, kN2, 2), std::invalid_argument);
  const PointArray before = flat_grid();
  PointArray fewer = before.topRows(10);
  EXPECT_THROW(CorrectionSpread(kN1, kN2, 2).apply(before, fewer), std::invalid_argument);
}

} // namespace
} // namespace fsi::structure::collision
