#pragma once
// The case's `feed` section (issue 33): rags released into a running scene in sequence, as pump
// test rigs feed them. It names the rags' kinds (structure entries without a name's index,
// release or placement) and the schedule (FeedSchedule: how many, when, where, turned how).
// At load it becomes structures of their own (case/CaseConfig: expand_feed), named after their
// kind and release index (rag01, rag02, ...), each with its release_time_s, placement and
// remove_when_past, so that every process of a run sees the same rags.

#include "structure_solver/StructureConfig.hpp"
#include "structure_solver/feed/ClogCriterionConfig.hpp"
#include "structure_solver/feed/FeedSchedule.hpp"

#include <optional>
#include <type_traits>
#include <vector>

namespace fsi::structure::feed {

struct FeedRegion {
  Vec3 min_m = Vec3::Zero();
  Vec3 max_m = Vec3::Zero();

  template <class V> void visit(V &v) {
    v.vec3("min_m", min_m, "m", "Lowest corner of the box the rags' centroids are drawn in.");
    v.vec3("max_m", max_m, "m", "Highest corner (equal to min_m along an axis: no spread along it).");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      for (int k = 0; k < 3; ++k)
        if (min_m[k] > max_m[k])
          v.fail_value("max_m", "is below min_m along axis " + std::to_string(k) + ": the box is inside out.");
  }
};

enum class KindOrder { cycle, random };

struct FeedConfig {
  int rags = 1;
  int seed = 1;
  Spacing spacing = Spacing::fixed;
  double interval_s = 0.1;
  double first_release_s = 0.0;
  FeedRegion region;
  bool random_turn = true;
  Vec3 turn_axis = Vec3::Zero();
  KindOrder kind_order = KindOrder::cycle;
  std::vector<StructureConfig> kinds;
  std::optional<common::StopPlane> remove_when_past;
  std::optional<ClogCriterionConfig> clog_criterion;

  template <class V> void visit(V &v) {
    v.integer("rags", rags, common::Range::between(1, 10000, "1"), "How many rags the feed releases.");
    v.integer("seed", seed, common::Range::non_negative("1"),
              "Seed of every draw (times of a Poisson stream, centres, turns, kinds): a seed gives the same feed on "
              "every machine.");
    v.choice("spacing", spacing, {{"fixed", Spacing::fixed}, {"poisson", Spacing::poisson}},
             "'fixed': a release every interval_s; 'poisson': a Poisson stream whose mean interval is interval_s.");
    v.number("interval_s", interval_s, common::Range::positive("s"),
             "Time between releases (poisson: its mean). A rig's interval in impeller revolutions is this times "
             "the speed in rev/s.");
    v.number("first_release_s", first_release_s, common::Range::non_negative("s"), "When the first rag is released.");
    v.section("region", region, "The box in the sump the rags' centroids are drawn in, uniformly.");
    v.flag("random_turn", random_turn,
           "Turn each rag about its centroid at random (false: as its kind declares it).");
    v.vec3("turn_axis", turn_axis, "1",
           "[0, 0, 0]: the random turns are uniform over all rotations; an axis: about it only, by a uniform "
           "angle (rags declared upright in a sump lower than they are long stay upright).");
    v.choice("kind_order", kind_order, {{"cycle", KindOrder::cycle}, {"random", KindOrder::random}},
             "Which kind each rag is: the kinds in turn, or drawn with equal chances.");
    v.list("kinds", kinds,
           "The kinds of rag: structure entries (a model and its keys; `name` names the rags, rag01, rag02, ... "
           "by default) without release_time_s or placement, which the feed sets.");
    v.optional_section("remove_when_past", remove_when_past,
                       "The plane past which a rag has left (the discharge): it is removed from the scene there. "
                       "A kind's own remove_when_past takes precedence.");
    v.optional_section("clog_criterion", clog_criterion,
                       "When the fed pump counts as clogged (read by the feed report, python/fsi/feed_report.py).");
    if constexpr (std::is_same_v<V, common::ConfigReader>) {
      if (kinds.empty())
        v.fail_value("kinds", "is empty: declare at least one kind of rag (a structure entry).");
      for (std::size_t k = 0; k < kinds.size(); ++k)
        if (kinds[k].release_time_s != 0.0 || kinds[k].placement)
          v.list_item("kinds", k).fail("release_time_s and placement are the feed's to set: remove them from "
                                        "the kind.");
    }
  }

  FeedPlan plan() const {
    FeedPlan p;
    p.rags = rags;
    p.seed = static_cast<std::uint64_t>(seed);
    p.spacing = spacing;
    p.interval_s = interval_s;
    p.first_release_s = first_release_s;
    p.region_min_m = region.min_m;
    p.region_max_m = region.max_m;
    p.random_turn = random_turn;
    p.turn_axis = turn_axis;
    p.kinds = static_cast<int>(kinds.size());
    p.random_kind = kind_order == KindOrder::random;
    return p;
  }
};

} // namespace fsi::structure::feed
