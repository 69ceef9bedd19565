#include "CouplingLawRegistry.hpp"

#include "FeedbackLawConfig.hpp"
#include "PenaltyLawConfig.hpp"
#include "TwoPointSetsLawConfig.hpp"

namespace fsi::coupler {

const CouplingLawRegistry &CouplingLawRegistry::builtin() {
  static const CouplingLawRegistry registry = [] {
    CouplingLawRegistry r;
    r.add({"penalty", "Eq. (5) with X_ib^n = X^n: a drag relaxing V to U_ib, tau = rho_1 / (K_fsi dt)",
           [] { return std::make_unique<PenaltyLawConfig>(); }});
    r.add({"two_point_sets", "Eq. (5) with the paper's IB points advected by the fluid: a spring X - X_ib",
           [] { return std::make_unique<TwoPointSetsLawConfig>(); }});
    r.add({"feedback", "Huang, Shin & Sung: F_fsi = -(alpha int (U_ib - V) dt + beta (U_ib - V))",
           [] { return std::make_unique<FeedbackLawConfig>(); }});
    return r;
  }();
  return registry;
}

} // namespace fsi::coupler
