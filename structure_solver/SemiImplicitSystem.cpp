#include "SemiImplicitSystem.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::structure {

namespace {
/// In `auto` mode, more CG iterations than this in one step switch to the direct solver.
constexpr int cg_iteration_budget = 60;

/// LDLT of a matrix whose pattern never changes: analysed once, refactorised each step.
void factorize(Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> &ldlt, const Eigen::SparseMatrix<double> &matrix,
               bool &analysed, const char *what) {
  if (!analysed) {
    ldlt.analyzePattern(matrix);
    analysed = true;
  }
  ldlt.factorize(matrix);
  if (ldlt.info() != Eigen::Success)
    throw std::runtime_error(std::string("the LDLT factorisation of ") + what + " failed (singular system)");
}
} // namespace

/// Positions in the value array of the sparse matrix, precomputed once per pattern.
struct SemiImplicitSystem::Slots {
  std::vector<std::array<int, 4>> tension;  ///< aa, ab, ba, bb
  std::vector<std::array<int, 16>> shear;   ///< 4 x 4, row-major
  Eigen::VectorXd bending_values;           ///< constant bending Hessian, by slot
  std::vector<int> diagonal;                ///< per point
  std::vector<std::array<int, 3>> free_row_prescribed_col; ///< slot, row, col
  std::vector<int> prescribed_off_diagonal; ///< slots zeroed in prescribed rows/columns
  std::vector<int> constant_bending_terms;  ///< bending terms with a ghost or rest constant
};

SemiImplicitSystem::SemiImplicitSystem(const ElasticTerms &terms, const Eigen::VectorXd &point_measure,
                                       double mass_per_measure, double damping_per_measure,
                                       std::vector<bool> prescribed, LinearSolver solver, TimeScheme scheme,
                                       TensionScheme tension)
    : terms_(terms), measure_(point_measure), rho_(mass_per_measure), lambda_(damping_per_measure),
      prescribed_(std::move(prescribed)), solver_kind_(solver),
      theta_(scheme == TimeScheme::paper ? 1.0 : 0.5), stabilized_(tension == TensionScheme::stabilized),
      linearized_(tension == TensionScheme::linearized),
      direct_active_(solver == LinearSolver::direct),
      slots_(std::make_unique<Slots>()) {
  build_pattern();
  if (linearized_)
    build_block_pattern();
  double max_inv_ds_squared = 0.0;
  for (const auto &t : terms_.tension())
    max_inv_ds_squared = std::max(max_inv_ds_squared, t.inv_ds_squared);
  if (max_inv_ds_squared > 0.0)
    min_spacing_m_ = 1.0 / std::sqrt(max_inv_ds_squared);
  constexpr double beta = 1.5; // explicit remainder at Delta s / dt = 1.5 x its wave speed
  stabilization_speed_m_per_s_ = beta * std::sqrt(2.0 * terms_.tension_coefficient() / rho_);
}

SemiImplicitSystem::~SemiImplicitSystem() = default;

void SemiImplicitSystem::build_pattern() {
  const auto n = static_cast<int>(measure_.size());
  std::vector<Eigen::Triplet<double>> entries;
  const auto couple = [&](const int *points, int count) {
    for (int r = 0; r < count; ++r)
      for (int c = 0; c < count; ++c)
        entries.emplace_back(points[r], points[c], 0.0);
  };
  for (int i = 0; i < n; ++i)
    entries.emplace_back(i, i, 0.0);
  for (const auto &t : terms_.tension()) {
    const int p[2] = {t.a, t.b};
    couple(p, 2);
  }
  for (const auto &t : terms_.shear())
    couple(t.points.data(), 4);
  for (const auto &t : terms_.bending())
    couple(t.points.data(), t.n_points);
  matrix_.resize(n, n);
  matrix_.setFromTriplets(entries.begin(), entries.end());
  matrix_.makeCompressed();
  if (theta_ < 1.0)
    hessian_ = matrix_; // same pattern; only the energy-conserving scheme needs H itself
  if (stabilized_)
    bound_ = matrix_;

  const auto slot = [&](int row, int col) {
    const int *begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col];
    const int *end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - matrix_.innerIndexPtr());
  };
  Slots &s = *slots_;
  for (int i = 0; i < n; ++i)
    s.diagonal.push_back(slot(i, i));
  for (const auto &t : terms_.tension())
    s.tension.push_back({slot(t.a, t.a), slot(t.a, t.b), slot(t.b, t.a), slot(t.b, t.b)});
  for (const auto &t : terms_.shear()) {
    std::array<int, 16> slots{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        slots[4 * r + c] = slot(t.points[r], t.points[c]);
    s.shear.push_back(slots);
  }
  s.bending_values = Eigen::VectorXd::Zero(matrix_.nonZeros());
  const double zeta = terms_.bending_rigidity();
  for (std::size_t k = 0; k < terms_.bending().size(); ++k) {
    const auto &t = terms_.bending()[k];
    for (int r = 0; r < t.n_points; ++r)
      for (int c = 0; c < t.n_points; ++c)
        s.bending_values[slot(t.points[r], t.points[c])] += zeta * t.weight * t.coef[r] * t.coef[c];
    if (!t.ghost_body.isZero() || !t.rest.isZero())
      s.constant_bending_terms.push_back(static_cast<int>(k));
  }
  for (int col = 0; col < n; ++col)
    for (int k = matrix_.outerIndexPtr()[col]; k < matrix_.outerIndexPtr()[col + 1]; ++k) {
      const int row = matrix_.innerIndexPtr()[k];
      if (row == col || !(prescribed_[row] || prescribed_[col]))
        continue;
      s.prescribed_off_diagonal.push_back(k);
      if (!prescribed_[row])
        s.free_row_prescribed_col.push_back({k, row, col});
    }
}

