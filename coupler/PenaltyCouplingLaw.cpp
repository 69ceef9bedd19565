#include "PenaltyCouplingLaw.hpp"

#include <stdexcept>

namespace fsi::coupler {

PenaltyCouplingLaw::PenaltyCouplingLaw(double penalty_n_per_m_per_measure) : penalty_(penalty_n_per_m_per_measure) {
  if (!(penalty_ > 0.0))
    throw std::invalid_argument("the penalty constant K_fsi must be positive (N/m^3)");
}

void PenaltyCouplingLaw::compute_force(const CouplingInputs &in, CouplingOutputs &out) {
  // Eq. (5).
  out.force_density_n_per_measure = -penalty_ * (out.x_ib_next_m - 2.0 * *in.x_now_m + *in.x_prev_m);
}

} // namespace fsi::coupler
