#pragma once
// The case's `run` section: time stepping and output, shared by every process of a run (the
// coupler, the structure and the fluids step with the same Delta t to the same end time).

#include "common/ConfigReader.hpp"
#include "common/Range.hpp"

#include <cmath>
#include <string>

namespace fsi::common {

struct RunConfig {
  double end_time_s = 1.0;
  double time_step_s = 1e-4;
  double output_interval_s = 0.01;
  std::string output_directory = "output";
  double progress_interval_s = 5.0;

  template <class V> void visit(V &v) {
    v.number("end_time_s", end_time_s, common::Range::positive("s"), "Simulated time to reach.");
    v.number("time_step_s", time_step_s, common::Range::positive("s"),
             "Time step Delta t (rule of section 2.2: Delta s / Delta t >= 100 m/s).");
    v.number("output_interval_s", output_interval_s, common::Range::positive("s"),
             "Simulated time between saved steps (rounded to whole steps).");
    v.text("output_directory", output_directory, "Results folder, relative to the case folder.");
    v.number("progress_interval_s", progress_interval_s, common::Range::positive("s"),
             "Wall-clock time between progress lines in the log.");
  }

  /// Number of steps from t = 0 to the end time.
  long n_steps() const { return std::lround(end_time_s / time_step_s); }
};

} // namespace fsi::common
