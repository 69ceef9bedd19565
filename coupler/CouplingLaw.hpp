#pragma once
// The coupling law: how the coupler turns the fluid velocity at the immersed-boundary points
// into the FSI force density F_fsi of Eqs. (3) and (8). A swappable family (see
// CouplingLawRegistry):
// - penalty (PenaltyCouplingLaw): Eq. (5) with X_ib^n = X^n, a drag;
// - two_point_sets (TwoPointSetsCouplingLaw): Eq. (5) with the paper's own immersed-boundary
//   points, advected by the fluid, a spring to the structure;
// - feedback (FeedbackCouplingLaw): the Goldstein-type law of Huang, Shin & Sung.
// A law may keep state across steps (the IB points, an integral): it changes only when the
// coupler accepts a step (accept()), so an implicit scheme may evaluate a step many times, and
// it is part of the coupler's checkpoint (save_state / load_state).

#include "checkpoint/StateArchive.hpp"
#include "common/Types.hpp"

#include <string>

namespace fsi::coupler {

/// What a coupling law sees at step n (all structures concatenated, N x 3, SI).
struct CouplingInputs {
  const PointArray *x_now_m = nullptr;       ///< X^n, structure positions
  const PointArray *x_prev_m = nullptr;      ///< X^{n-1}
  const PointArray *u_ib_now_m_per_s = nullptr; ///< U_ib^n, fluid velocity at interpolation_points()
  double dt_s = 0.0;
};

struct CouplingOutputs {
  PointArray x_ib_next_m;              ///< X_ib^{n+1} = X_ib^n + U_ib^n dt
  PointArray force_density_n_per_measure;   ///< F_fsi^n: +f_fsi on the fluid (Eq. 1), -F_fsi on the structure (Eq. 3)
};

class CouplingLaw {
public:
  virtual ~CouplingLaw() = default;
  virtual std::string name() const = 0;

  /// Once, with the structures' first state X^0 (a restart: X^k, then load_state()).
  virtual void start(const PointArray & /*x_m*/) {}
  /// Where the fluid velocity U_ib^n is sampled: the structure points X^n, or the law's own
  /// immersed-boundary points X_ib^n. Eq. (8) always spreads at X^n.
  virtual const PointArray &interpolation_points(const PointArray &x_now_m) const { return x_now_m; }
  /// Whether the law may be evaluated at the end of a step (implicit coupling): its inputs
  /// then are X^{n+1}, X^n and U_ib^{n+1}.
  virtual bool allows_implicit() const { return true; }

  /// Computes X_ib^{n+1} and F_fsi^n from the law's state; does not change the state.
  /// Checks the input sizes (programmer errors).
  CouplingOutputs compute(const CouplingInputs &in);
  /// As above, into out, reusing its arrays' memory (no allocation once sized).
  void compute(const CouplingInputs &in, CouplingOutputs &out);
  /// The step of the last compute() is accepted: the law's state moves on to it.
  virtual void accept(const CouplingOutputs & /*out*/) {}

  /// The law's state for a checkpoint (names under "law/"), and back.
  virtual void save_state(checkpoint::StateArchive & /*archive*/) const {}
  virtual void load_state(const checkpoint::StateArchive & /*archive*/, long /*n_points*/) {}

protected:
  /// X_ib^n of the step being computed (interpolation_points of X^n).
  virtual void compute_force(const CouplingInputs &in, CouplingOutputs &out) = 0;
};

} // namespace fsi::coupler
