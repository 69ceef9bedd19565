#pragma once
// When and where the rags of a feed are released (issue 33: rags fed in sequence, as test rigs
// do): a fixed interval or a Poisson stream at a mean interval, each rag's centre drawn
// uniformly in a box of the sump and its orientation turned at random (uniform over all
// rotations, or about one axis only), all from one seed. The whole schedule is drawn at setup, so that every process,
// a restart and a rerun with the same seed see the same rags at the same times.
//
// The draws come from std::mt19937_64's raw output mapped by this file (53 bits to [0, 1)), not
// from the standard library's distributions, whose algorithms differ between libraries: a seed
// gives the same feed wherever it runs.

#include "common/Types.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace fsi::structure::feed {

enum class Spacing { fixed, poisson };

struct FeedPlan {
  int rags = 1;                     ///< how many (>= 1)
  std::uint64_t seed = 1;
  Spacing spacing = Spacing::fixed;
  double interval_s = 0.1;          ///< fixed: between releases; poisson: the mean (> 0)
  double first_release_s = 0.0;     ///< the first rag's release (>= 0)
  Vec3 region_min_m = Vec3::Zero(); ///< the box the centres are drawn in (min <= max)
  Vec3 region_max_m = Vec3::Zero();
  bool random_turn = true;          ///< false: every rag as its kind is declared
  Vec3 turn_axis = Vec3::Zero();    ///< zero: turns uniform over all rotations; else about this axis only
  int kinds = 1;                    ///< kinds of rag to choose from (>= 1)
  bool random_kind = false;         ///< false: the kinds in turn; true: drawn with equal chances
};

struct Release {
  int index = 0;              ///< 0, 1, ... in release order
  double time_s = 0.0;
  Vec3 centre_m = Vec3::Zero();
  Eigen::Quaterniond turn = Eigen::Quaterniond::Identity(); ///< applied about the rag's centre
  int kind = 0;               ///< which of the plan's kinds
};

/// The releases of `plan`, in time order. Throws std::invalid_argument naming the field for a
/// plan that cannot be drawn (no rags, a non-positive interval, a box inside out).
std::vector<Release> draw_releases(const FeedPlan &plan);

} // namespace fsi::structure::feed
