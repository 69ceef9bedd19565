#include "ChannelLayout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::pump {
namespace {

constexpr double deg = M_PI / 180.0;
/// The floor falls from the cover back to the shroud over this angle.
constexpr double floor_fall_rad = 30.0 * deg;

std::string fixed(double value, int digits = 4) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

} // namespace

ChannelLayout::ChannelLayout(const PumpDesign &design) {
  const auto &imp = design.impeller;
  if (!imp.single_channel)
    throw std::invalid_argument("the impeller has no single_channel section");
  const auto &sc = *imp.single_channel;
  r2_ = 0.5 * imp.outer_diameter_m;
  b2_ = imp.outlet_width_m;
  r_eye_ = 0.5 * imp.eye_diameter_m;
  r_boss_ = 0.5 * imp.hub_diameter_m;
  wrap_ = imp.wrap_angle_deg * deg;
  phi_m_ = sc.mouth_angle_deg * deg;
  tan_beta2_ = std::tan(imp.outlet_blade_angle_deg * deg);
  w1_ = sc.inlet_width_m;
  w2_ = sc.exit_width_m;
  cover_ = sc.eye_cover_thickness_m;
  drop_ = 0.5 * sc.disc_thickness_m;
  roof0_ = sc.mouth_roof_height_m.value_or(b2_ + drop_);
  if (r_boss_ <= 0.0)
    throw std::invalid_argument("hub_diameter_m = 0: a single-channel impeller needs a boss (the leading edge runs "
                                "from it to the eye's rim)");
  if (r_boss_ + w1_ <= r_eye_)
    throw std::invalid_argument("single_channel.inlet_width_m = " + fixed(w1_) +
                                " does not reach the eye's rim from the boss (eye_diameter_m / 2 - hub_diameter_m / 2 = " +
                                fixed(r_eye_ - r_boss_) + "): the mouth would not span the eye");
  if (r_boss_ + w1_ > r2_ - sc.disc_thickness_m)
    throw std::invalid_argument("single_channel.inlet_width_m = " + fixed(w1_) +
                                " takes the mouth out to D2 (the boss's radius plus it must stay a disc's thickness "
                                "inside outer_diameter_m / 2 = " + fixed(r2_) + ")");
  if (2.0 * imp.leading_edge_radius_m >= r_eye_ - r_boss_)
    throw std::invalid_argument("leading_edge_radius_m = " + fixed(imp.leading_edge_radius_m) +
                                " leaves no leading edge between the boss and the eye's rim (" +
                                fixed(r_eye_ - r_boss_) + " m apart)");
  if (sc.mouth_roof_height_m && !(drop_ < roof0_ && roof0_ < b2_))
    throw std::invalid_argument("single_channel.mouth_roof_height_m = " + fixed(roof0_) +
                                " must lie between the channel's floor in the mouth (" + fixed(-drop_) +
                                " m) and the hub disc (outlet_width_m = " + fixed(b2_) + ")");
  if (cover_ + drop_ >= b2_)
    throw std::invalid_argument("single_channel.eye_cover_thickness_m = " + fixed(cover_) +
                                " leaves no channel under the hub disc (outlet_width_m = " + fixed(b2_) + ")");
  const double r_mean = 0.5 * (r_boss_ + r_eye_);
  const double ramp = (cover_ + drop_) / (r_mean * std::tan(imp.inlet_blade_angle_deg * deg));
  phi_a_ = phi_m_ + ramp;
  phi_le_ = phi_m_ + ramp * drop_ / (cover_ + drop_);
  if (phi_a_ + 30.0 * deg >= wrap_)
    throw std::invalid_argument("the mouth (single_channel.mouth_angle_deg = " + fixed(sc.mouth_angle_deg) +
                                ") and the leading edge's ramp (" + fixed(ramp / deg) +
                                " deg at inlet_blade_angle_deg) leave less than 30 deg of the wrap_angle_deg = " +
                                fixed(imp.wrap_angle_deg) + " for the spiral");
  // The inner wall's cubic leaves the boss tangentially and reaches D2 at beta_2: monotonic
  // (Fritsch-Carlson, one end slope 0) while its end slope is at most 3 times the mean slope.
  const double end_slope = r2_ * tan_beta2_ * (wrap_ - phi_a_);
  if (end_slope > 3.0 * (r2_ - r_boss_))
    throw std::invalid_argument("outlet_blade_angle_deg = " + fixed(imp.outlet_blade_angle_deg) +
                                " is too steep for the spiral's " + fixed((wrap_ - phi_a_) / deg) +
                                " deg from the boss to D2: the channel's inner wall would fold back (at most " +
                                fixed(std::atan(3.0 * (r2_ - r_boss_) / (r2_ * (wrap_ - phi_a_))) / deg) + " deg)");
  phi_x_ = wrap_ + std::max(0.003 / (r2_ * tan_beta2_), 2.0 * deg);
  // The cover ends once the inner wall is past the eye's rim (bisection: the wall is monotonic).
  const double past = r_eye_ + 0.5 * cover_;
  if (inner_radius(wrap_ - floor_fall_rad) < past)
    throw std::invalid_argument("the channel's inner wall reaches the eye's rim too late to let its floor fall back "
                                "to the shroud before the exit (a steeper outlet angle bends the wall's end inwards): lower "
                                "outlet_blade_angle_deg, mouth_angle_deg or single_channel.eye_cover_thickness_m, or "
                                "raise inlet_blade_angle_deg or wrap_angle_deg");
  double lo = phi_a_, hi = wrap_ - floor_fall_rad;
  for (int i = 0; i < 60; ++i)
    (inner_radius(0.5 * (lo + hi)) < past ? lo : hi) = 0.5 * (lo + hi);
  phi_r_ = hi;
  // Where the spiral comes round onto an earlier part of itself (its mouth, or a turn before),
  // the vane between them must be at least a disc thick.
  const int n = 240;
  for (int i = 0; i <= n; ++i) {
    const double late = phi_x_ * i / n;
    for (int j = 0; j <= n; ++j) {
      const double early = phi_x_ * j / n;
      if (late - early <= M_PI)
        continue;
      const ChannelSection a = section(early), b = section(late);
      const double lo_r = std::max(a.inner_radius_m, b.inner_radius_m);
      const double hi_r = std::min({a.outer_radius_m, b.outer_radius_m, r2_});
      if (hi_r > lo_r && (2.0 * M_PI - (late - early)) * lo_r < sc.disc_thickness_m)
        throw std::invalid_argument("the channel comes round onto itself: at " + fixed(late / deg) +
                                    " deg along the wrap it passes " + fixed(early / deg) + " deg behind, with " +
                                    fixed(std::max(0.0, 2.0 * M_PI - (late - early)) * lo_r) +
                                    " m of vane between them: lower wrap_angle_deg or single_channel.inlet_width_m");
    }
  }
}

