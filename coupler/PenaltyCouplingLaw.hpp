#pragma once
// The penalty law of Eq. (5): F_fsi^n = -K_fsi (X_ib^{n+1} - 2 X^n + X^{n-1}).
//
// Signs and units. Eq. (3) reads rho_1 X_tt = ... - F_fsi, so the structure feels
// +K (X_ib^{n+1} - 2 X^n + X^{n-1}): with X^{n+1} ~ 2 X^n - X^{n-1} the predicted position of
// the structure, the bracket is the gap between where the fluid carries the point and where the
// structure would go on its own, and the force pulls the structure toward the fluid. The fluid
// feels the opposite, +f_fsi in Eq. (1), spread from F_fsi with Eq. (8): action and reaction.
// F_fsi is a force per unit area of sheet (N/m^2; per unit length for a filament), so K_fsi
// is in N/m^3 (N/m^2 for filaments).
//
// When the immersed-boundary points coincide with the structure points (X_ib^n = X^n), the
// bracket is dt (U_ib^n - V^n) with V^n = (X^n - X^{n-1}) / dt: the law is a drag
// rho_1 dV/dt = K dt (U - V), which relaxes the structure velocity to the fluid velocity
// with the time constant tau = rho_1 / (K_fsi dt).

#include "CouplingLaw.hpp"

namespace fsi::coupler {

class PenaltyCouplingLaw final : public CouplingLaw {
public:
  explicit PenaltyCouplingLaw(double penalty_n_per_m_per_measure);
  std::string name() const override { return "penalty"; }
  double penalty_n_per_m_per_measure() const { return penalty_; }

protected:
  void compute_force(const CouplingInputs &in, CouplingOutputs &out) override;

private:
  double penalty_;
};

} // namespace fsi::coupler
