#include "TwoPointSetsLawConfig.hpp"

#include "TwoPointSetsCouplingLaw.hpp"

#include <cmath>

namespace fsi::coupler {

std::unique_ptr<CouplingLaw> TwoPointSetsLawConfig::build() const {
  return std::make_unique<TwoPointSetsCouplingLaw>(stiffness_n_per_m_per_measure);
}

double TwoPointSetsLawConfig::stable_time_step_s(double mass_per_measure) const {
  // e^{n+1} = (1 - a)(2 e^n - e^{n-1}), a = K dt^2 / rho_1: stable for a < 4/3
  // (TwoPointSetsCouplingLaw.hpp).
  return std::sqrt(4.0 * mass_per_measure / (3.0 * stiffness_n_per_m_per_measure));
}

} // namespace fsi::coupler
