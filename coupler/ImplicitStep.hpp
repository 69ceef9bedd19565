#pragma once
// Implicit coupling (coupling.scheme: implicit): the fixed point F = H(F) of each step, where H
// advances the fluid and the structure from t^n under F and evaluates the coupling law at the
// end of the step (X^{n+1}, X^n, U_ib^{n+1}). Iterated from the previous step's last H (for the
// penalty law the explicit scheme's F^n: one iteration is the explicit step), each next F from
// the accelerator (constant or Aitken relaxation, IQN-ILS), until converged or
// coupling.implicit.max_iterations.

#include "Accelerator.hpp"
#include "ImplicitCouplingConfig.hpp"
#include "StepScheme.hpp"

namespace fsi::coupler {

class ImplicitStep final : public StepScheme {
public:
  explicit ImplicitStep(const ImplicitCouplingConfig &settings);

  void advance(long n, StepExchange &exchange) override;
  int iterations() const override { return iterations_; }
  double residual() const override { return residual_; }
  std::string progress_note(double mean_iterations) const override;
  void save_state(checkpoint::StateArchive &archive) const override;
  void load_state(const checkpoint::StateArchive &archive, Eigen::Index n_points) override;
  std::string accelerator_name() const { return accelerator_->name(); }

private:
  /// F_0 of step n: the previous step's last H, or on a run's first step the explicit F^n.
  void first_force(long n, StepExchange &exchange);
  /// F~_k against F_k: updates residual_; true when within the tolerances.
  bool compare(const PointArray &f_k, const PointArray &f_tilde, Eigen::Index n_points);
  void warn_unconverged(long n);

  ImplicitCouplingConfig settings_;
  std::unique_ptr<Accelerator> accelerator_;
  CouplingOutputs evaluated_; ///< F~ = H(F): the law at the end of the step
  PointArray guess_;          ///< the next step's F_0
  bool have_guess_ = false;
  Eigen::VectorXd next_force_;
  int iterations_ = 1;          ///< of the last step
  double residual_ = 0.0;       ///< |F~ - F| / |F~| of the last step's last iteration
  long unconverged_steps_ = 0;
};

} // namespace fsi::coupler