void SemiImplicitSystem::fill_values(const PointArray &x, double dt) {
  // A = M_lambda + theta dt^2 H(x): the constant part (masses, damping, bending) is kept for
  // the current dt; only the frozen tension terms change from step to step. For theta < 1
  // the Hessian itself is also needed (H X^{n-1} on the right-hand side).
  const Slots &s = *slots_;
  if (dt != base_dt_) {
    base_values_ = theta_ * dt * dt * s.bending_values;
    for (std::size_t i = 0; i < s.diagonal.size(); ++i)
      base_values_[s.diagonal[i]] += (rho_ + 0.5 * dt * lambda_) * measure_[static_cast<Eigen::Index>(i)];
    base_dt_ = dt;
  }
  Eigen::Map<Eigen::VectorXd>(matrix_.valuePtr(), matrix_.nonZeros()) = base_values_;
  add_tension_hessian(x, theta_ * dt * dt, matrix_.valuePtr());
  if (stabilized_) {
    const double r = min_spacing_m_ / (stabilization_speed_m_per_s_ * dt);
    const double f = std::max(0.0, 1.0 - r * r);
    Eigen::Map<Eigen::VectorXd>(bound_.valuePtr(), bound_.nonZeros()).setZero();
    if (f > 0.0)
      add_stretching_bound(x, f, bound_.valuePtr());
    Eigen::Map<Eigen::VectorXd>(matrix_.valuePtr(), matrix_.nonZeros()) +=
        dt * dt * Eigen::Map<const Eigen::VectorXd>(bound_.valuePtr(), bound_.nonZeros());
  }
  if (theta_ < 1.0) {
    Eigen::Map<Eigen::VectorXd>(hessian_.valuePtr(), hessian_.nonZeros()) = s.bending_values;
    add_tension_hessian(x, 1.0, hessian_.valuePtr());
  }
}

void SemiImplicitSystem::add_tension_hessian(const PointArray &x, double scale, double *values) const {
  const Slots &s = *slots_;
  for (std::size_t k = 0; k < s.tension.size(); ++k) {
    const auto &t = terms_.tension()[k];
    const double v = scale * terms_.sigma(t, x) * t.measure * t.inv_ds_squared;
    values[s.tension[k][0]] += v, values[s.tension[k][1]] -= v, values[s.tension[k][2]] -= v;
    values[s.tension[k][3]] += v;
  }
  for (std::size_t k = 0; k < s.shear.size(); ++k) {
    const auto &t = terms_.shear()[k];
    const double v = scale * terms_.sigma(t, x) * t.measure;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        values[s.shear[k][4 * r + c]] += v * (t.coef_a[r] * t.coef_b[c] + t.coef_b[r] * t.coef_a[c]);
  }
}

