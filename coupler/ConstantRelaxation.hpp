#pragma once
// F_{k+1} = F_k + omega (F~_k - F_k). For a linear H with Jacobian J it converges iff every
// eigenvalue lambda of J has |1 - omega (1 - lambda)| < 1, at that rate.

#include "Accelerator.hpp"

namespace fsi::coupler {

class ConstantRelaxation final : public Accelerator {
public:
  explicit ConstantRelaxation(double omega) : omega_(omega) {}
  std::string name() const override { return "constant"; }
  void begin_step() override {}
  void next(const Eigen::VectorXd &x, const Eigen::VectorXd &x_tilde, Eigen::VectorXd &out) override;

private:
  double omega_;
};

} // namespace fsi::coupler
