#include "structure_solver/feed/FeedSchedule.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace fsi::structure::feed {
namespace {

/// A double in [0, 1) from the generator's top 53 bits.
double unit(std::mt19937_64 &generator) { return static_cast<double>(generator() >> 11) * 0x1.0p-53; }

/// Uniform over all rotations (Shoemake, Graphics Gems III: three uniform numbers to a unit
/// quaternion).
Eigen::Quaterniond random_turn(std::mt19937_64 &generator) {
  const double u1 = unit(generator), u2 = unit(generator), u3 = unit(generator);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double two_pi = 2.0 * M_PI;
  return Eigen::Quaterniond(b * std::cos(two_pi * u3), a * std::sin(two_pi * u2), a * std::cos(two_pi * u2),
                            b * std::sin(two_pi * u3));
}

/// Uniform in angle about `axis` (a unit vector).
Eigen::Quaterniond random_turn_about(std::mt19937_64 &generator, const Vec3 &axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(2.0 * M_PI * unit(generator), axis));
}

} // namespace

std::vector<Release> draw_releases(const FeedPlan &plan) {
  if (plan.rags < 1)
    throw std::invalid_argument("feed.rags = " + std::to_string(plan.rags) + ": at least one rag");
  if (!(plan.interval_s > 0.0) || !std::isfinite(plan.interval_s))
    throw std::invalid_argument("feed: the interval between releases (" + std::to_string(plan.interval_s) +
                                " s) must be positive");
  if (plan.kinds < 1)
    throw std::invalid_argument("feed.kinds: at least one kind of rag");
  if (!(plan.first_release_s >= 0.0))
    throw std::invalid_argument("feed.first_release_s = " + std::to_string(plan.first_release_s) +
                                ": must be 0 or later");
  for (int k = 0; k < 3; ++k)
    if (!(plan.region_min_m[k] <= plan.region_max_m[k]))
      throw std::invalid_argument("feed.region: min_m[" + std::to_string(k) + "] = " +
                                  std::to_string(plan.region_min_m[k]) + " is above max_m[" + std::to_string(k) +
                                  "] = " + std::to_string(plan.region_max_m[k]));
  if (!plan.turn_axis.allFinite())
    throw std::invalid_argument("feed.turn_axis: not a finite vector");
  const bool about_axis = plan.turn_axis.norm() > 0.0;
  const Vec3 axis = about_axis ? Vec3(plan.turn_axis.normalized()) : Vec3::UnitZ();
  std::mt19937_64 generator(plan.seed);
  std::vector<Release> releases;
  double t = plan.first_release_s;
  for (int i = 0; i < plan.rags; ++i) {
    if (i > 0)
      t += plan.spacing == Spacing::fixed ? plan.interval_s : -plan.interval_s * std::log1p(-unit(generator));
    Release r;
    r.index = i;
    r.time_s = t;
    for (int k = 0; k < 3; ++k)
      r.centre_m[k] = plan.region_min_m[k] + unit(generator) * (plan.region_max_m[k] - plan.region_min_m[k]);
    if (plan.random_turn)
      r.turn = about_axis ? random_turn_about(generator, axis) : random_turn(generator);
    r.kind = plan.random_kind ? std::min(plan.kinds - 1, static_cast<int>(unit(generator) * plan.kinds))
                              : i % plan.kinds;
    releases.push_back(r);
  }
  return releases;
}

} // namespace fsi::structure::feed
