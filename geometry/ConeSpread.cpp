#include "geometry/ConeSpread.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::geometry {
namespace {

/// Candidates within this of a constraint plane count as satisfying it: the true optimum
/// may be computed a little outside the cone.
constexpr double kFeasibleTolerance = 1e-9;
/// Added to every result to cover the round-off of the candidates themselves.
constexpr double kSpreadMargin = 1e-6;

bool satisfies_all(const Vec3 &u, const std::vector<Vec3> &constraints) {
  return std::all_of(constraints.begin(), constraints.end(),
                     [&u](const Vec3 &c) { return u.dot(c) <= kFeasibleTolerance; });
}

/// Raises spread_i to |u_i| when u (unit) or -u is in the cone.
void consider(const Vec3 &u, const std::vector<Vec3> &constraints, Vec3 &spread) {
  if (satisfies_all(u, constraints) || satisfies_all(-u, constraints))
    spread = spread.cwiseMax(u.cwiseAbs());
}

} // namespace

Vec3 cone_spread(const std::vector<Vec3> &constraints) {
  std::vector<Vec3> unit;
  for (const Vec3 &c : constraints) {
    if (c.norm() > 0.0 && c.allFinite())
      unit.push_back(c.normalized());
  }
  Vec3 spread = Vec3::Zero();
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 e = Vec3::Unit(axis);
    consider(e, unit, spread);
    for (const Vec3 &c : unit) {
      const Vec3 projected = e - e.dot(c) * c;
      if (projected.norm() > 1e-12)
        consider(projected.normalized(), unit, spread);
    }
  }
  for (std::size_t a = 0; a < unit.size(); ++a) {
    for (std::size_t b = a + 1; b < unit.size(); ++b) {
      const Vec3 line = unit[a].cross(unit[b]);
      if (line.norm() > 1e-12)
        consider(line.normalized(), unit, spread);
    }
  }
  return (spread.array() + kSpreadMargin).min(1.0).matrix();
}

} // namespace fsi::geometry
