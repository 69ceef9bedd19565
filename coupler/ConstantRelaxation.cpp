#include "ConstantRelaxation.hpp"

namespace fsi::coupler {

void ConstantRelaxation::next(const Eigen::VectorXd &x, const Eigen::VectorXd &x_tilde, Eigen::VectorXd &out) {
  out = x + omega_ * (x_tilde - x);
}

} // namespace fsi::coupler
