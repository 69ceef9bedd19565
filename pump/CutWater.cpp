#include "CutWater.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::pump {
namespace {

Eigen::Vector2d wall(const std::function<double(double)> &outer_radius, double phi) {
  return outer_radius(phi) * Eigen::Vector2d(std::sin(phi), std::cos(phi));
}

/// The wall angle in [0, pi/2] nearest a point: a scan, then a golden-section refinement.
double nearest_phi(const std::function<double(double)> &outer_radius, const Eigen::Vector2d &point) {
  auto distance = [&](double phi) { return (wall(outer_radius, phi) - point).norm(); };
  const int n = 900;
  double best = 0.0;
  for (int i = 0; i <= n; ++i)
    if (distance(0.5 * M_PI * i / n) < distance(best))
      best = 0.5 * M_PI * i / n;
  double lo = std::max(0.0, best - 0.5 * M_PI / n), hi = std::min(0.5 * M_PI, best + 0.5 * M_PI / n);
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 60; ++i) {
    const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
    if (distance(a) < distance(b))
      hi = b;
    else
      lo = a;
  }
  return 0.5 * (lo + hi);
}

} // namespace

CutWater place_cut_water(const std::function<double(double)> &outer_radius, double inner_wall_v_m, double nose_radius_m,
                         double tangent_fraction) {
  CutWater cut;
  cut.nose_radius_m = nose_radius_m;
  // The crossing: the wall starts above the line (outside the base circle) and falls below it.
  double lo = 1e-9, hi = 0.5 * M_PI;
  if (wall(outer_radius, hi)[1] >= inner_wall_v_m || wall(outer_radius, lo)[1] <= inner_wall_v_m)
    throw std::invalid_argument("the spiral's outer wall does not cross the discharge duct's inner wall within "
                                "a quarter turn of the cut-water");
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (wall(outer_radius, mid)[1] > inner_wall_v_m)
      lo = mid;
    else
      hi = mid;
  }
  cut.crossing_m = wall(outer_radius, lo);
  // The nose centre runs along v = v_w - rho (rho = tangent_fraction r_n) until its distance to
  // the wall is rho: there the tongue is 2 rho thick.
  const double rho = tangent_fraction * nose_radius_m;
  auto gap = [&](double u) {
    const Eigen::Vector2d c(u, inner_wall_v_m - rho);
    return (wall(outer_radius, nearest_phi(outer_radius, c)) - c).norm() - rho;
  };
  double u_lo = cut.crossing_m[0], u_hi = u_lo;
  for (int i = 0; gap(u_hi) < 0.0; ++i) {
    u_hi += 2.0 * nose_radius_m;
    if (i > 1000)
      throw std::invalid_argument("the tongue between the spiral and the discharge never gets two nose radii thick");
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (u_lo + u_hi);
    if (gap(mid) < 0.0)
      u_lo = mid;
    else
      u_hi = mid;
  }
  cut.nose_centre_m = Eigen::Vector2d(u_hi, inner_wall_v_m - rho);
  cut.wall_contact_phi_rad = nearest_phi(outer_radius, cut.nose_centre_m);
  cut.wall_contact_m = wall(outer_radius, cut.wall_contact_phi_rad);
  return cut;
}

} // namespace fsi::pump
