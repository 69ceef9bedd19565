#pragma once
// Keys of the paper's two-point-set law of Eq. (5) (`coupling.law: two_point_sets`).

#include "CouplingLawConfig.hpp"

namespace fsi::coupler {

class TwoPointSetsLawConfig final : public CouplingLawConfigBase<TwoPointSetsLawConfig> {
public:
  double stiffness_n_per_m_per_measure = 1.0e5;

  template <class V> void visit_keys(V &v) {
    v.number("stiffness_n_per_m_per_measure", stiffness_n_per_m_per_measure,
             common::Range::positive("N/m^3 (sheet), N/m^2 (filament)"),
             "Penalty constant K_fsi of Eq. (5): a spring per unit of the structure's measure between each "
             "structure point and its immersed-boundary point, which the fluid advects. The structure oscillates "
             "about the IB points at omega = sqrt(K_fsi / rho_1); stable for K_fsi dt^2 / rho_1 < 4/3.");
  }

  std::unique_ptr<CouplingLaw> build() const override;
  double stable_time_step_s(double mass_per_measure) const override;
};

} // namespace fsi::coupler
