#pragma once
// The `feed.clog_criterion` section (issue 33): when a pump fed rags in sequence counts as
// clogged, as test rigs judge it. The solver does not use it; it is read here so that a typo
// stops the run at load instead of after hours, and python/fsi/clog_criterion.py evaluates it on
// the run's traces (the definitions are there).

#include "common/ConfigReader.hpp"
#include "common/Range.hpp"

#include <optional>
#include <type_traits>

namespace fsi::structure::feed {

struct ClogCriterionConfig {
  std::optional<double> head_drop_fraction;
  std::optional<double> power_rise_fraction;
  int held_revolutions = 3;
  std::optional<int> retained_rags;
  double residence_revolutions = 10.0;

  template <class V> void visit(V &v) {
    v.optional_number("head_drop_fraction", head_drop_fraction, common::Range{0.0, 1.0, true, true, "1"},
                      "Clogged when a revolution's mean head is this fraction under the clean pump's at the same "
                      "flow (absent: not checked).");
    v.optional_number("power_rise_fraction", power_rise_fraction, common::Range::positive("1"),
                      "Clogged when a revolution's mean shaft power is this fraction over the clean pump's "
                      "(absent: not checked).");
    v.integer("held_revolutions", held_revolutions, common::Range::at_least(1, "1"),
              "For this many consecutive revolutions (the head and power conditions).");
    v.optional_integer("retained_rags", retained_rags, common::Range::at_least(1, "1"),
                       "Clogged when this many rags are retained at once (absent: not checked).");
    v.number("residence_revolutions", residence_revolutions, common::Range::positive("1"),
             "A rag in the scene this many revolutions after its release is retained.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (!head_drop_fraction && !power_rise_fraction && !retained_rags)
        v.fail("has no condition: give at least one of head_drop_fraction, power_rise_fraction, retained_rags.");
  }
};

} // namespace fsi::structure::feed
