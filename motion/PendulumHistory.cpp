#include "PendulumHistory.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::motion {

PendulumHistory::PendulumHistory(double gravity_m_per_s2, double length_m, double initial_angle_rad)
    : omega_squared_(gravity_m_per_s2 / length_m), angle_{initial_angle_rad}, rate_{0.0} {
  if (!(gravity_m_per_s2 > 0.0) || !(length_m > 0.0))
    throw std::invalid_argument("pendulum needs gravity > 0 and length > 0");
  step_s_ = linear_period_s() / 4000.0; // RK4 error ~ (w dt)^4 ~ 1e-11 per period
}

double PendulumHistory::linear_period_s() const { return 2.0 * M_PI / std::sqrt(omega_squared_); }

void PendulumHistory::extend_to(double time_s) const {
  const auto needed = static_cast<std::size_t>(std::ceil(time_s / step_s_)) + 2;
  const auto acceleration = [this](double theta) { return -omega_squared_ * std::sin(theta); };
  while (angle_.size() < needed) {
    const double th = angle_.back(), w = rate_.back(), h = step_s_;
    const double k1t = w, k1w = acceleration(th);
    const double k2t = w + 0.5 * h * k1w, k2w = acceleration(th + 0.5 * h * k1t);
    const double k3t = w + 0.5 * h * k2w, k3w = acceleration(th + 0.5 * h * k2t);
    const double k4t = w + h * k3w, k4w = acceleration(th + h * k3t);
    angle_.push_back(th + h / 6.0 * (k1t + 2 * k2t + 2 * k3t + k4t));
    rate_.push_back(w + h / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w));
  }
}

double PendulumHistory::angle_rad(double time_s) const {
  if (time_s <= 0.0)
    return angle_.front();
  extend_to(time_s);
  const auto i = static_cast<std::size_t>(time_s / step_s_);
  const double h = step_s_, s = time_s / h - static_cast<double>(i);
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * angle_[i] + h10 * h * rate_[i] + h01 * angle_[i + 1] + h11 * h * rate_[i + 1];
}

double PendulumHistory::rate_rad_per_s(double time_s) const {
  if (time_s <= 0.0)
    return 0.0;
  extend_to(time_s);
  const auto i = static_cast<std::size_t>(time_s / step_s_);
  const double s = time_s / step_s_ - static_cast<double>(i);
  return (1 - s) * rate_[i] + s * rate_[i + 1];
}

} // namespace fsi::motion