void SemiImplicitSystem::add_stretching_bound(const PointArray &x, double scale, double *values) const {
  // Material part of the tension Hessian and its isotropic bound (u: any displacement):
  //   edge, d = X_b - X_a:  (2 phi m / ds^4) (u_d . d)^2 <= (2 phi m T / ds^2) |u_d|^2, T = |d|^2 / ds^2;
  //   shear, T_12 = a . b:  phi m (u_a . b + u_b . a)^2 <= 2 phi m (|b|^2 |u_a|^2 + |a|^2 |u_b|^2),
  // u_d, u_a, u_b the stencils' differences of u: each bound is a scalar stencil times the 3x3
  // identity, so S shares the pattern (and the three coordinates) of the frozen-tension matrix.
  const Slots &s = *slots_;
  const double phi = terms_.tension_coefficient();
  for (std::size_t k = 0; k < s.tension.size(); ++k) {
    const auto &t = terms_.tension()[k];
    const double stretch = (x.row(t.b) - x.row(t.a)).squaredNorm() * t.inv_ds_squared;
    const double v = scale * 2.0 * phi * t.measure * t.inv_ds_squared * stretch;
    values[s.tension[k][0]] += v, values[s.tension[k][1]] -= v, values[s.tension[k][2]] -= v;
    values[s.tension[k][3]] += v;
  }
  for (std::size_t k = 0; k < s.shear.size(); ++k) {
    const auto &t = terms_.shear()[k];
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    for (int p = 0; p < 4; ++p) {
      a += t.coef_a[p] * x.row(t.points[p]).transpose();
      b += t.coef_b[p] * x.row(t.points[p]).transpose();
    }
    const double wa = scale * 2.0 * phi * t.measure * b.squaredNorm(), wb = scale * 2.0 * phi * t.measure * a.squaredNorm();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        values[s.shear[k][4 * r + c]] += wa * t.coef_a[r] * t.coef_a[c] + wb * t.coef_b[r] * t.coef_b[c];
  }
}

void SemiImplicitSystem::assemble_rhs(const StepInputs &in, PointArray &rhs) const {
  const double dt = in.dt_s;
  rhs = measure_.asDiagonal() * (2.0 * rho_ * *in.x_now - (rho_ - 0.5 * dt * lambda_) * *in.x_prev);
  rhs += dt * dt * *in.nodal_load_n;
  if (theta_ < 1.0)
    rhs -= (1.0 - theta_) * dt * dt * (hessian_ * *in.x_prev);
  if (stabilized_) // + dt^2 S X*, X* = 2 X^n - X^{n-1}: the bound acts on X^{n+1} - X* only
    rhs += dt * dt * (bound_ * (2.0 * *in.x_now - *in.x_prev));
  const double zeta = terms_.bending_rigidity();
  for (const int k : slots_->constant_bending_terms) { // ghost/rest constants: -zeta w coef (R c - rest)
    const auto &t = terms_.bending()[static_cast<std::size_t>(k)];
    const Vec3 c = in.clamp_rotation_next * t.ghost_body - t.rest;
    for (int r = 0; r < t.n_points; ++r)
      rhs.row(t.points[r]) -= dt * dt * zeta * t.weight * t.coef[r] * c.transpose();
  }
}

void SemiImplicitSystem::apply_prescribed(const PointArray &prescribed_next, PointArray &rhs) {
  double *a = matrix_.valuePtr();
  for (const auto &[k, row, col] : slots_->free_row_prescribed_col)
    rhs.row(row) -= a[k] * prescribed_next.row(col);
  for (const int k : slots_->prescribed_off_diagonal)
    a[k] = 0.0;
  // A prescribed row keeps its own diagonal (mass scale), so the system stays well scaled.
  for (std::size_t i = 0; i < prescribed_.size(); ++i)
    if (prescribed_[i]) {
      const auto row = static_cast<Eigen::Index>(i);
      rhs.row(row) = a[slots_->diagonal[i]] * prescribed_next.row(row);
    }
}

void SemiImplicitSystem::build_block_pattern() {
  // Every scalar nonzero (r, c) becomes a full 3 x 3 block (3r + i, 3c + j).
  std::vector<Eigen::Triplet<double>> entries;
  for (int col = 0; col < matrix_.outerSize(); ++col)
    for (int k = matrix_.outerIndexPtr()[col]; k < matrix_.outerIndexPtr()[col + 1]; ++k)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          entries.emplace_back(3 * matrix_.innerIndexPtr()[k] + i, 3 * col + j, 0.0);
  block_.resize(3 * matrix_.rows(), 3 * matrix_.cols());
  block_.setFromTriplets(entries.begin(), entries.end());
  block_.makeCompressed();
  material_ = block_;
  block_slots_.resize(static_cast<std::size_t>(matrix_.nonZeros()));
  for (int col = 0; col < matrix_.outerSize(); ++col)
    for (int k = matrix_.outerIndexPtr()[col]; k < matrix_.outerIndexPtr()[col + 1]; ++k) {
      const int row = matrix_.innerIndexPtr()[k];
      for (int j = 0; j < 3; ++j) {
        const int bcol = 3 * col + j;
        const int *begin = block_.innerIndexPtr() + block_.outerIndexPtr()[bcol];
        const int *end = block_.innerIndexPtr() + block_.outerIndexPtr()[bcol + 1];
        for (int i = 0; i < 3; ++i)
          block_slots_[static_cast<std::size_t>(k)][3 * i + j] =
              static_cast<int>(std::lower_bound(begin, end, 3 * row + i) - block_.innerIndexPtr());
      }
    }
}

