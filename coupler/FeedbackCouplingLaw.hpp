#pragma once
// The Goldstein-type feedback law of Huang, Shin & Sung (J. Comput. Phys. 226, 2007), the
// classic coupling for flexible filaments and flags:
//   F_fsi^n = -(alpha I^n + beta W^n),   W^n = U_ib^n - V^n,   I^n = I^{n-1} + W^n dt,
// with V^n = (X^n - X^{n-1}) / dt and U_ib^n sampled at X^n. Huang, Shin & Sung write
// F = alpha' int (U_ib - V) dt + beta' (U_ib - V) with large negative alpha', beta' and the same
// signs as ours for the fluid (+f) and the structure (-F): our gains are alpha = -alpha',
// beta = -beta', both >= 0. I is the gap between a point the fluid would carry and the
// structure point (m): alpha is a spring (N/m^3 for a sheet), beta a drag (N s/m^3). The law
// keeps I (checkpointed); it changes only when the coupler accepts the step.
//
// With alpha = 0 and beta = K_fsi dt it is the penalty law's drag. Its stability: Eq. (4) under
// this load alone in a uniform flow gives, with A = alpha dt^2 / rho_1 and B = beta dt / rho_1,
//   I^{n+1} = (2 - A - B) I^n - (1 - B) I^{n-1},
// whose roots lie in the unit disc (Jury: |1 - B| < 1, p(1) = A > 0, p(-1) = 4 - A - 2B > 0)
// iff 0 < B < 2 and A + 2B < 4; with beta = 0 it is undamped (|mu| = 1 for A < 4). So
//   dt < (sqrt(beta^2 + 4 alpha rho_1) - beta) / alpha   (2 rho_1 / beta when alpha = 0).

#include "CouplingLaw.hpp"

namespace fsi::coupler {

class FeedbackCouplingLaw final : public CouplingLaw {
public:
  FeedbackCouplingLaw(double alpha_n_per_m_per_measure, double beta_n_s_per_m_per_measure);
  std::string name() const override { return "feedback"; }

  void start(const PointArray &x_m) override { integral_ = PointArray::Zero(x_m.rows(), 3); }
  void accept(const CouplingOutputs &out) override;
  void save_state(checkpoint::StateArchive &archive) const override;
  void load_state(const checkpoint::StateArchive &archive, long n_points) override;

  const PointArray &integral_m() const { return integral_; }

protected:
  void compute_force(const CouplingInputs &in, CouplingOutputs &out) override;

private:
  double alpha_, beta_;
  PointArray integral_; ///< I^{n-1} (m)
  PointArray next_;     ///< I^n of the last compute()
};

} // namespace fsi::coupler
