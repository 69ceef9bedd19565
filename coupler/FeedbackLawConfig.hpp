#pragma once
// Keys of the feedback law of Huang, Shin & Sung (`coupling.law: feedback`).

#include "CouplingLawConfig.hpp"

namespace fsi::coupler {

class FeedbackLawConfig final : public CouplingLawConfigBase<FeedbackLawConfig> {
public:
  double alpha_n_per_m_per_measure = 1.0e5;
  double beta_n_s_per_m_per_measure = 1.0;

  template <class V> void visit_keys(V &v) {
    v.number("alpha_n_per_m_per_measure", alpha_n_per_m_per_measure, common::Range::at_least(0.0, "N/m^3 (sheet)"),
             "Integral gain alpha: F_fsi = -(alpha int (U_ib - V) dt + beta (U_ib - V)), a spring per unit of the "
             "structure's measure on the gap the fluid opens (Huang, Shin & Sung's -alpha).");
    v.number("beta_n_s_per_m_per_measure", beta_n_s_per_m_per_measure,
             common::Range::at_least(0.0, "N s/m^3 (sheet)"),
             "Proportional gain beta: a drag on the slip U_ib - V (Huang, Shin & Sung's -beta). Stable for "
             "alpha dt^2 / rho_1 + 2 beta dt / rho_1 < 4.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (!(alpha_n_per_m_per_measure + beta_n_s_per_m_per_measure > 0.0))
        v.fail_value("beta_n_s_per_m_per_measure", "and alpha_n_per_m_per_measure are both 0: give one of them a "
                                                   "positive value.");
  }

  std::unique_ptr<CouplingLaw> build() const override;
  double stable_time_step_s(double mass_per_measure) const override;
};

} // namespace fsi::coupler
