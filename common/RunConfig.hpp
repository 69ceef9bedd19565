#pragma once
// The case's `run` section: time stepping and output, shared by every process of a run (the
// coupler, the structure and the fluids step with the same Delta t to the same end time).

#include "common/ConfigReader.hpp"
#include "common/Range.hpp"
#include "common/Types.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

namespace fsi::common {

/// A plane that ends a run once every point of every structure is past it (on the side its
/// normal points to): a rag that has left a pump through its discharge.
struct StopPlane {
  Vec3 point_m{0.0, 0.0, 0.0};
  Vec3 normal{1.0, 0.0, 0.0};

  template <class V> void visit(V &v) {
    v.vec3("point_m", point_m, "m", "A point of the plane.");
    v.vec3("normal", normal, "1", "Its normal, towards the side every structure point must reach.");
    if constexpr (std::is_same_v<V, ConfigReader>)
      if (!(normal.norm() > 0.0))
        v.fail_value("normal", "is zero: give the direction the structures leave by, e.g. [1, 0, 0].");
  }

  /// Every row of `points_m` (positions) lies strictly past the plane.
  bool all_past(const PointArray &points_m) const {
    if (points_m.rows() == 0)
      return false;
    return (((points_m.rowwise() - point_m.transpose()) * normal).array() > 0.0).all();
  }
};

struct RunConfig {
  double end_time_s = 1.0;
  double time_step_s = 1e-4;
  double output_interval_s = 0.01;
  std::string output_directory = "output";
  double progress_interval_s = 5.0;
  std::optional<StopPlane> stop_when_past;
  double checkpoint_interval_s = 0.0;
  int checkpoint_keep = 2;

  template <class V> void visit(V &v) {
    v.number("end_time_s", end_time_s, common::Range::positive("s"), "Simulated time to reach.");
    v.number("time_step_s", time_step_s, common::Range::positive("s"),
             "Time step Delta t (rule of section 2.2: Delta s / Delta t >= 100 m/s).");
    v.number("output_interval_s", output_interval_s, common::Range::positive("s"),
             "Simulated time between saved steps (rounded to whole steps).");
    v.text("output_directory", output_directory, "Results folder, relative to the case folder.");
    v.number("progress_interval_s", progress_interval_s, common::Range::positive("s"),
             "Wall-clock time between progress lines in the log.");
    v.optional_section("stop_when_past", stop_when_past,
                       "End the run early, completed, at the first step where every point of every structure is "
                       "past this plane (a rag that has left through a pump's discharge); the coupler checks it in "
                       "a coupled run, the structure solver in a run of its own.");
    v.number("checkpoint_interval_s", checkpoint_interval_s, common::Range::non_negative("s"),
             "Simulated time between checkpoints (rounded to whole steps; 0: none): every process writes its "
             "whole state to <output>/checkpoints/, from which ./fsi run --restart resumes exactly (docs/restart.md).");
    v.integer("checkpoint_keep", checkpoint_keep, common::Range::at_least(1, "1"),
              "Complete checkpoints kept (older ones are removed as new ones complete).");
  }

  /// Steps between checkpoints (0: none).
  long checkpoint_every() const {
    return checkpoint_interval_s > 0.0 ? std::max(1L, std::lround(checkpoint_interval_s / time_step_s)) : 0L;
  }

  /// Number of steps from t = 0 to the end time.
  long n_steps() const { return std::lround(end_time_s / time_step_s); }
};

} // namespace fsi::common
