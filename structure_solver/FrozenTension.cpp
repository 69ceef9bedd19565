#include "FrozenTension.hpp"

namespace fsi::structure {

FrozenTension::FrozenTension(const StepSettings &settings) : system_(settings) {}

int FrozenTension::solve(const StepInputs &in, PointArray &x_next) {
  system_.fill_values(*in.x_now, in.dt_s);
  PointArray rhs;
  system_.assemble_rhs(in, rhs);
  return system_.solve(in, rhs, x_next);
}

} // namespace fsi::structure
