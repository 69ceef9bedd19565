#include "BladeProfile.hpp"

#include <cmath>

namespace fsi::pump {
namespace {

double camber_theta(const BladeCamber &camber, double radius_m) {
  const double r2 = camber.outlet_radius_m();
  if (radius_m <= r2)
    return camber.theta_rad(radius_m);
  return camber.theta_rad(r2) - camber.rotation_sense() * camber.cot_beta(r2) * std::log(radius_m / r2);
}

/// d(x, y)/dr of the camber line, normalised: e_r + r dtheta/dr e_theta.
Eigen::Vector2d camber_tangent(const BladeCamber &camber, double theta_rad, double radius_m) {
  const double cot = camber.cot_beta(std::min(radius_m, camber.outlet_radius_m()));
  const Eigen::Vector2d e_r(std::cos(theta_rad), std::sin(theta_rad)),
      e_theta(-std::sin(theta_rad), std::cos(theta_rad));
  return (e_r - camber.rotation_sense() * cot * e_theta).normalized();
}

} // namespace

Eigen::Vector2d camber_point(const BladeCamber &camber, double theta0_rad, double radius_m) {
  const double theta = theta0_rad + camber_theta(camber, radius_m);
  return radius_m * Eigen::Vector2d(std::cos(theta), std::sin(theta));
}

BladeProfile make_blade_profile(const BladeCamber &camber, double theta0_rad, double thickness_m, double overshoot_m,
                                int n_samples) {
  const double r1 = camber.inlet_radius_m(), r2 = camber.outlet_radius_m();
  std::vector<double> radii;
  for (int i = 0; i <= n_samples; ++i) { // denser near the leading edge, where the camber bends most
    const double x = 0.5 * (1.0 - std::cos(M_PI * i / n_samples));
    radii.push_back(r1 + x * (r2 - r1));
  }
  BladeProfile profile;
  profile.n_inside = radii.size();
  for (const double extra : {0.5, 1.0})
    radii.push_back(r2 + extra * overshoot_m);
  for (const double r : radii) {
    const double theta = theta0_rad + camber_theta(camber, r);
    const Eigen::Vector2d p = camber_point(camber, theta0_rad, r);
    const Eigen::Vector2d tangent = camber_tangent(camber, theta, r);
    const Eigen::Vector2d normal(-tangent[1], tangent[0]);
    profile.camber_m.push_back(p);
    profile.left_m.push_back(p + 0.5 * thickness_m * normal);
    profile.right_m.push_back(p - 0.5 * thickness_m * normal);
  }
  profile.leading_edge_centre_m = profile.camber_m.front();
  profile.leading_edge_tip_m =
      profile.leading_edge_centre_m - 0.5 * thickness_m * camber_tangent(camber, theta0_rad, r1);
  return profile;
}

} // namespace fsi::pump
