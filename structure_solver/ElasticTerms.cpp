#include "ElasticTerms.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::structure {

ElasticTerms::ElasticTerms(const LagrangianGrid &grid, const EdgeConditions &bc, const PointArray &initial_m,
                           double tension_coefficient, double bending_rigidity, bool curved_rest_state,
                           CompressionResponse compression)
    : phi_(tension_coefficient), zeta_(bending_rigidity), compression_(compression) {
  add_tension_terms(grid, initial_m);
  if (!grid.is_filament())
    add_shear_terms(grid, initial_m);
  add_bending_terms(grid, bc, initial_m);
  if (!curved_rest_state)
    return;
  for (auto &term : bending_)
    term.rest = bending_value(term, initial_m, Eigen::Matrix3d::Identity());
}

void ElasticTerms::add_tension_terms(const LagrangianGrid &grid, const PointArray &x0) {
  const auto add = [&](int a, int b, double ds, double measure) {
    const double inv = 1.0 / (ds * ds);
    tension_.push_back({a, b, inv, (x0.row(b) - x0.row(a)).squaredNorm() * inv, measure});
  };
  for (int i1 = 0; i1 + 1 < grid.n1(); ++i1)
    for (int i2 = 0; i2 < grid.n2(); ++i2)
      add(grid.index(i1, i2), grid.index(i1 + 1, i2), grid.ds1(), grid.edge_measure_1(i2));
  for (int i1 = 0; i1 < grid.n1(); ++i1)
    for (int i2 = 0; i2 + 1 < grid.n2(); ++i2)
      add(grid.index(i1, i2), grid.index(i1, i2 + 1), grid.ds2(), grid.edge_measure_2(i1));
}

void ElasticTerms::add_shear_terms(const LagrangianGrid &grid, const PointArray &x0) {
  const double ha = 0.5 / grid.ds1(), hb = 0.5 / grid.ds2();
  for (int i1 = 0; i1 + 1 < grid.n1(); ++i1)
    for (int i2 = 0; i2 + 1 < grid.n2(); ++i2) {
      ShearTerm term{{grid.index(i1, i2), grid.index(i1 + 1, i2), grid.index(i1, i2 + 1), grid.index(i1 + 1, i2 + 1)},
                     {-ha, ha, -ha, ha},
                     {-hb, -hb, hb, hb},
                     0.0,
                     grid.cell_measure()};
      term.rest_value = 0.0;
      Vec3 a = Vec3::Zero(), b = Vec3::Zero();
      for (int k = 0; k < 4; ++k) {
        a += term.coef_a[k] * x0.row(term.points[k]).transpose();
        b += term.coef_b[k] * x0.row(term.points[k]).transpose();
      }
      term.rest_value = a.dot(b);
      shear_.push_back(term);
    }
}

void ElasticTerms::add_bending_terms(const LagrangianGrid &grid, const EdgeConditions &bc, const PointArray &x0) {
  for (int i2 = 0; i2 < grid.n2(); ++i2)
    add_bending_line(grid, true, i2, bc.s1_min, bc.s1_max, x0);
  if (grid.is_filament())
    return;
  for (int i1 = 0; i1 < grid.n1(); ++i1)
    add_bending_line(grid, false, i1, bc.s2_min, bc.s2_max, x0);
  add_twist_terms(grid);
}

void ElasticTerms::add_bending_line(const LagrangianGrid &grid, bool along_1, int line, EdgeCondition at_min,
                                    EdgeCondition at_max, const PointArray &x0) {
  const int n = along_1 ? grid.n1() : grid.n2();
  const double ds = along_1 ? grid.ds1() : grid.ds2(), inv = 1.0 / (ds * ds);
  const auto point = [&](int k) { return along_1 ? grid.index(k, line) : grid.index(line, k); };
  const auto measure = [&](int k) { return along_1 ? grid.point_measure(k, line) : grid.point_measure(line, k); };
  const auto tangent = [&](int k0, int k1, int k2) { // second-order one-sided dX/ds at k0
    return Vec3((-3.0 * x0.row(point(k0)) + 4.0 * x0.row(point(k1)) - x0.row(point(k2))).transpose() /
                (2.0 * ds));
  };
  for (int k = 1; k + 1 < n; ++k) {
    BendingTerm term;
    term.points = {point(k - 1), point(k), point(k + 1), 0};
    term.coef = {inv, -2.0 * inv, inv, 0.0};
    term.n_points = 3;
    term.weight = measure(k);
    bending_.push_back(term);
  }
  // Clamped ends: ghost point X_ghost = X_inner -/+ 2 ds t, with t = dX/ds outward-signed.
  if (at_min == EdgeCondition::clamped) {
    BendingTerm term;
    term.points = {point(0), point(1), 0, 0};
    term.coef = {-2.0 * inv, 2.0 * inv, 0.0, 0.0};
    term.n_points = 2;
    term.weight = measure(0);
    term.ghost_body = -2.0 / ds * tangent(0, 1, 2);
    bending_.push_back(term);
  }
  if (at_max == EdgeCondition::clamped) {
    BendingTerm term;
    term.points = {point(n - 1), point(n - 2), 0, 0};
    term.coef = {-2.0 * inv, 2.0 * inv, 0.0, 0.0};
    term.n_points = 2;
    term.weight = measure(n - 1);
    term.ghost_body = -2.0 / ds * tangent(n - 1, n - 2, n - 3); // tangent(n-1 <- n-2) = -dX/ds
    bending_.push_back(term);
  }
}

