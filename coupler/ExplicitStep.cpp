#include "ExplicitStep.hpp"

namespace fsi::coupler {

void ExplicitStep::advance(long n, StepExchange &exchange) {
  const double t = static_cast<double>(n) * exchange.time_step_s();
  auto &law = exchange.law();
  exchange.interpolate_fluid_velocity(n, t, law.interpolation_points(exchange.state().x_now_m)); // U_ib^n at X_ib^n
  exchange.apply_coupling_law(exchange.coupled()); // X_ib^{n+1} and F_fsi^n, Eq. (5)
  exchange.advance_fluid_and_structure(n, false);  // Eq. (8) + PIMPLE || Eq. (4) + Eq. (11), concurrently
  law.accept(exchange.coupled());                  // the law's state (IB points, integral) moves to step n + 1
}

} // namespace fsi::coupler
