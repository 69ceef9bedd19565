#include "ModelConfig.hpp"

#include "LagrangianSheet.hpp"
#include "motion/MotionFactory.hpp"

namespace fsi::structure {

void fill_shared_setup(SheetSetup &setup, const SharedSheetKeys &keys, const BuildContext &context) {
  const auto &[clamp_motion, initial, solver] = keys;
  setup.initial_velocity_m_per_s = initial.velocity_m_per_s;
  setup.curved_rest_state = initial.curved_rest_state;
  if (clamp_motion)
    setup.clamp_motion = motion::make_motion(*clamp_motion, context.gravity_m_per_s2.norm());
  setup.gravity_m_per_s2 = context.gravity_m_per_s2;
  setup.time_step_s = context.time_step_s;
  setup.linear_solver = solver.linear_solver;
  setup.time_scheme = solver.time_scheme;
  setup.tension_scheme = solver.tension;
  setup.max_stretch_ratio = solver.max_stretch_ratio;
  setup.max_speed_m_per_s = solver.max_speed_m_per_s;
}

} // namespace fsi::structure