void SemiImplicitSystem::fill_material_blocks(const PointArray &x, double *values) const {
  // Material part of the tension Hessian (the change of sigma with X), scale 1:
  //   edge:  2 phi m / ds^4 d d^T on (a,a), (b,b) and minus it on (a,b), (b,a);
  //   shear: phi m v_r v_c^T with v_r = dT_12 / dX_r = coef_a[r] b + coef_b[r] a.
  const Slots &s = *slots_;
  const double phi = terms_.tension_coefficient();
  const auto add = [&](int scalar_slot, const Eigen::Matrix3d &block) {
    const auto &slots = block_slots_[static_cast<std::size_t>(scalar_slot)];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        values[slots[3 * i + j]] += block(i, j);
  };
  for (std::size_t k = 0; k < s.tension.size(); ++k) {
    const auto &t = terms_.tension()[k];
    const Vec3 d = (x.row(t.b) - x.row(t.a)).transpose();
    const Eigen::Matrix3d block = 2.0 * phi * t.measure * t.inv_ds_squared * t.inv_ds_squared * d * d.transpose();
    add(s.tension[k][0], block), add(s.tension[k][1], -block), add(s.tension[k][2], -block);
    add(s.tension[k][3], block);
  }
  for (std::size_t k = 0; k < s.shear.size(); ++k) {
    const auto &t = terms_.shear()[k];
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    for (int p = 0; p < 4; ++p) {
      a += t.coef_a[p] * x.row(t.points[p]).transpose();
      b += t.coef_b[p] * x.row(t.points[p]).transpose();
    }
    std::array<Vec3, 4> v;
    for (int r = 0; r < 4; ++r)
      v[static_cast<std::size_t>(r)] = t.coef_a[r] * b + t.coef_b[r] * a;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        add(s.shear[k][4 * r + c], phi * t.measure * v[static_cast<std::size_t>(r)] *
                                       v[static_cast<std::size_t>(c)].transpose());
  }
}

void SemiImplicitSystem::solve_linearized(const StepInputs &in, PointArray &x_next) {
  // [M + dt^2 (H_sigma(X^n) + K(X^n))] X^{n+1} = [paper's right-hand side] + dt^2 K(X^n) X^n:
  // the frozen-tension step plus the change of sigma, linearised about X^n.
  const double dt = in.dt_s;
  fill_values(*in.x_now, dt);
  PointArray rhs;
  assemble_rhs(in, rhs);
  Eigen::Map<Eigen::VectorXd> material(material_.valuePtr(), material_.nonZeros());
  material.setZero();
  fill_material_blocks(*in.x_now, material_.valuePtr());
  material *= dt * dt;
  Eigen::Map<Eigen::VectorXd> b(rhs.data(), rhs.size());
  const Eigen::Map<const Eigen::VectorXd> xn(in.x_now->data(), in.x_now->size());
  b += material_ * xn;
  Eigen::Map<Eigen::VectorXd>(block_.valuePtr(), block_.nonZeros()) = material;
  double *values = block_.valuePtr();
  const double *scalar = matrix_.valuePtr();
  for (std::size_t k = 0; k < block_slots_.size(); ++k)
    for (int i = 0; i < 3; ++i)
      values[block_slots_[k][4 * i]] += scalar[k]; // the diagonal of each block: 3i + i
  // Prescribed points: move their known values to the right-hand side, keep their rows.
  const PointArray &xp = *in.prescribed_next;
  const Slots &s = *slots_;
  for (const auto &[k, row, col] : s.free_row_prescribed_col) {
    const auto &slots = block_slots_[static_cast<std::size_t>(k)];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        b[3 * row + i] -= values[slots[3 * i + j]] * xp(col, j);
  }
  for (const int k : s.prescribed_off_diagonal)
    for (const int slot : block_slots_[static_cast<std::size_t>(k)])
      values[slot] = 0.0;
  for (std::size_t p = 0; p < prescribed_.size(); ++p)
    if (prescribed_[p]) {
      const auto &slots = block_slots_[static_cast<std::size_t>(s.diagonal[p])];
      for (int i = 0; i < 3; ++i) {
        b[3 * static_cast<Eigen::Index>(p) + i] = 0.0;
        for (int j = 0; j < 3; ++j)
          b[3 * static_cast<Eigen::Index>(p) + i] += values[slots[3 * i + j]] * xp(static_cast<Eigen::Index>(p), j);
      }
    }
  factorize(block_ldlt_, block_, block_analysed_, "the linearized-tension step");
  x_next.resize(in.x_now->rows(), 3);
  Eigen::Map<Eigen::VectorXd>(x_next.data(), x_next.size()) = block_ldlt_.solve(b);
}

