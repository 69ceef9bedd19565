#pragma once
// Eq. (5) as section 2.3 of the paper states it, with two sets of Lagrangian points: the
// immersed-boundary points X_ib, advected by the fluid on their own,
//   X_ib^{n+1} = X_ib^n + U_ib^n dt,   U_ib^n = U(X_ib^n),
// and the structure points X of Eq. (4), held to them by
//   F_fsi^n = -K_fsi (X_ib^{n+1} - 2 X^n + X^{n-1}).
// The coupler owns X_ib (state of this law, checkpointed); the fluid interpolates at X_ib^n and
// spreads F_fsi^n at X^n (Eq. 8).
//
// What it is as a discrete ODE. Eq. (4) with only this load (no elasticity, a uniform flow U,
// so X_ib^{n+1} - 2 X_ib^n + X_ib^{n-1} = 0) reads, for the gap e^n = X^n - X_ib^n and
// a = K_fsi dt^2 / rho_1,
//   X^{n+1} - 2 X^n + X^{n-1} = a (X_ib^{n+1} - 2 X^n + X^{n-1})
//   =>  e^{n+1} = (1 - a) (2 e^n - e^{n-1}).
// This is the leapfrog (Stormer-Verlet) discretisation, evaluated at the predictor, of a spring
// rho_1 e'' = -K_fsi e: the structure oscillates about the IB points with
// omega = sqrt(K_fsi / rho_1), damped numerically by |mu|^2 = 1 - a per step. The roots of
// mu^2 - 2 (1 - a) mu + (1 - a) = 0 lie in the unit disc (Jury: |1 - a| < 1, p(1) = a > 0,
// p(-1) = 4 - 3a > 0) iff 0 < a < 4/3: stable for dt < sqrt(4 rho_1 / (3 K_fsi)).
//
// What K_fsi means now: a spring stiffness per unit measure (N/m^3 for a sheet) between each
// structure point and its IB point, no longer a drag rate: the structure follows the fluid's
// displacement, not its velocity. Unlike the drag law, the gap X - X_ib is not reset each
// step: if the structure is held (a pole, a wall, its own tension) while the fluid goes on, the
// gap and the force grow until the force has slowed the fluid at X_ib (two-way coupling); with
// a prescribed flow that cannot react they grow without bound.

#include "CouplingLaw.hpp"

namespace fsi::coupler {

class TwoPointSetsCouplingLaw final : public CouplingLaw {
public:
  explicit TwoPointSetsCouplingLaw(double stiffness_n_per_m_per_measure);
  std::string name() const override { return "two_point_sets"; }

  void start(const PointArray &x_m) override { x_ib_ = x_m; }
  const PointArray &interpolation_points(const PointArray &) const override { return x_ib_; }
  /// The IB points advance with U_ib^n at X_ib^n: evaluated at the end of the step the law would
  /// need X_ib^{n+2}; implicit coupling takes the penalty or the feedback law.
  bool allows_implicit() const override { return false; }
  void accept(const CouplingOutputs &out) override;
  void save_state(checkpoint::StateArchive &archive) const override;
  void load_state(const checkpoint::StateArchive &archive, long n_points) override;

  const PointArray &ib_points_m() const { return x_ib_; }

protected:
  void compute_force(const CouplingInputs &in, CouplingOutputs &out) override;

private:
  double stiffness_;
  PointArray x_ib_; ///< X_ib^n
};

} // namespace fsi::coupler
