#include "BladeInlet.hpp"

#include "PumpDesign.hpp"

#include <cmath>

namespace fsi::pump {

BladeInlet blade_inlet_at(const PumpDesign &design, double flow_rate_m3_per_s) {
  const auto &i = design.impeller;
  const double deg = M_PI / 180.0, beta_blade = i.inlet_blade_angle_deg * deg;
  BladeInlet in;
  in.radius_m = 0.5 * i.blade_inlet_diameter_m;
  in.blade_height_m = i.outlet_width_m;
  in.blade_speed_m_per_s = design.operation.rotation_rate_rad_per_s * in.radius_m;
  const double circle = 2.0 * M_PI * in.radius_m * in.blade_height_m;
  in.meridional_m_per_s = flow_rate_m3_per_s / circle;
  in.flow_angle_deg = std::atan2(in.meridional_m_per_s, in.blade_speed_m_per_s) / deg;
  in.incidence_deg = i.inlet_blade_angle_deg - in.flow_angle_deg;
  in.throat_area_m2 = circle * std::sin(beta_blade);
  in.throat_velocity_m_per_s = flow_rate_m3_per_s / in.throat_area_m2;
  in.shockless_flow_rate_m3_per_s = circle * in.blade_speed_m_per_s * std::tan(beta_blade);
  return in;
}

} // namespace fsi::pump
