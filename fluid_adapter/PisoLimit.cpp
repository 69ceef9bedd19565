#include "fluid_adapter/PisoLimit.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace fsi::fluid {

double PisoLimit::measured_limit(const PisoSettings &settings) {
  if (!settings.momentum_predictor || settings.outer_correctors != 1)
    return std::numeric_limits<double>::infinity();
  if (settings.correctors <= 1)
    return 0.55;
  if (settings.correctors == 2)
    return 30.5;
  return std::numeric_limits<double>::infinity();
}

std::string PisoLimit::refusal(const PisoSettings &settings, const ViscousNumber &d, double dt_s) {
  const double limit = measured_limit(settings);
  if (!(d.value > kMargin * limit))
    return "";
  std::ostringstream text;
  text << "the time step " << dt_s
       << " s (run.time_step_s; the precursor's: fluid.openfoam.precursor_time_step_s) gives the viscous number nu_eff dt sum 1/dx^2 = " << d.value
       << " in the cell at (" << d.where_m.x() << ", " << d.where_m.y() << ", " << d.where_m.z()
       << ") m; with momentumPredictor yes and nCorrectors " << settings.correctors
       << " (system/fvSolution, PIMPLE), OpenFOAM's PISO loop diverges above " << limit
       << " (measured, docs/verification.md: with or without bodies). Use run.time_step_s <= "
       << dt_s * kMargin * limit / d.value << " s, or nCorrectors " << settings.correctors + 1
       << " (stable beyond 1,800), or momentumPredictor no (a viscous flow needs no predictor)";
  return text.str();
}

} // namespace fsi::fluid
