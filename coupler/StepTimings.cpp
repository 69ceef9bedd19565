#include "StepTimings.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::coupler {

double StepTimings::overhead_s() const {
  return std::max(0.0, step_wall_s - interpolation_s - std::max(fluid_solve_s, structure_solve_s));
}

double StepTimings::idle_s() const { return std::abs(fluid_solve_s - structure_solve_s); }

StepTimings &StepTimings::operator+=(const StepTimings &o) {
  step_wall_s += o.step_wall_s;
  interpolation_s += o.interpolation_s;
  fluid_solve_s += o.fluid_solve_s;
  structure_solve_s += o.structure_solve_s;
  coupling_law_s += o.coupling_law_s;
  waiting_s += o.waiting_s;
  return *this;
}

std::array<double, 8> StepTimings::values() const {
  return {step_wall_s,    interpolation_s, fluid_solve_s, structure_solve_s,
          coupling_law_s, waiting_s,       overhead_s(),  idle_s()};
}

} // namespace fsi::coupler
