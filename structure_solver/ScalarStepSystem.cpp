#include "ScalarStepSystem.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::structure {

namespace {
/// In `auto` mode, more CG iterations than this in one step switch to the direct solver.
constexpr int cg_iteration_budget = 60;
} // namespace

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

ScalarStepSystem::ScalarStepSystem(const StepSettings &settings)
    : terms_(settings.terms), measure_(settings.point_measures), rho_(settings.mass_per_measure),
      lambda_(settings.damping_per_measure), prescribed_(settings.prescribed), solver_kind_(settings.linear_solver),
      theta_(settings.time_scheme == TimeScheme::paper ? 1.0 : 0.5),
      direct_active_(settings.linear_solver == LinearSolver::direct) {
  build_pattern();
}

void ScalarStepSystem::build_pattern() {
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

  const auto slot = [&](int row, int col) {
    const int *begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col];
    const int *end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - matrix_.innerIndexPtr());
  };
  StepSlots &s = slots_;
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

void ScalarStepSystem::fill_values(const PointArray &x, double dt) {
  // A = M_lambda + theta dt^2 H(x): the constant part (masses, damping, bending) is kept for
  // the current dt; only the frozen tension terms change from step to step. For theta < 1
  // the Hessian itself is also needed (H X^{n-1} on the right-hand side).
  const StepSlots &s = slots_;
  if (dt != base_dt_) {
    base_values_ = theta_ * dt * dt * s.bending_values;
    for (std::size_t i = 0; i < s.diagonal.size(); ++i)
      base_values_[s.diagonal[i]] += (rho_ + 0.5 * dt * lambda_) * measure_[static_cast<Eigen::Index>(i)];
    base_dt_ = dt;
  }
  Eigen::Map<Eigen::VectorXd>(matrix_.valuePtr(), matrix_.nonZeros()) = base_values_;
  add_tension_hessian(x, theta_ * dt * dt, matrix_.valuePtr());
  if (theta_ < 1.0) {
    Eigen::Map<Eigen::VectorXd>(hessian_.valuePtr(), hessian_.nonZeros()) = s.bending_values;
    add_tension_hessian(x, 1.0, hessian_.valuePtr());
  }
}