double ChannelLayout::inner_radius(double phi) const {
  if (phi <= phi_a_)
    return r_boss_;
  const double slope = r2_ * tan_beta2_;
  if (phi >= wrap_)
    return r2_ + slope * (phi - wrap_);
  const double length = wrap_ - phi_a_, x = (phi - phi_a_) / length;
  const double h01 = x * x * (3.0 - 2.0 * x), h11 = x * x * (x - 1.0);
  return r_boss_ + (r2_ - r_boss_) * h01 + slope * length * h11;
}

double ChannelLayout::width(double phi) const {
  if (phi <= phi_a_)
    return w1_;
  if (phi >= wrap_)
    return w2_;
  return w1_ + (w2_ - w1_) * (phi - phi_a_) / (wrap_ - phi_a_);
}

double ChannelLayout::floor_z(double phi) const {
  if (phi <= phi_m_)
    return -drop_;
  if (phi <= phi_a_)
    return -drop_ + (cover_ + drop_) * (phi - phi_m_) / (phi_a_ - phi_m_);
  if (phi <= phi_r_)
    return cover_;
  if (phi <= phi_r_ + floor_fall_rad)
    return cover_ - (cover_ + drop_) * (phi - phi_r_) / floor_fall_rad;
  return -drop_;
}

double ChannelLayout::top_z(double phi) const {
  if (phi >= phi_m_)
    return b2_ + drop_;
  return roof0_ + (b2_ + drop_ - roof0_) * phi / phi_m_;
}

double ChannelLayout::mouth_roof_angle_deg() const {
  const double r_mean = 0.5 * (r_boss_ + r_eye_);
  return std::atan((b2_ + drop_ - roof0_) / (r_mean * phi_m_)) / deg;
}

ChannelSection ChannelLayout::section(double phi) const {
  ChannelSection s;
  s.phi_rad = phi;
  s.inner_radius_m = inner_radius(phi);
  s.outer_radius_m = s.inner_radius_m + width(phi);
  s.floor_z_m = floor_z(phi);
  s.top_z_m = top_z(phi);
  return s;
}

std::vector<ChannelSection> ChannelLayout::loft_sections(double max_step_rad) const {
  // The kinks of the floor and the wall are sections; the spans between are split evenly.
  const std::vector<double> knots{0.0, phi_m_, phi_a_, phi_r_, phi_r_ + floor_fall_rad, wrap_, phi_x_};
  std::vector<ChannelSection> sections{section(0.0)};
  for (std::size_t k = 1; k < knots.size(); ++k) {
    if (knots[k] - knots[k - 1] < 1e-6)
      continue;
    const int n = std::max(1, static_cast<int>(std::ceil((knots[k] - knots[k - 1]) / max_step_rad)));
    for (int i = 1; i <= n; ++i)
      sections.push_back(section(knots[k - 1] + (knots[k] - knots[k - 1]) * i / n));
  }
  return sections;
}

double ChannelLayout::exit_area_m2() const { return w2_ * b2_ * std::cos(std::atan(tan_beta2_)); }

double ChannelLayout::smallest_section_side_m() const {
  double smallest = 1e300;
  for (int i = 0; i <= 400; ++i) {
    const ChannelSection s = section(phi_a_ + (wrap_ - phi_a_) * i / 400.0);
    smallest = std::min({smallest, s.outer_radius_m - s.inner_radius_m,
                         std::min(s.top_z_m, b2_) - std::max(s.floor_z_m, 0.0)});
  }
  return smallest;
}

} // namespace fsi::pump
