#include "VoluteSizing.hpp"

#include "DutyEstimate.hpp"
#include "PhysicalConstants.hpp"
#include "PumpDesign.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::pump {
VoluteSizing::VoluteSizing(double flow_rate_m3_per_s, double head_m, double hydraulic_efficiency,
                           double tip_speed_m_per_s, double impeller_radius_m, double base_radius_m,
                           double base_width_m, double flank_angle_rad)
    : q_(flow_rate_m3_per_s), k_(g_m_per_s2 * head_m / (hydraulic_efficiency * tip_speed_m_per_s) * impeller_radius_m),
      r3_(base_radius_m), b3_(base_width_m), tan_alpha_(std::tan(flank_angle_rad)) {
  if (!(q_ > 0.0 && k_ > 0.0 && r3_ > 0.0 && b3_ > 0.0 && tan_alpha_ >= 0.0))
    throw std::invalid_argument("VoluteSizing: flow rate, head, speeds and the section must be positive");
}

VoluteSizing VoluteSizing::for_swirl(double flow_rate_m3_per_s, double angular_momentum_m2_per_s,
                                     double base_radius_m, double base_width_m, double flank_angle_rad) {
  // k = g H / (eta_h u2) r2: with eta_h = 1, u2 = g and r2 = 1, H is k itself.
  return VoluteSizing(flow_rate_m3_per_s, angular_momentum_m2_per_s, 1.0, g_m_per_s2, 1.0, base_radius_m, base_width_m,
                      flank_angle_rad);
}

double VoluteSizing::section_flow_m3_per_s(double outer_radius_m) const {
  // k int_{r3}^{ro} (b3 + 2 (r - r3) t) / r dr = k [(b3 - 2 r3 t) ln(ro / r3) + 2 t (ro - r3)]
  return k_ *
         ((b3_ - 2.0 * r3_ * tan_alpha_) * std::log(outer_radius_m / r3_) + 2.0 * tan_alpha_ * (outer_radius_m - r3_));
}

double VoluteSizing::outer_radius_m(double theta_rad) const {
  const double wanted = q_ * theta_rad / (2.0 * M_PI);
  double ro = r3_ * std::exp(wanted / (k_ * b3_)); // the rectangular answer: exact when alpha = 0
  if (tan_alpha_ == 0.0)
    return ro;
  for (int i = 0; i < 50; ++i) { // Newton on a convex, increasing function of ro
    const double f = section_flow_m3_per_s(ro) - wanted;
    const double df = k_ * width_m(ro) / ro;
    const double step = f / df;
    ro -= step;
    if (std::abs(step) < 1e-15 * ro)
      break;
  }
  return ro;
}

double VoluteSizing::section_area_m2(double theta_rad) const {
  const double h = outer_radius_m(theta_rad) - r3_; // int_{r3}^{ro} b(r) dr
  return b3_ * h + tan_alpha_ * h * h;
}

double VoluteSizing::throat_area_m2() const { return section_area_m2(2.0 * M_PI); }

VoluteSizing size_volute(const PumpDesign &design) {
  const auto &op = design.operation;
  const auto &vol = design.volute;
  const double d2 = design.impeller.outer_diameter_m;
  if (op.design_swirl_m2_per_s > 0.0)
    return VoluteSizing::for_swirl(op.design_flow_rate_m3_per_s, op.design_swirl_m2_per_s, vol.base_radius_m,
                                   vol.base_width_m, vol.flank_angle_deg * M_PI / 180.0);
  const DutyEstimate duty = estimate_duty_for_flow(op.rotation_rate_rad_per_s, d2, op.design_flow_rate_m3_per_s);
  return VoluteSizing(op.design_flow_rate_m3_per_s, duty.head_m, op.hydraulic_efficiency, duty.tip_speed_m_per_s,
                      0.5 * d2, vol.base_radius_m, vol.base_width_m, vol.flank_angle_deg * M_PI / 180.0);
}

ThroatBand throat_band(double flow_rate_m3_per_s, double head_m) {
  if (!(flow_rate_m3_per_s > 0.0 && head_m > 0.0))
    throw std::invalid_argument("throat_band: the flow rate and the head must be positive");
  const double jet = std::sqrt(2.0 * g_m_per_s2 * head_m);
  ThroatBand band;
  band.min_area_m2 = flow_rate_m3_per_s / (ThroatBand::max_velocity_ratio * jet);
  band.max_area_m2 = flow_rate_m3_per_s / (ThroatBand::min_velocity_ratio * jet);
  return band;
}

ThroatBand throat_band(const PumpDesign &design) {
  const auto &op = design.operation;
  if (op.design_swirl_m2_per_s > 0.0)
    return throat_band(op.design_flow_rate_m3_per_s,
                       op.hydraulic_efficiency * op.rotation_rate_rad_per_s * op.design_swirl_m2_per_s / g_m_per_s2);
  const DutyEstimate duty =
      estimate_duty_for_flow(op.rotation_rate_rad_per_s, design.impeller.outer_diameter_m, op.design_flow_rate_m3_per_s);
  return throat_band(op.design_flow_rate_m3_per_s, duty.head_m);
}

} // namespace fsi::pump
