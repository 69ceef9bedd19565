#include "CouplingLawRegistry.hpp"

#include "PenaltyLawConfig.hpp"

namespace fsi::coupler {

const CouplingLawRegistry &CouplingLawRegistry::builtin() {
  static const CouplingLawRegistry registry = [] {
    CouplingLawRegistry r;
    r.add({"penalty", "Eq. (5): F_fsi = -K_fsi (X_ib^{n+1} - 2 X^n + X^{n-1})",
           [] { return std::make_unique<PenaltyLawConfig>(); }});
    return r;
  }();
  return registry;
}

} // namespace fsi::coupler
