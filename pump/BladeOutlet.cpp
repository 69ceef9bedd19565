#include "BladeOutlet.hpp"

#include "PhysicalConstants.hpp"
#include "PumpDesign.hpp"

#include <cmath>

namespace fsi::pump {

BladeOutlet blade_outlet_at(const PumpDesign &design, double flow_rate_m3_per_s) {
  const auto &i = design.impeller;
  const double beta = i.outlet_blade_angle_deg * M_PI / 180.0, z = i.n_blades, d2 = i.outer_diameter_m;
  const double u2 = design.operation.rotation_rate_rad_per_s * 0.5 * d2;
  BladeOutlet out;
  out.slip_factor = 1.0 - std::sqrt(std::sin(beta)) / std::pow(z, 0.7);
  out.blockage = 1.0 - z * i.blade_thickness_m / (M_PI * d2 * std::sin(beta));
  out.meridional_m_per_s = flow_rate_m3_per_s / (M_PI * d2 * i.outlet_width_m * out.blockage);
  out.swirl_m_per_s = u2 * out.slip_factor - out.meridional_m_per_s * std::cos(beta) / std::sin(beta);
  out.euler_head_m = u2 * out.swirl_m_per_s / g_m_per_s2;
  out.torque_n_m = water_kg_per_m3 * flow_rate_m3_per_s * 0.5 * d2 * out.swirl_m_per_s;
  return out;
}

} // namespace fsi::pump
