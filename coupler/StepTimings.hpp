#pragma once
// Where the wall time of one coupled step went (seconds). The fluid and structure solves run
// concurrently, so the step costs about max(fluid, structure) plus the overhead of coupling.

#include <array>
#include <string_view>

namespace fsi::coupler {

struct StepTimings {
  double step_wall_s = 0.0;        ///< the whole step, as the coupler saw it
  double interpolation_s = 0.0;    ///< fluid: U_ib^n at the points (reported by the fluid)
  double fluid_solve_s = 0.0;      ///< fluid: spreading (Eq. 8) and the PIMPLE step (reported)
  double structure_solve_s = 0.0;  ///< structure: Eq. (4) and Eq. (11) (reported)
  double coupling_law_s = 0.0;     ///< coupler: Eq. (5)
  double waiting_s = 0.0;          ///< coupler blocked on replies (includes the solves)
  /// Everything but the solves: messages, serialisation, the law, the coupler's bookkeeping.
  double overhead_s() const;
  /// Time the faster participant sat idle while the slower one solved.
  double idle_s() const;

  static constexpr std::array<std::string_view, 8> names{"step_wall_s",     "interpolation_s", "fluid_solve_s",
                                                         "structure_solve_s", "coupling_law_s", "waiting_s",
                                                         "overhead_s",      "idle_s"};
  std::array<double, 8> values() const;
  /// Adds the measured parts (not the derived ones), to average over several steps.
  StepTimings &operator+=(const StepTimings &other);
};

} // namespace fsi::coupler
