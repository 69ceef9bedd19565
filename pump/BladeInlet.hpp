#pragma once
// The impeller's blade inlet at a flow rate: the velocity triangle at the leading-edge circle
// (radius r1 = blade_inlet_diameter_m / 2, blade height b1 = outlet_width_m: the channel is of
// constant width, no pre-swirl) against the blade angle, and the inlet throat of the channels.
// A design rule check (Gülich, ch. 7: incidence i = beta_1B - beta_1 of 0-6 deg at the BEP): a
// blade much flatter than the flow meets it at a large negative incidence and its throat
// chokes the flow; the flow rate of zero incidence says which duty the inlet is made for.

namespace fsi::pump {

struct PumpDesign;

struct BladeInlet {
  double radius_m = 0.0;            ///< r1
  double blade_height_m = 0.0;      ///< b1
  double blade_speed_m_per_s = 0.0; ///< u1 = omega r1
  double meridional_m_per_s = 0.0;  ///< c1m = Q / (2 pi r1 b1)
  double flow_angle_deg = 0.0;      ///< beta_1 = atan(c1m / u1), from the circumferential direction
  double incidence_deg = 0.0;       ///< i = beta_1B - beta_1
  double throat_area_m2 = 0.0;      ///< all channels: z (2 pi r1 / z) sin(beta_1B) b1
  double throat_velocity_m_per_s = 0.0;      ///< w1 = Q / throat area
  double shockless_flow_rate_m3_per_s = 0.0; ///< Q of zero incidence: 2 pi r1 b1 u1 tan(beta_1B)
};

/// The blade inlet of `design` at the flow rate Q (m^3/s).
BladeInlet blade_inlet_at(const PumpDesign &design, double flow_rate_m3_per_s);

} // namespace fsi::pump
