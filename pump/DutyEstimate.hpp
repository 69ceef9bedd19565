#pragma once
// The best efficiency point a radial impeller of diameter D2 turning at omega is expected to
// reach at a specific speed n_q, from the standard design fit of the head coefficient
// (Gülich, Centrifugal Pumps, 3rd ed., Table 3.3: psi_opt = 1.21 exp(-0.77 n_q / n_q,Ref),
// n_q,Ref = 100, with psi = 2 g H / u2^2). Plausibility bands, not targets: a single blade does
// not follow multi-blade slip theory. n_q = N sqrt(Q) / H^0.75 with N in rpm, Q in m^3/s, H in
// m (the paper's n_s).

namespace fsi::pump {

struct DutyEstimate {
  double specific_speed = 0.0;        ///< n_q (rpm, m^3/s, m)
  double tip_speed_m_per_s = 0.0;     ///< u2 = omega D2 / 2
  double head_m = 0.0;                ///< H at the BEP
  double flow_rate_m3_per_s = 0.0;    ///< Q at the BEP
  double head_coefficient = 0.0;      ///< psi = g H / u2^2 (half of Gülich's)
  double flow_coefficient = 0.0;      ///< phi = Q / (omega R2^3)
  double hydraulic_power_w = 0.0;     ///< rho g Q H (water, rho = 1000 kg/m^3)

  /// Shaft torque (N m) at an overall efficiency eta: rho g Q H / (eta omega).
  double torque_n_m(double efficiency, double omega_rad_per_s) const {
    return hydraulic_power_w / (efficiency * omega_rad_per_s);
  }
};

/// Gülich's psi_opt(n_q) = 2 g H / u2^2 of a radial pump (f_T = 1).
double gulich_head_coefficient(double specific_speed);

/// The duty of an impeller of outer diameter D2 at omega and specific speed n_q.
DutyEstimate estimate_duty(double omega_rad_per_s, double outer_diameter_m, double specific_speed);

/// The duty at a given flow rate Q: the n_q at which Gülich's head and Q are consistent
/// (n_q = N sqrt(Q) / H(n_q)^0.75, one root, found by bisection over 5 < n_q < 300).
DutyEstimate estimate_duty_for_flow(double omega_rad_per_s, double outer_diameter_m, double flow_rate_m3_per_s);

/// n_q = N sqrt(Q) / H^0.75 (N = omega 60 / 2 pi in rpm).
double specific_speed(double omega_rad_per_s, double flow_rate_m3_per_s, double head_m);

} // namespace fsi::pump
