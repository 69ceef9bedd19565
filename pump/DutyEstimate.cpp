#include "DutyEstimate.hpp"

#include "PhysicalConstants.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::pump {
double gulich_head_coefficient(double specific_speed) { return 1.21 * std::exp(-0.77 * specific_speed / 100.0); }

double specific_speed(double omega_rad_per_s, double flow_rate_m3_per_s, double head_m) {
  return rpm(omega_rad_per_s) * std::sqrt(flow_rate_m3_per_s) / std::pow(head_m, 0.75);
}

DutyEstimate estimate_duty(double omega_rad_per_s, double outer_diameter_m, double specific_speed) {
  DutyEstimate d;
  d.specific_speed = specific_speed;
  const double r2 = 0.5 * outer_diameter_m;
  d.tip_speed_m_per_s = omega_rad_per_s * r2;
  d.head_m = gulich_head_coefficient(specific_speed) * d.tip_speed_m_per_s * d.tip_speed_m_per_s / (2.0 * g_m_per_s2);
  // n_q = N sqrt(Q) / H^0.75  =>  Q = (n_q H^0.75 / N)^2
  const double root_q = specific_speed * std::pow(d.head_m, 0.75) / rpm(omega_rad_per_s);
  d.flow_rate_m3_per_s = root_q * root_q;
  d.head_coefficient = g_m_per_s2 * d.head_m / (d.tip_speed_m_per_s * d.tip_speed_m_per_s);
  d.flow_coefficient = d.flow_rate_m3_per_s / (omega_rad_per_s * r2 * r2 * r2);
  d.hydraulic_power_w = water_kg_per_m3 * g_m_per_s2 * d.flow_rate_m3_per_s * d.head_m;
  return d;
}

DutyEstimate estimate_duty_for_flow(double omega_rad_per_s, double outer_diameter_m, double flow_rate_m3_per_s) {
  // f(n_q) = n_q - N sqrt(Q) / H(n_q)^0.75 rises with n_q (H falls): one sign change.
  const auto f = [&](double nq) {
    return nq - specific_speed(omega_rad_per_s, flow_rate_m3_per_s, estimate_duty(omega_rad_per_s, outer_diameter_m, nq).head_m);
  };
  double lo = 5.0, hi = 300.0;
  if (f(lo) > 0.0 || f(hi) < 0.0)
    throw std::invalid_argument("no radial-pump specific speed between 5 and 300 gives Q = " +
                                std::to_string(flow_rate_m3_per_s) + " m^3/s at this diameter and speed");
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  DutyEstimate d = estimate_duty(omega_rad_per_s, outer_diameter_m, 0.5 * (lo + hi));
  return d;
}

} // namespace fsi::pump
