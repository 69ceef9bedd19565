#pragma once
// How the coupler advances one step of section 2.3 (coupling.scheme): explicitly, the paper's
// sequence once (ExplicitStep), or implicitly, repeated until the coupling law at the end of
// the step agrees with the force the step was advanced under (ImplicitStep, with its
// accelerator). A scheme owns what it carries from step to step and checkpoints it.

#include "StepExchange.hpp"
#include "checkpoint/StateArchive.hpp"

#include <memory>
#include <string>

namespace fsi::coupler {

class StepScheme {
public:
  virtual ~StepScheme() = default;
  /// Advances step n: both participants from t^n to t^{n+1} under exchange.coupled(), X^{n+1}
  /// into exchange.state(), the law's state to step n + 1.
  virtual void advance(long n, StepExchange &exchange) = 0;
  /// Coupling iterations of the last step and the relative residual of its last one.
  virtual int iterations() const { return 1; }
  virtual double residual() const { return 0.0; }
  /// What the progress line says of the scheme (mean_iterations: per step since the last line).
  virtual std::string progress_note(double /*mean_iterations*/) const { return ""; }
  /// The scheme's state across steps, in the coupler's checkpoint part.
  virtual void save_state(checkpoint::StateArchive & /*archive*/) const {}
  virtual void load_state(const checkpoint::StateArchive & /*archive*/, Eigen::Index /*n_points*/) {}
};

} // namespace fsi::coupler
