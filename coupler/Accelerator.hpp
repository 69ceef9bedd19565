#pragma once
// Acceleration of the sub-iterations of implicit coupling: the fixed-point problem of a step is
// F = H(F), H the coupling law evaluated at the end of the step advanced under F (all points'
// force densities as one vector). Given the iterate F_k the step was advanced with and
// F~_k = H(F_k), an accelerator proposes F_{k+1}. The family (constant, aitken, iqn_ils) is
// chosen by ImplicitCouplingConfig::acceleration; make_accelerator() is its one registry.

#include "ImplicitCouplingConfig.hpp"
#include "checkpoint/StateArchive.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace fsi::coupler {

class Accelerator {
public:
  virtual ~Accelerator() = default;
  virtual std::string name() const = 0;
  /// A new time step: its first iterate is the previous step's last F~.
  virtual void begin_step() = 0;
  /// F_{k+1} from F_k (x) and F~_k = H(F_k) (x_tilde).
  virtual void next(const Eigen::VectorXd &x, const Eigen::VectorXd &x_tilde, Eigen::VectorXd &out) = 0;
  /// The step was accepted at its last iterate.
  virtual void end_step() {}
  /// What it carries from step to step, for the coupler's checkpoint part (entries under
  /// "implicit/"); load_state() takes it back (`size`: the length of F), or starts afresh from
  /// a part without it.
  virtual void save_state(checkpoint::StateArchive & /*archive*/) const {}
  virtual void load_state(const checkpoint::StateArchive & /*archive*/, long /*size*/) {}
};

std::unique_ptr<Accelerator> make_accelerator(const ImplicitCouplingConfig &config);

} // namespace fsi::coupler
