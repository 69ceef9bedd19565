#pragma once
// The coupling law: how the coupler turns the fluid velocity at the Lagrangian points into
// the FSI force density F_fsi of Eqs. (3) and (8). A swappable family (see
// CouplingLawRegistry); the penalty law of Eq. (5) is the paper's.

#include "common/Types.hpp"

#include <string>

namespace fsi::coupler {

/// What a coupling law sees at step n (all structures concatenated, N x 3, SI).
struct CouplingInputs {
  const PointArray *x_now_m = nullptr;       ///< X^n, structure positions
  const PointArray *x_prev_m = nullptr;      ///< X^{n-1}
  const PointArray *x_ib_now_m = nullptr;    ///< X_ib^n, immersed-boundary points
  const PointArray *u_ib_now_m_per_s = nullptr; ///< U_ib^n, fluid velocity at X_ib^n
  double dt_s = 0.0;
};

struct CouplingOutputs {
  PointArray x_ib_next_m;              ///< X_ib^{n+1}
  PointArray force_density_n_per_measure;   ///< F_fsi^n: +f_fsi on the fluid (Eq. 1), -F_fsi on the structure (Eq. 3)
};

class CouplingLaw {
public:
  virtual ~CouplingLaw() = default;
  virtual std::string name() const = 0;
  /// Computes X_ib^{n+1} and F_fsi^n. Checks the input sizes (programmer errors).
  CouplingOutputs compute(const CouplingInputs &in);
  /// As above, into out, reusing its arrays' memory (no allocation once sized).
  void compute(const CouplingInputs &in, CouplingOutputs &out);

protected:
  virtual void compute_force(const CouplingInputs &in, CouplingOutputs &out) = 0;
};

} // namespace fsi::coupler
