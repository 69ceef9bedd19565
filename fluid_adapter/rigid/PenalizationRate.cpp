#include "fluid_adapter/rigid/PenalizationRate.hpp"

#include <stdexcept>
#include <string>

namespace fsi::fluid::rigid {

PenalizationRate PenalizationRate::from_permeability(double kinematic_viscosity_m2_per_s,
                                                     double permeability_m2) {
  if (!(kinematic_viscosity_m2_per_s > 0.0) || !(permeability_m2 > 0.0))
    throw std::invalid_argument("IBM penalization: kinematic viscosity (" +
                                std::to_string(kinematic_viscosity_m2_per_s) +
                                " m^2/s) and permeability K_ibm (" + std::to_string(permeability_m2) +
                                " m^2) must both be positive");
  return PenalizationRate(kinematic_viscosity_m2_per_s / permeability_m2);
}

PenalizationRate PenalizationRate::from_relaxation_time(double relaxation_time_s) {
  if (!(relaxation_time_s > 0.0))
    throw std::invalid_argument("IBM penalization: relaxation time K_ibm (" +
                                std::to_string(relaxation_time_s) + " s) must be positive");
  return PenalizationRate(1.0 / relaxation_time_s);
}

} // namespace fsi::fluid::rigid
