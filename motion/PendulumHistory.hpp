#pragma once
// Angle history of a free simple pendulum released from rest:
//   theta'' = -(g / L) sin(theta),  theta(0) = theta_0,  theta'(0) = 0.
// Integrated with classical RK4 on a fine fixed step and extended on demand; between stored
// samples the angle is a cubic Hermite interpolant (uses theta and theta').

#include <vector>

namespace fsi::motion {

class PendulumHistory {
public:
  PendulumHistory(double gravity_m_per_s2, double length_m, double initial_angle_rad);

  double angle_rad(double time_s) const;
  double rate_rad_per_s(double time_s) const;
  /// Small-amplitude period 2 pi sqrt(L/g), for messages and tests.
  double linear_period_s() const;

private:
  void extend_to(double time_s) const;

  double omega_squared_;
  double step_s_;
  mutable std::vector<double> angle_;
  mutable std::vector<double> rate_;
};

} // namespace fsi::motion
