#pragma once
// The work the blades can put into the water at a flow rate: the velocity triangle at the
// impeller's outlet with the slip factor of Wiesner (1967; Gülich, Centrifugal Pumps, 3rd ed.,
// Table 3.3): sigma = 1 - sqrt(sin beta_2B) / z^0.7, c_u2 = u2 (sigma - c_2m cot beta_2B /
// u2), c_2m = Q / (pi D2 b2 tau2) with the blades' blockage tau2 = 1 - z t / (pi D2 sin beta_2B);
// no pre-swirl at the inlet, so the Euler head is H_E = u2 c_u2 / g and the torque rho Q r2 c_u2.
// The design rules' head (DutyEstimate, Gülich's psi_opt) assumes the 5-7 blades of a normal
// impeller; with one blade the relative eddy takes most of the swirl, and this says how much:
// a check of the blade count against the duty, not a prediction (Wiesner's fit is for z >= 3).

namespace fsi::pump {

struct PumpDesign;

struct BladeOutlet {
  double slip_factor = 0.0;            ///< sigma (Wiesner)
  double blockage = 0.0;               ///< tau2, the open fraction of the outlet circumference
  double meridional_m_per_s = 0.0;     ///< c_2m
  double swirl_m_per_s = 0.0;          ///< c_u2
  double euler_head_m = 0.0;           ///< u2 c_u2 / g
  double torque_n_m = 0.0;             ///< rho Q r2 c_u2 (water)
};

/// The blade outlet of `design` at the flow rate Q (m^3/s).
BladeOutlet blade_outlet_at(const PumpDesign &design, double flow_rate_m3_per_s);

} // namespace fsi::pump
