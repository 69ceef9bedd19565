#pragma once
// Aitken's dynamic relaxation (Irons & Tuck; Kuttler & Wall, Comput. Mech. 43, 2008): with the
// residual r_k = F~_k - F_k,
//   omega_k = -omega_{k-1} r_{k-1} . (r_k - r_{k-1}) / |r_k - r_{k-1}|^2,   F_{k+1} = F_k + omega_k r_k,
// omega_0 the configured relaxation at the first iteration of each step. For a linear H whose
// Jacobian is a multiple of the identity, lambda I, the second update lands on the fixed
// point: omega_1 = 1 / (1 - lambda).

#include "Accelerator.hpp"

namespace fsi::coupler {

class AitkenRelaxation final : public Accelerator {
public:
  explicit AitkenRelaxation(double initial_omega) : initial_(initial_omega) {}
  std::string name() const override { return "aitken"; }
  void begin_step() override { iteration_ = 0; }
  void next(const Eigen::VectorXd &x, const Eigen::VectorXd &x_tilde, Eigen::VectorXd &out) override;
  double last_omega() const { return omega_; }

private:
  double initial_, omega_ = 0.0;
  int iteration_ = 0;
  Eigen::VectorXd r_prev_, r_;
};

} // namespace fsi::coupler
