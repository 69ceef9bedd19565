#include "TwoPointSetsCouplingLaw.hpp"

#include <stdexcept>

namespace fsi::coupler {

TwoPointSetsCouplingLaw::TwoPointSetsCouplingLaw(double stiffness_n_per_m_per_measure)
    : stiffness_(stiffness_n_per_m_per_measure) {
  if (!(stiffness_ > 0.0))
    throw std::invalid_argument("the penalty constant K_fsi must be positive (N/m^3)");
}

void TwoPointSetsCouplingLaw::compute_force(const CouplingInputs &in, CouplingOutputs &out) {
  // Eq. (5), X_ib^{n+1} from the IB points' own state (CouplingLaw::compute).
  out.force_density_n_per_measure = -stiffness_ * (out.x_ib_next_m - 2.0 * *in.x_now_m + *in.x_prev_m);
}

void TwoPointSetsCouplingLaw::accept(const CouplingOutputs &out) { x_ib_ = out.x_ib_next_m; }

void TwoPointSetsCouplingLaw::save_state(checkpoint::StateArchive &archive) const {
  archive.put_points("law/x_ib_m", x_ib_);
}

void TwoPointSetsCouplingLaw::load_state(const checkpoint::StateArchive &archive, long n_points) {
  x_ib_ = archive.points("law/x_ib_m", n_points);
}

} // namespace fsi::coupler
