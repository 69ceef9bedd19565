#pragma once
// Keys of the penalty coupling law of Eq. (5) (`coupling.law: penalty`).

#include "CouplingLawConfig.hpp"

namespace fsi::coupler {

class PenaltyLawConfig final : public CouplingLawConfigBase<PenaltyLawConfig> {
public:
  double stiffness_n_per_m3 = 1.0e5;

  template <class V> void visit_keys(V &v) {
    v.number("stiffness_n_per_m3", stiffness_n_per_m3, common::Range::positive("N/m^3"),
             "Penalty constant K_fsi of Eq. (5) (N/m^2 for filaments). The structure velocity relaxes to the "
             "fluid velocity with tau = rho_1 / (K_fsi dt); stable for K_fsi dt^2 / rho_1 < 2.");
  }

  std::unique_ptr<CouplingLaw> build() const override;
  double stable_time_step_s(double density_kg_per_m2) const override;
};

} // namespace fsi::coupler
