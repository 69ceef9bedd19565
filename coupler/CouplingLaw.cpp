#include "CouplingLaw.hpp"

#include <stdexcept>

namespace fsi::coupler {

CouplingOutputs CouplingLaw::compute(const CouplingInputs &in) {
  CouplingOutputs out;
  compute(in, out);
  return out;
}

void CouplingLaw::compute(const CouplingInputs &in, CouplingOutputs &out) {
  const auto n = in.x_now_m->rows();
  const PointArray &x_ib = interpolation_points(*in.x_now_m);
  if (in.x_prev_m->rows() != n || x_ib.rows() != n || in.u_ib_now_m_per_s->rows() != n)
    throw std::logic_error("coupling law '" + name() + "': inputs have different numbers of points");
  if (!(in.dt_s > 0.0))
    throw std::logic_error("coupling law '" + name() + "': time step must be positive");
  // Section 2.3: the immersed-boundary points move with the local fluid velocity,
  // X_ib^{n+1} = X_ib^n + U_ib^n dt (explicit Euler).
  out.x_ib_next_m = x_ib + in.dt_s * *in.u_ib_now_m_per_s;
  compute_force(in, out);
}

} // namespace fsi::coupler