int SemiImplicitSystem::solve(const StepInputs &in, PointArray &x_next) {
  if (linearized_) {
    solve_linearized(in, x_next);
    return 0;
  }
  fill_values(*in.x_now, in.dt_s);
  PointArray rhs;
  assemble_rhs(in, rhs);
  apply_prescribed(*in.prescribed_next, rhs);
  PointArray x = 2.0 * *in.x_now - *in.x_prev; // warm start: constant-velocity guess
  int iterations = 0;
  if (!direct_active_) {
    iterations = solve_cg(rhs, x);
    if (iterations > cg_iteration_budget && solver_kind_ == LinearSolver::automatic) {
      spdlog::info("linear solver: conjugate gradient needed {} iterations (stiff system for this time step), "
                   "switching to the direct (LDLT) solver",
                   iterations);
      direct_active_ = true;
    } else if (iterations < 0) {
      if (solver_kind_ == LinearSolver::conjugate_gradient)
        throw std::runtime_error("the conjugate-gradient solve of Eq. (4) did not converge; the system may be "
                                 "indefinite (strong compression): use solver.linear_solver: direct");
      spdlog::info("linear solver: conjugate gradient did not converge, switching to the direct (LDLT) solver");
      direct_active_ = true;
    }
  }
  if (direct_active_)
    solve_direct(rhs, x);
  x_next = x;
  return std::max(iterations, 0);
}

int SemiImplicitSystem::solve_cg(const PointArray &b, PointArray &x) const {
  // Jacobi-preconditioned conjugate gradients on the three coordinates at once (one matrix
  // traversal per iteration). Returns the iteration count, or -1 without convergence.
  const Eigen::VectorXd inv_diag = matrix_.diagonal().cwiseInverse();
  PointArray r = b - matrix_ * x;
  PointArray z = inv_diag.asDiagonal() * r;
  // Stop when the preconditioned residual has dropped by 1e-10 from that of the warm start
  // (the constant-velocity guess), or reached round-off relative to the coordinates.
  const double round_off_m = 1e-15 * std::max(x.cwiseAbs().maxCoeff(), 1e-3);
  const double tolerance_m = std::max(1e-10 * z.cwiseAbs().maxCoeff(), round_off_m);
  PointArray p = z;
  Eigen::Array3d rz = (r.array() * z.array()).colwise().sum();
  constexpr int max_iterations = 400;
  for (int it = 0; it < max_iterations; ++it) {
    const Eigen::Array3d error_m = z.cwiseAbs().colwise().maxCoeff().transpose();
    if ((error_m <= tolerance_m).all())
      return it;
    const PointArray q = matrix_ * p;
    const Eigen::Array3d pq = (p.array() * q.array()).colwise().sum();
    Eigen::Array3d alpha = Eigen::Array3d::Zero();
    for (int c = 0; c < 3; ++c) {
      if (error_m[c] <= tolerance_m)
        continue; // this coordinate has converged
      if (!(pq[c] > 0.0))
        return -1; // not positive definite
      alpha[c] = rz[c] / pq[c];
    }
    x += p * alpha.matrix().asDiagonal();
    r -= q * alpha.matrix().asDiagonal();
    z = inv_diag.asDiagonal() * r;
    const Eigen::Array3d rz_new = (r.array() * z.array()).colwise().sum();
    const Eigen::Array3d beta = (rz > 0.0).select(rz_new / rz, 0.0);
    p = z + p * beta.matrix().asDiagonal();
    rz = rz_new;
  }
  return -1;
}

void SemiImplicitSystem::solve_direct(const PointArray &rhs, PointArray &x) {
  factorize(ldlt_, matrix_, ldlt_analysed_, "Eq. (4)");
  x = ldlt_.solve(rhs);
}

} // namespace fsi::structure
