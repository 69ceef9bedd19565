#pragma once
// IQN-ILS, the interface quasi-Newton method with an approximation of the inverse Jacobian
// from a least-squares model (Degroote, Bathe & Vierendeels, Comput. Struct. 87, 2009), the
// Anderson acceleration of the fixed point F = H(F). With the residual r_k = F~_k - F_k and the
// differences of successive iterates as columns,
//   V = [r_{i+1} - r_i],  W = [F~_{i+1} - F~_i],
// c = argmin |V c + r_k| (QR with column pivoting, which drops near-dependent columns) and
//   F_{k+1} = F~_k + W c.
// The first iteration of a step without columns relaxes with omega. Columns of the last
// `reuse_steps` steps are kept (they carry the Jacobian from step to step, and are checkpointed;
// 0: none). On a linear
// H of dimension m it reaches the fixed point in at most m + 1 iterations (it is then GMRES).

#include "Accelerator.hpp"

#include <Eigen/Dense>

#include <deque>

namespace fsi::coupler {

class IqnIlsAccelerator final : public Accelerator {
public:
  IqnIlsAccelerator(double initial_omega, int reuse_steps) : omega_(initial_omega), reuse_steps_(reuse_steps) {}
  std::string name() const override { return "iqn_ils"; }
  void begin_step() override;
  void next(const Eigen::VectorXd &x, const Eigen::VectorXd &x_tilde, Eigen::VectorXd &out) override;
  void end_step() override;
  /// The columns of the last reuse_steps steps: a restart goes on with the same Jacobian model.
  void save_state(checkpoint::StateArchive &archive) const override;
  void load_state(const checkpoint::StateArchive &archive, long size) override;
  /// Columns in use (this step's and the reused ones).
  long n_columns() const;

private:
  double omega_;
  int reuse_steps_;
  int iteration_ = 0;
  Eigen::VectorXd r_prev_, x_tilde_prev_;
  /// Per step, its difference columns (V, W), newest step last.
  std::deque<std::pair<std::vector<Eigen::VectorXd>, std::vector<Eigen::VectorXd>>> steps_;
};

} // namespace fsi::coupler
