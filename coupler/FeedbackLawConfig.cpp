#include "FeedbackLawConfig.hpp"

#include "FeedbackCouplingLaw.hpp"

#include <cmath>

namespace fsi::coupler {

std::unique_ptr<CouplingLaw> FeedbackLawConfig::build() const {
  return std::make_unique<FeedbackCouplingLaw>(alpha_n_per_m_per_measure, beta_n_s_per_m_per_measure);
}

double FeedbackLawConfig::stable_time_step_s(double mass_per_measure) const {
  // A + 2B < 4 with A = alpha dt^2 / rho_1, B = beta dt / rho_1 (FeedbackCouplingLaw.hpp).
  const double alpha = alpha_n_per_m_per_measure, beta = beta_n_s_per_m_per_measure, rho = mass_per_measure;
  if (alpha == 0.0)
    return 2.0 * rho / beta;
  return (std::sqrt(beta * beta + 4.0 * alpha * rho) - beta) / alpha;
}

} // namespace fsi::coupler
