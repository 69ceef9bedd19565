#pragma once
// The n x n system of Eq. (4) (StepSystem.hpp) that every tension scheme shares: one matrix for
// the three coordinates, A = M_lambda + theta dt^2 H(X^n) with the tension frozen at X^n.
// The sparse pattern is built and analysed once; each step only refills the values and solves
// for the three coordinates together (one matrix, three right-hand sides), by Jacobi-
// preconditioned CG or sparse LDLT. Prescribed points keep their rows with their known values.

#include "StepSettings.hpp"
#include "StepSystem.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace fsi::structure {

/// Positions in the value array of the sparse matrix, precomputed once per pattern.
struct StepSlots {
  std::vector<std::array<int, 4>> tension;  ///< aa, ab, ba, bb
  std::vector<std::array<int, 16>> shear;   ///< 4 x 4, row-major
  Eigen::VectorXd bending_values;           ///< constant bending Hessian, by slot
  std::vector<int> diagonal;                ///< per point
  std::vector<std::array<int, 3>> free_row_prescribed_col; ///< slot, row, col
  std::vector<int> prescribed_off_diagonal; ///< slots zeroed in prescribed rows/columns
  std::vector<int> constant_bending_terms;  ///< bending terms with a ghost or rest constant
};

/// LDLT of a matrix whose pattern never changes: analysed once, refactorised each step.
void factorize(Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> &ldlt, const Eigen::SparseMatrix<double> &matrix,
               bool &analysed, const char *what);

class ScalarStepSystem {
public:
  explicit ScalarStepSystem(const StepSettings &settings);

  /// A = M_lambda + theta dt^2 H(x), and H(x) itself for theta < 1.
  void fill_values(const PointArray &x_now, double dt);
  /// rhs = A [2 rho1 X^n - (rho1 - dt lambda/2) X^{n-1}] + dt^2 L^n - (1-theta) dt^2 H X^{n-1}.
  void add_inertia_and_loads(const StepInputs &in, PointArray &rhs) const;
  /// rhs -= dt^2 b(t^{n+1}): the ghost and rest constants of the bending terms.
  void subtract_bending_constants(const StepInputs &in, PointArray &rhs) const;
  /// The right-hand side of Eq. (4): the two above.
  void assemble_rhs(const StepInputs &in, PointArray &rhs) const;
  /// Moves the prescribed points to the right-hand side and solves A X^{n+1} = rhs by CG (warm
  /// start X* = 2 X^n - X^{n-1}) or LDLT; returns the number of CG iterations.
  int solve(const StepInputs &in, PointArray &rhs, PointArray &x_next);

  const Eigen::SparseMatrix<double> &matrix() const { return matrix_; }
  Eigen::Map<Eigen::VectorXd> matrix_values() { return {matrix_.valuePtr(), matrix_.nonZeros()}; }
  const StepSlots &slots() const { return slots_; }
  const ElasticTerms &terms() const { return terms_; }
  const std::vector<bool> &prescribed() const { return prescribed_; }
  bool using_direct_solver() const { return direct_active_; }

private:
  void build_pattern();
  void add_tension_hessian(const PointArray &x, double scale, double *values) const;
  void apply_prescribed(const PointArray &prescribed_next, PointArray &rhs);
  int solve_cg(const PointArray &rhs, PointArray &x);
  void solve_direct(const PointArray &rhs, PointArray &x);

  const ElasticTerms &terms_;
  Eigen::VectorXd measure_;
  double rho_, lambda_;
  std::vector<bool> prescribed_;
  LinearSolver solver_kind_;
  double theta_;
  bool direct_active_ = false;

  Eigen::SparseMatrix<double> matrix_;
  Eigen::SparseMatrix<double> hessian_; ///< frozen H of the current step (for theta < 1)
  Eigen::VectorXd base_values_;         ///< masses, damping and bending for base_dt_
  double base_dt_ = -1.0;
  StepSlots slots_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  bool ldlt_analysed_ = false;
  PointArray cg_r_, cg_z_, cg_p_, cg_q_; ///< work arrays of solve_cg, kept from step to step
  Eigen::VectorXd cg_inv_diag_;
};

} // namespace fsi::structure
