#include "StabilizedTension.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::structure {

StabilizedTension::StabilizedTension(const StepSettings &settings)
    : system_(settings), bound_(system_.matrix()) {
  const ElasticTerms &terms = settings.terms;
  double max_inv_ds_squared = 0.0;
  for (const auto &t : terms.tension())
    max_inv_ds_squared = std::max(max_inv_ds_squared, t.inv_ds_squared);
  if (max_inv_ds_squared > 0.0)
    min_spacing_m_ = 1.0 / std::sqrt(max_inv_ds_squared);
  constexpr double beta = 1.5; // explicit remainder at Delta s / dt = 1.5 x its wave speed
  stabilization_speed_m_per_s_ = beta * std::sqrt(2.0 * terms.tension_coefficient() / settings.mass_per_measure);
}

int StabilizedTension::solve(const StepInputs &in, PointArray &x_next) {
  const double dt = in.dt_s;
  system_.fill_values(*in.x_now, dt);
  fill_bound(*in.x_now, dt);
  PointArray rhs;
  system_.add_inertia_and_loads(in, rhs);
  // + dt^2 S X*, X* = 2 X^n - X^{n-1}: the bound acts on X^{n+1} - X* only
  rhs += dt * dt * (bound_ * (2.0 * *in.x_now - *in.x_prev));
  system_.subtract_bending_constants(in, rhs);
  return system_.solve(in, rhs, x_next);
}

void StabilizedTension::fill_bound(const PointArray &x, double dt) {
  // A += dt^2 f S(x), on top of the frozen-tension matrix.
  const double r = min_spacing_m_ / (stabilization_speed_m_per_s_ * dt);
  const double f = std::max(0.0, 1.0 - r * r);
  Eigen::Map<Eigen::VectorXd>(bound_.valuePtr(), bound_.nonZeros()).setZero();
  if (f > 0.0)
    add_stretching_bound(x, f, bound_.valuePtr());
  system_.matrix_values() += dt * dt * Eigen::Map<const Eigen::VectorXd>(bound_.valuePtr(), bound_.nonZeros());
}

void StabilizedTension::add_stretching_bound(const PointArray &x, double scale, double *values) const {
  // Material part of the tension Hessian and its isotropic bound (u: any displacement):
  //   edge, d = X_b - X_a:  (2 phi m / ds^4) (u_d . d)^2 <= (2 phi m T / ds^2) |u_d|^2, T = |d|^2 / ds^2;
  //   shear, T_12 = a . b:  phi m (u_a . b + u_b . a)^2 <= 2 phi m (|b|^2 |u_a|^2 + |a|^2 |u_b|^2),
  // u_d, u_a, u_b the stencils' differences of u: each bound is a scalar stencil times the 3x3
  // identity, so S shares the pattern (and the three coordinates) of the frozen-tension matrix.
  const StepSlots &s = system_.slots();
  const ElasticTerms &terms = system_.terms();
  const double phi = terms.tension_coefficient();
  for (std::size_t k = 0; k < s.tension.size(); ++k) {
    const auto &t = terms.tension()[k];
    const double stretch = (x.row(t.b) - x.row(t.a)).squaredNorm() * t.inv_ds_squared;
    const double v = scale * 2.0 * phi * t.measure * t.inv_ds_squared * stretch;
    values[s.tension[k][0]] += v, values[s.tension[k][1]] -= v, values[s.tension[k][2]] -= v;
    values[s.tension[k][3]] += v;
  }
  for (std::size_t k = 0; k < s.shear.size(); ++k) {
    const auto &t = terms.shear()[k];
    Vec3 a, b;
    t.tangents(x, a, b);
    const double wa = scale * 2.0 * phi * t.measure * b.squaredNorm(), wb = scale * 2.0 * phi * t.measure * a.squaredNorm();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        values[s.shear[k][4 * r + c]] += wa * t.coef_a[r] * t.coef_a[c] + wb * t.coef_b[r] * t.coef_b[c];
  }
}

} // namespace fsi::structure
