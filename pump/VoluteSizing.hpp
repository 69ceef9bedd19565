#pragma once
// A spiral volute sized by the constant-angular-momentum rule: the swirl leaving the impeller,
// c_u2 = g H / (eta_h u2) (Euler's equation without inlet swirl), is carried on as a free
// vortex c_u r = c_u2 r2, and the section at angle theta from the cut-water passes the share
// theta / 2 pi of the flow:
//   Q theta / (2 pi) = int_{r3}^{r_o(theta)} c_u(r) b(r) dr = c_u2 r2 int_{r3}^{r_o} b(r) / r dr,
// with b(r) = b3 + 2 (r - r3) tan(alpha) (rectangular: alpha = 0, then r_o = r3 exp(...)).
// The throat is the section at theta = 2 pi, where the spiral meets the discharge.

namespace fsi::pump {

class VoluteSizing {
public:
  /// flow_rate: the design Q; head: H at it; swirl from eta_h; r2 = D2 / 2; r3, b3, alpha: the
  /// base radius, the width at it and the flank angle of the section.
  VoluteSizing(double flow_rate_m3_per_s, double head_m, double hydraulic_efficiency, double tip_speed_m_per_s,
               double impeller_radius_m, double base_radius_m, double base_width_m, double flank_angle_rad);
  /// The volute for a swirl c_u2 r2 given as such (measured: T / (rho Q) at the best point).
  static VoluteSizing for_swirl(double flow_rate_m3_per_s, double angular_momentum_m2_per_s, double base_radius_m,
                                double base_width_m, double flank_angle_rad);

  /// Angular momentum per unit mass of the free vortex, c_u2 r2 (m^2/s).
  double angular_momentum_m2_per_s() const { return k_; }
  /// Outer radius of the section at angle theta (rad, 0 at the cut-water, 2 pi at the throat).
  double outer_radius_m(double theta_rad) const;
  /// Area of the section at angle theta (m^2).
  double section_area_m2(double theta_rad) const;
  /// Area of the throat (theta = 2 pi).
  double throat_area_m2() const;
  /// Axial width of the section at radius r.
  double width_m(double radius_m) const { return b3_ + 2.0 * (radius_m - r3_) * tan_alpha_; }
  /// The flow a section carries, int c_u b dr with c_u = k / r (closed form).
  double section_flow_m3_per_s(double outer_radius_m) const;

private:
  double q_, k_, r3_, b3_, tan_alpha_;
};

struct PumpDesign;
/// The volute of a design: sized for the swirl its impeller leaves at the design flow rate,
/// operation.design_swirl_m2_per_s when given (measured), else the design rules' duty's.
VoluteSizing size_volute(const PumpDesign &design);

/// The design rules' band of the throat area for a duty, as a band of the volute velocity ratio
/// k3 = c3 / sqrt(2 g H) with c3 = Q / A_throat the throat's mean velocity: 0.30 <= k3 <= 0.43.
/// That is issue 11's 80-115 cm^2 for the paper's duty (Q = 45 L/s, H = 8.88 m: 79-114 cm^2)
/// said so that it holds for another flow rate and head (A = Q / (k3 sqrt(2 g H))).
struct ThroatBand {
  static constexpr double min_velocity_ratio = 0.30;
  static constexpr double max_velocity_ratio = 0.43;
  double min_area_m2 = 0.0, max_area_m2 = 0.0;
};
ThroatBand throat_band(double flow_rate_m3_per_s, double head_m);
/// The band for the duty of a design at its design flow rate: the head its given swirl makes,
/// eta_h omega c_u2 r2 / g, or else Gülich's head (DutyEstimate).
ThroatBand throat_band(const PumpDesign &design);

} // namespace fsi::pump
