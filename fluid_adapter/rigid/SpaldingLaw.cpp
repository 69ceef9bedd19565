#include "fluid_adapter/rigid/SpaldingLaw.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fsi::fluid::rigid {

double SpaldingLaw::y_plus(double u_plus) const {
  const double k = kappa * u_plus;
  return u_plus + (std::exp(k) - 1.0 - k - 0.5 * k * k - k * k * k / 6.0) / e;
}

double SpaldingLaw::wall_shear_per_density(double speed, double distance, double nu) const {
  if (!(distance > 0.0) || !(nu > 0.0) || !(speed >= 0.0))
    throw std::invalid_argument("SpaldingLaw: needs y > 0, nu > 0 and U >= 0");
  if (speed == 0.0)
    return 0.0;
  const double re_y = speed * distance / nu;
  // F(u+) = Re_y / u+ - y+(u+) falls monotonically from +inf (u+ -> 0) and is <= 0 at
  // u+ = sqrt(Re_y) (where Re_y / u+ = u+ <= y+): the root is bracketed in (0, sqrt(Re_y)].
  // In the log layer the root lies below ln(E Re_y) / kappa, where y+ alone exceeds Re_y
  // (checked: the exponential would overflow at sqrt(Re_y) for Re_y above about 3e5).
  const auto residual = [&](double u) { return re_y / u - y_plus(u); };
  double lo = 0.0, hi = std::sqrt(re_y);
  const double log_bound = std::log(e * re_y) / kappa + 10.0;
  if (log_bound < hi && residual(log_bound) <= 0.0)
    hi = log_bound;
  double u = std::min(hi, std::max(std::log(e * re_y) / kappa, 0.5 * hi)); // the log law's u+, or half the bracket
  for (int i = 0; i < 300 && hi - lo > 1e-14 * hi; ++i) {
    const double f = residual(u);
    if (f == 0.0)
      break;
    (f > 0.0 ? lo : hi) = u;
    const double k = kappa * u;
    const double dy = 1.0 + kappa * (std::exp(k) - 1.0 - k - 0.5 * k * k) / e; // dy+/du+
    double next = u + f / (re_y / (u * u) + dy);
    if (!(next > lo && next < hi))
      next = 0.5 * (lo + hi); // Newton left the bracket: bisect
    const bool converged = std::abs(next - u) <= 1e-14 * u;
    u = next;
    if (converged)
      break;
  }
  const double u_tau = speed / u;
  return u_tau * u_tau;
}

} // namespace fsi::fluid::rigid
