// The release schedule of a rag feed (structure_solver/feed): the same seed gives the same feed;
// a fixed interval gives its times; a Poisson stream has the mean interval asked for and the
// spread of an exponential one; the centres fill the region's box and the turns cover all
// orientations evenly (to a few standard errors of 4000 draws); plans that cannot be drawn are
// refused naming the field.

#include "structure_solver/feed/FeedSchedule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::structure::feed {
namespace {

FeedPlan plan(int rags, Spacing spacing, std::uint64_t seed = 7) {
  FeedPlan p;
  p.rags = rags;
  p.seed = seed;
  p.spacing = spacing;
  p.interval_s = 0.1;
  p.first_release_s = 0.05;
  p.region_min_m = Vec3(-0.02, -0.03, -0.30);
  p.region_max_m = Vec3(0.02, 0.01, -0.25);
  return p;
}

TEST(FeedSchedule, TheSameSeedGivesTheSameFeedAndAnotherSeedAnother) {
  const auto a = draw_releases(plan(20, Spacing::poisson)), b = draw_releases(plan(20, Spacing::poisson));
  const auto c = draw_releases(plan(20, Spacing::poisson, 8));
  ASSERT_EQ(a.size(), 20u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].time_s, b[i].time_s);
    EXPECT_EQ(a[i].centre_m, b[i].centre_m);
    EXPECT_EQ(a[i].turn.coeffs(), b[i].turn.coeffs());
  }
  EXPECT_NE(a[5].time_s, c[5].time_s);
  EXPECT_NE(a[5].centre_m, c[5].centre_m);
}

TEST(FeedSchedule, AFixedIntervalReleasesAtItsTimes) {
  const auto r = draw_releases(plan(12, Spacing::fixed));
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(r[static_cast<std::size_t>(i)].index, i);
    EXPECT_NEAR(r[static_cast<std::size_t>(i)].time_s, 0.05 + 0.1 * i, 1e-12);
  }
}

TEST(FeedSchedule, APoissonStreamHasTheMeanIntervalAndTheSpreadOfAnExponentialOne) {
  constexpr int n = 4000;
  const auto r = draw_releases(plan(n, Spacing::poisson));
  EXPECT_EQ(r.front().time_s, 0.05);
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 1; i < n; ++i) {
    const double gap = r[static_cast<std::size_t>(i)].time_s - r[static_cast<std::size_t>(i - 1)].time_s;
    ASSERT_GT(gap, 0.0);
    sum += gap;
    sum_sq += gap * gap;
  }
  const double mean = sum / (n - 1), sd = std::sqrt(sum_sq / (n - 1) - mean * mean);
  EXPECT_NEAR(mean, 0.1, 4.0 * 0.1 / std::sqrt(n - 1.0)); // 4 standard errors: 0.0063 s
  EXPECT_NEAR(sd / mean, 1.0, 0.1);                      // an exponential's: 1 (a fixed interval's: 0)
}

TEST(FeedSchedule, CentresFillTheBoxAndTurnsCoverAllOrientations) {
  constexpr int n = 4000;
  const auto p = plan(n, Spacing::fixed);
  const auto r = draw_releases(p);
  Vec3 mean_centre = Vec3::Zero(), mean_axis = Vec3::Zero();
  for (const auto &release : r) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(release.centre_m[k], p.region_min_m[k]);
      EXPECT_LE(release.centre_m[k], p.region_max_m[k]);
    }
    EXPECT_NEAR(release.turn.norm(), 1.0, 1e-12);
    mean_centre += release.centre_m / n;
    mean_axis += release.turn * Vec3::UnitZ() / n;
  }
  const Vec3 width = p.region_max_m - p.region_min_m;
  for (int k = 0; k < 3; ++k) {
    // Uniform in the box: the mean within 4 standard errors (width / sqrt(12 n)) of its centre.
    EXPECT_NEAR(mean_centre[k], 0.5 * (p.region_min_m[k] + p.region_max_m[k]), 4.0 * width[k] / std::sqrt(12.0 * n));
    // Uniform over the sphere: each component of a turned axis has mean 0 and variance 1/3.
    EXPECT_NEAR(mean_axis[k], 0.0, 4.0 * std::sqrt(1.0 / (3.0 * n)));
  }
  auto unturned = p;
  unturned.random_turn = false;
  EXPECT_TRUE(draw_releases(unturned).back().turn.isApprox(Eigen::Quaterniond::Identity(), 0.0));
}

TEST(FeedSchedule, TurnsAboutAnAxisKeepThatAxisAndSpreadTheAngleUniformly) {
  const int n = 2000;
  auto p = plan(n, Spacing::fixed);
  p.turn_axis = Vec3(0, 0, 2); // any length: its direction
  double mean_cos = 0.0, mean_sin = 0.0;
  for (const auto &release : draw_releases(p)) {
    // An upright rag stays upright: z is not moved, to round-off.
    EXPECT_LT((release.turn * Vec3::UnitZ() - Vec3::UnitZ()).norm(), 1e-15);
    const Vec3 x = release.turn * Vec3::UnitX();
    const double angle = std::atan2(x[1], x[0]);
    mean_cos += std::cos(angle) / n;
    mean_sin += std::sin(angle) / n;
  }
  // Uniform in angle: cos and sin have mean 0 and variance 1/2 (4 standard errors).
  EXPECT_NEAR(mean_cos, 0.0, 4.0 * std::sqrt(0.5 / n));
  EXPECT_NEAR(mean_sin, 0.0, 4.0 * std::sqrt(0.5 / n));
}

TEST(FeedSchedule, PlansThatCannotBeDrawnAreRefusedNamingTheField) {
  const auto refused = [](FeedPlan p, const std::string &word) {
    try {
      draw_releases(p);
      ADD_FAILURE() << "accepted: " << word;
    } catch (const std::invalid_argument &e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  auto p = plan(0, Spacing::fixed);
  refused(p, "feed.rags");
  p = plan(3, Spacing::poisson);
  p.interval_s = 0.0;
  refused(p, "interval");
  p = plan(3, Spacing::fixed);
  p.region_min_m.z() = 0.0;
  refused(p, "feed.region");
  p = plan(3, Spacing::fixed);
  p.first_release_s = -1.0;
  refused(p, "first_release_s");
}

} // namespace
} // namespace fsi::structure::feed
