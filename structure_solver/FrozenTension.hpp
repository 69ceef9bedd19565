#pragma once
// solver.tension: frozen: sigma at X^n, the paper's semi-implicit Eq. (4) as printed
// (StepSystem.hpp). Stretching is then explicit and the step is stable only for about
// Delta s / Delta t >= sqrt(2 phi / rho_1).

#include "ScalarStepSystem.hpp"
#include "StepSystem.hpp"

namespace fsi::structure {

class FrozenTension final : public StepSystem {
public:
  explicit FrozenTension(const StepSettings &settings);

  int solve(const StepInputs &in, PointArray &x_next) override;
  const Eigen::SparseMatrix<double> &matrix() const override { return system_.matrix(); }
  bool using_direct_solver() const override { return system_.using_direct_solver(); }
  bool explicit_stretching() const override { return true; }

private:
  ScalarStepSystem system_;
};

} // namespace fsi::structure
