#include "AitkenRelaxation.hpp"

namespace fsi::coupler {

void AitkenRelaxation::next(const Eigen::VectorXd &x, const Eigen::VectorXd &x_tilde, Eigen::VectorXd &out) {
  r_ = x_tilde - x;
  if (iteration_ == 0) {
    omega_ = initial_;
  } else {
    const Eigen::VectorXd dr = r_ - r_prev_;
    const double dr2 = dr.squaredNorm();
    if (dr2 > 0.0)
      omega_ = -omega_ * r_prev_.dot(dr) / dr2;
  }
  out = x + omega_ * r_;
  r_prev_.swap(r_);
  ++iteration_;
}

} // namespace fsi::coupler
