#include "BladeCamber.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::pump {
namespace {

/// The integrals int_0^1 x^k / (a + x) dx for k = 0, 1, 2 (a = r1 / (r2 - r1)), up to x.
struct Moments {
  double i0, i1, i2;
};

Moments moments(double a, double x) {
  const double log_term = std::log((a + x) / a);
  return {log_term, x - a * log_term, 0.5 * x * x - a * x + a * a * log_term};
}

} // namespace

BladeCamber::BladeCamber(double inlet_radius_m, double outlet_radius_m, double inlet_angle_rad, double outlet_angle_rad,
                         double wrap_angle_rad, double rotation_sense)
    : r1_(inlet_radius_m), r2_(outlet_radius_m), cot1_(1.0 / std::tan(inlet_angle_rad)),
      cot2_(std::cos(outlet_angle_rad) / std::sin(outlet_angle_rad)), c_(0.0), s_(rotation_sense > 0 ? 1.0 : -1.0) {
  if (!(r1_ > 0.0 && r2_ > r1_))
    throw std::invalid_argument("BladeCamber: the blade inlet radius must be positive and below the outlet radius");
  // wrap = cot1 I0 + (cot2 - cot1) I1 + c (I1 - I2): linear in c.
  const Moments m = moments(r1_ / (r2_ - r1_), 1.0);
  c_ = (wrap_angle_rad - cot1_ * m.i0 - (cot2_ - cot1_) * m.i1) / (m.i1 - m.i2);
  // cot beta = A + B x - c x^2: for c < 0 it opens upwards and may dip below both ends at its
  // vertex; otherwise its smallest value on [0, 1] is at an end. beta = 90 deg where cot beta = 0
  // is refused inside the blade (a radial outlet, outlet_blade_angle_deg = 90, is allowed).
  double lowest = std::min(cot1_, cot2_);
  const double vertex = c_ < 0.0 ? 0.5 * (1.0 + (cot2_ - cot1_) / c_) : -1.0;
  if (vertex > 0.0 && vertex < 1.0)
    lowest = std::min(lowest, cot_beta(r1_ + vertex * (r2_ - r1_)));
  const bool outlet_radial_only = lowest == cot2_ && std::abs(cot2_) <= 1e-12;
  if (lowest <= 1e-12 && !outlet_radial_only)
    throw std::invalid_argument(
        "the blade cannot reach impeller.wrap_angle_deg = " + std::to_string(wrap_angle_rad * 180.0 / M_PI) +
        " deg from impeller.inlet_blade_angle_deg to impeller.outlet_blade_angle_deg between the radii "
        "impeller.blade_inlet_diameter_m / 2 and impeller.outer_diameter_m / 2 with a blade angle inside "
        "(0, 90) deg (it would need beta = " +
        std::to_string(std::atan2(1.0, lowest) * 180.0 / M_PI) +
        " deg); raise the wrap angle or the blade angles (steeper blades wrap less)");
}

double BladeCamber::cot_beta(double radius_m) const {
  const double x = (radius_m - r1_) / (r2_ - r1_);
  return cot1_ + (cot2_ - cot1_) * x + c_ * x * (1.0 - x);
}

double BladeCamber::beta_rad(double radius_m) const { return std::atan2(1.0, cot_beta(radius_m)); }

double BladeCamber::unwrapped_angle_rad(double radius_m) const {
  // cot beta = A + B x + C x^2 with A = cot1, B = cot2 - cot1 + c, C = -c.
  const Moments m = moments(r1_ / (r2_ - r1_), (radius_m - r1_) / (r2_ - r1_));
  return cot1_ * m.i0 + (cot2_ - cot1_ + c_) * m.i1 - c_ * m.i2;
}

double BladeCamber::theta_rad(double radius_m) const { return -s_ * unwrapped_angle_rad(radius_m); }

} // namespace fsi::pump