void ScalarStepSystem::add_tension_hessian(const PointArray &x, double scale, double *values) const {
  const StepSlots &s = slots_;
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

void ScalarStepSystem::assemble_rhs(const StepInputs &in, PointArray &rhs) const {
  add_inertia_and_loads(in, rhs);
  subtract_bending_constants(in, rhs);
}

void ScalarStepSystem::add_inertia_and_loads(const StepInputs &in, PointArray &rhs) const {
  const double dt = in.dt_s;
  rhs = measure_.asDiagonal() * (2.0 * rho_ * *in.x_now - (rho_ - 0.5 * dt * lambda_) * *in.x_prev);
  rhs += dt * dt * *in.nodal_load_n;
  if (theta_ < 1.0)
    rhs -= (1.0 - theta_) * dt * dt * (hessian_ * *in.x_prev);
}

void ScalarStepSystem::subtract_bending_constants(const StepInputs &in, PointArray &rhs) const {
  const double dt = in.dt_s;
  const double zeta = terms_.bending_rigidity();
  for (const int k : slots_.constant_bending_terms) { // ghost/rest constants: -zeta w coef (R c - rest)
    const auto &t = terms_.bending()[static_cast<std::size_t>(k)];
    const Vec3 c = in.clamp_rotation_next * t.ghost_body - t.rest;
    for (int r = 0; r < t.n_points; ++r)
      rhs.row(t.points[r]) -= dt * dt * zeta * t.weight * t.coef[r] * c.transpose();
  }
}

void ScalarStepSystem::apply_prescribed(const PointArray &prescribed_next, PointArray &rhs) {
  double *a = matrix_.valuePtr();
  for (const auto &[k, row, col] : slots_.free_row_prescribed_col)
    rhs.row(row) -= a[k] * prescribed_next.row(col);
  for (const int k : slots_.prescribed_off_diagonal)
    a[k] = 0.0;
  // A prescribed row keeps its own diagonal (mass scale), so the system stays well scaled.
  for (std::size_t i = 0; i < prescribed_.size(); ++i)
    if (prescribed_[i]) {
      const auto row = static_cast<Eigen::Index>(i);
      rhs.row(row) = a[slots_.diagonal[i]] * prescribed_next.row(row);
    }
}

int ScalarStepSystem::solve(const StepInputs &in, PointArray &rhs, PointArray &x_next) {
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

int ScalarStepSystem::solve_cg(const PointArray &b, PointArray &x) {
  // Jacobi-preconditioned conjugate gradients on the three coordinates at once (one matrix
  // traversal per iteration). Returns the iteration count, or -1 without convergence.
  // A is symmetric (the prescribed rows and columns are cleared alike), so A p is computed as
  // A^T p: a row-by-row traversal of the column-major matrix that gathers into each row of the
  // result instead of scattering. The vector updates of an iteration are fused into one pass
  // over the arrays, which no longer fit in the cache from about 10^5 points; the work arrays
  // are kept from step to step.
  const Eigen::Index n = x.rows();
  const double *a = matrix_.valuePtr();
  cg_inv_diag_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i)
    cg_inv_diag_[i] = 1.0 / a[slots_.diagonal[static_cast<std::size_t>(i)]];
  PointArray &r = cg_r_, &z = cg_z_, &p = cg_p_, &q = cg_q_;
  r.resize(n, 3), z.resize(n, 3), p.resize(n, 3), q.resize(n, 3);
  q.noalias() = matrix_.transpose() * x;
  Eigen::Array3d rz = Eigen::Array3d::Zero(), error_m = Eigen::Array3d::Zero();
  for (Eigen::Index i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      const double ri = b(i, c) - q(i, c), zi = cg_inv_diag_[i] * ri;
      r(i, c) = ri, z(i, c) = zi, p(i, c) = zi;
      rz[c] += ri * zi;
      error_m[c] = std::max(error_m[c], std::abs(zi));
    }
  // Stop when the preconditioned residual has dropped by 1e-10 from that of the warm start
  // (the constant-velocity guess), or reached round-off relative to the coordinates.
  const double round_off_m = 1e-15 * std::max(x.cwiseAbs().maxCoeff(), 1e-3);
  const double tolerance_m = std::max(1e-10 * error_m.maxCoeff(), round_off_m);
  constexpr int max_iterations = 400;
  for (int it = 0; it < max_iterations; ++it) {
    if ((error_m <= tolerance_m).all())
      return it;
    q.noalias() = matrix_.transpose() * p;
    Eigen::Array3d pq = Eigen::Array3d::Zero();
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        pq[c] += p(i, c) * q(i, c);
    Eigen::Array3d alpha = Eigen::Array3d::Zero();
    for (int c = 0; c < 3; ++c) {
      if (error_m[c] <= tolerance_m)
        continue; // this coordinate has converged
      if (!(pq[c] > 0.0))
        return -1; // not positive definite
      alpha[c] = rz[c] / pq[c];
    }
    Eigen::Array3d rz_new = Eigen::Array3d::Zero();
    error_m.setZero();
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        x(i, c) += alpha[c] * p(i, c);
        const double ri = r(i, c) - alpha[c] * q(i, c), zi = cg_inv_diag_[i] * ri;
        r(i, c) = ri, z(i, c) = zi;
        rz_new[c] += ri * zi;
        error_m[c] = std::max(error_m[c], std::abs(zi));
      }
    const Eigen::Array3d beta = (rz > 0.0).select(rz_new / rz, 0.0);
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c)
        p(i, c) = z(i, c) + beta[c] * p(i, c);
    rz = rz_new;
  }
  return -1;
}

void ScalarStepSystem::solve_direct(const PointArray &rhs, PointArray &x) {
  factorize(ldlt_, matrix_, ldlt_analysed_, "Eq. (4)");
  x = ldlt_.solve(rhs);
}

} // namespace fsi::structure