void ElasticTerms::add_twist_terms(const LagrangianGrid &grid) {
  const double inv = 1.0 / (grid.ds1() * grid.ds2());
  for (int i1 = 0; i1 + 1 < grid.n1(); ++i1)
    for (int i2 = 0; i2 + 1 < grid.n2(); ++i2) {
      BendingTerm term;
      term.points = {grid.index(i1, i2), grid.index(i1 + 1, i2), grid.index(i1, i2 + 1), grid.index(i1 + 1, i2 + 1)};
      term.coef = {inv, -inv, -inv, inv};
      term.n_points = 4;
      term.weight = 2.0 * grid.cell_measure(); // sum_ij counts X_12 and X_21
      bending_.push_back(term);
    }
}

double ElasticTerms::sigma(const TensionTerm &t, const PointArray &x) const {
  const double s = phi_ * ((x.row(t.b) - x.row(t.a)).squaredNorm() * t.inv_ds_squared - t.rest_value);
  return compression_ == CompressionResponse::slack ? std::max(0.0, s) : s;
}

double ElasticTerms::tension_stiffness(const TensionTerm &t, const PointArray &x) const {
  if (compression_ == CompressionResponse::elastic)
    return phi_;
  return (x.row(t.b) - x.row(t.a)).squaredNorm() * t.inv_ds_squared > t.rest_value ? phi_ : 0.0;
}

namespace {
std::pair<Vec3, Vec3> shear_vectors(const ShearTerm &t, const PointArray &x) {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  for (int k = 0; k < 4; ++k) {
    a += t.coef_a[k] * x.row(t.points[k]).transpose();
    b += t.coef_b[k] * x.row(t.points[k]).transpose();
  }
  return {a, b};
}
} // namespace

double ElasticTerms::sigma(const ShearTerm &t, const PointArray &x) const {
  const auto [a, b] = shear_vectors(t, x);
  return phi_ * (a.dot(b) - t.rest_value);
}

Vec3 ElasticTerms::bending_value(const BendingTerm &t, const PointArray &x, const Eigen::Matrix3d &rotation) const {
  Vec3 d = rotation * t.ghost_body - t.rest;
  for (int k = 0; k < t.n_points; ++k)
    d += t.coef[k] * x.row(t.points[k]).transpose();
  return d;
}

ElasticEnergy ElasticTerms::energy(const PointArray &x, const Eigen::Matrix3d &rotation) const {
  ElasticEnergy e;
  for (const auto &t : tension_) {
    const double s = sigma(t, x);
    e.tension_j += s * s / (4.0 * phi_) * t.measure;
  }
  for (const auto &t : shear_) {
    const double s = sigma(t, x);
    e.tension_j += s * s / (2.0 * phi_) * t.measure;
  }
  for (const auto &t : bending_)
    e.bending_j += 0.5 * zeta_ * t.weight * bending_value(t, x, rotation).squaredNorm();
  return e;
}

void ElasticTerms::add_forces(const PointArray &x, const Eigen::Matrix3d &rotation, PointArray &forces) const {
  for (const auto &t : tension_) {
    const Vec3 f = sigma(t, x) * t.measure * t.inv_ds_squared * (x.row(t.b) - x.row(t.a)).transpose();
    forces.row(t.a) += f.transpose();
    forces.row(t.b) -= f.transpose();
  }
  for (const auto &t : shear_) {
    const auto [a, b] = shear_vectors(t, x);
    const double s = phi_ * (a.dot(b) - t.rest_value) * t.measure;
    for (int k = 0; k < 4; ++k)
      forces.row(t.points[k]) -= s * (t.coef_a[k] * b + t.coef_b[k] * a).transpose();
  }
  for (const auto &t : bending_) {
    const Vec3 d = zeta_ * t.weight * bending_value(t, x, rotation);
    for (int k = 0; k < t.n_points; ++k)
      forces.row(t.points[k]) -= t.coef[k] * d.transpose();
  }
}

double ElasticTerms::max_stretch_ratio(const PointArray &x) const {
  double worst = 0.0;
  for (const auto &t : tension_)
    worst = std::max(worst, std::sqrt((x.row(t.b) - x.row(t.a)).squaredNorm() * t.inv_ds_squared / t.rest_value));
  return worst;
}

int ElasticTerms::most_stretched_point(const PointArray &x) const {
  double worst = -1.0;
  int point = 0;
  for (const auto &t : tension_) {
    const double ratio = (x.row(t.b) - x.row(t.a)).squaredNorm() * t.inv_ds_squared / t.rest_value;
    if (!(ratio <= worst)) { // also catches NaN
      worst = std::isfinite(ratio) ? ratio : std::numeric_limits<double>::infinity();
      point = t.b;
    }
  }
  return point;
}

} // namespace fsi::structure
