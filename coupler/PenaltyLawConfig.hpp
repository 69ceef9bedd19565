#pragma once
// Keys of the penalty coupling law of Eq. (5) (`coupling.law: penalty`).

#include "CouplingLawConfig.hpp"

namespace fsi::coupler {

class PenaltyLawConfig final : public CouplingLawConfigBase<PenaltyLawConfig> {
public:
  double stiffness_n_per_m_per_measure = 1.0e5;

  template <class V> void visit_keys(V &v) {
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (v.has("stiffness_n_per_m3"))
        v.fail_value("stiffness_n_per_m3", "was renamed stiffness_n_per_m_per_measure: N/m^3 for a sheet, N/m^2 "
                                           "for a filament (per metre of gap, per unit of the structure's measure); "
                                           "rename the key, the value stays.");
    v.number("stiffness_n_per_m_per_measure", stiffness_n_per_m_per_measure,
             common::Range::positive("N/m^3 (sheet), N/m^2 (filament)"),
             "Penalty constant K_fsi of Eq. (5): force per unit of the structure's measure (area of a sheet, "
             "length of a filament) per metre between X_ib and X. The structure velocity relaxes to the fluid "
             "velocity with tau = rho_1 / (K_fsi dt); stable for K_fsi dt^2 / rho_1 < 2.");
  }

  std::unique_ptr<CouplingLaw> build() const override;
  double stable_time_step_s(double mass_per_measure) const override;
};

} // namespace fsi::coupler
