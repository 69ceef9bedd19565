#include "PenaltyLawConfig.hpp"

#include "PenaltyCouplingLaw.hpp"

#include <cmath>

namespace fsi::coupler {

std::unique_ptr<CouplingLaw> PenaltyLawConfig::build() const {
  return std::make_unique<PenaltyCouplingLaw>(stiffness_n_per_m_per_measure);
}

double PenaltyLawConfig::stable_time_step_s(double mass_per_measure) const {
  // With X_ib^n = X^n, Eq. (5) in Eq. (4) gives U - V^{n+1} = (1 - a)(U - V^n) with
  // a = K dt^2 / rho_1: the velocity relaxation is stable for a < 2 (monotone for a < 1).
  return std::sqrt(2.0 * mass_per_measure / stiffness_n_per_m_per_measure);
}

} // namespace fsi::coupler
