#pragma once
// One time step of the motion equation, Eq. (4), multiplied through by the point measures A:
//
//   [(rho1 + dt lambda/2) A + theta dt^2 H(X^n)] X^{n+1}
//        = A [2 rho1 X^n - (rho1 - dt lambda/2) X^{n-1}] - (1-theta) dt^2 H X^{n-1}
//          + dt^2 (L^n - b(t^{n+1}))
//
// H is the Hessian of the elastic energy with the tension coefficients sigma frozen at X^n
// (semi-implicit: -K of Eq. 4), b the constant part of the clamped-edge ghost terms, L the
// nodal loads (rho1 g - F_fsi + F_c, integrated over each point's measure). theta = 1 is the
// paper's scheme (first-order dissipative); theta = 1/2 applies H to the average of X^{n+1}
// and X^{n-1} and conserves the energy of the linearised system exactly.
// The sparse pattern is built and analysed once; each step only refills the values and solves
// for the three coordinates together (one matrix, three right-hand sides).

#include "ElasticTerms.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace fsi::structure {

enum class LinearSolver { automatic, conjugate_gradient, direct };
enum class TimeScheme { paper, energy_conserving };
/// How the tension enters the step. frozen: sigma at X^n (the paper's semi-implicit Eq. 4);
/// stretching is then explicit and the step is stable only for about Delta s / Delta t >=
/// sqrt(2 phi / rho_1). stabilized: in addition, an isotropic upper bound S(X^n) of the
/// stretching stiffness (the material part of the tension Hessian, 2 phi (dX/ds)(dX/ds)^T per
/// edge and its shear counterpart) is taken implicitly and subtracted explicitly at the
/// constant-velocity predictor X* = 2 X^n - X^{n-1}:
///   [M + dt^2 (H_sigma + f S)] X^{n+1} = [paper's right-hand side] + dt^2 f S X*.
/// Only the part that the explicit treatment cannot carry is moved: f = max(0, 1 - (Delta s /
/// (beta c dt))^2), c = sqrt(2 phi / rho_1), beta = 1.5, leaves explicit a stiffness whose wave
/// speed is Delta s / (beta dt), below the measured stability limit (Delta s / dt >= 0.7-1.06 c).
/// So for dt <= Delta s / (beta c) the step is the paper's exactly, and beyond it stretching waves
/// no longer limit the time step (linear stability argument; the stability suite measures it).
/// The added term dt^2 f S (X^{n+1} - X*) is of order dt^4 (c / Delta s)^2 per step.
/// linearized: the tension linearised about X^n, directionally: the full stretching and shearing
/// stiffness (material part 2 phi m d d^T / ds^4 per edge, phi m v_r v_c^T per shear cell, the
/// 3 x 3 blocks coupling the coordinates) is taken implicitly on X^{n+1} - X^n, one Newton step
/// of the implicit tension: a 3n x 3n system, solved by LDLT. No stretching-wave limit, and no
/// resistance to transverse motion that the stretching does not have.
enum class TensionScheme { frozen, stabilized, linearized };

struct StepInputs {
  const PointArray *x_now;
  const PointArray *x_prev;
  const PointArray *nodal_load_n; ///< N per point
  const PointArray *prescribed_next; ///< positions of prescribed points at t^{n+1} (others ignored)
  Eigen::Matrix3d clamp_rotation_next = Eigen::Matrix3d::Identity();
  double dt_s = 0.0;
};

class SemiImplicitSystem {
public:
  SemiImplicitSystem(const ElasticTerms &terms, const Eigen::VectorXd &point_measure, double mass_per_measure,
                     double damping_per_measure, std::vector<bool> prescribed, LinearSolver solver, TimeScheme scheme,
                     TensionScheme tension = TensionScheme::frozen);
  ~SemiImplicitSystem();

  /// Solves for X^{n+1}; returns the number of CG iterations (0 for the direct solver).
  int solve(const StepInputs &in, PointArray &x_next);

  const Eigen::SparseMatrix<double> &matrix() const { return matrix_; }
  bool using_direct_solver() const { return direct_active_; }

private:
  struct Slots;
  void build_pattern();
  void fill_values(const PointArray &x_now, double dt);
  void add_tension_hessian(const PointArray &x, double scale, double *values) const;
  void add_stretching_bound(const PointArray &x, double scale, double *values) const;
  void assemble_rhs(const StepInputs &in, PointArray &rhs) const;
  void apply_prescribed(const PointArray &prescribed_next, PointArray &rhs);
  int solve_cg(const PointArray &rhs, PointArray &x) const;
  void build_block_pattern();
  void fill_material_blocks(const PointArray &x, double *values) const;
  void solve_linearized(const StepInputs &in, PointArray &x_next);
  void solve_direct(const PointArray &rhs, PointArray &x);

  const ElasticTerms &terms_;
  Eigen::VectorXd measure_;
  double rho_, lambda_;
  std::vector<bool> prescribed_;
  LinearSolver solver_kind_;
  double theta_;
  bool stabilized_;
  bool linearized_;
  Eigen::SparseMatrix<double> block_;         ///< 3n x 3n system of the linearized tension
  Eigen::SparseMatrix<double> material_;      ///< its material part dt^2 K(X^n), same pattern
  std::vector<std::array<int, 9>> block_slots_; ///< per scalar slot: its 3 x 3 block's slots
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> block_ldlt_;
  bool block_analysed_ = false;
  double stabilization_speed_m_per_s_ = 0.0; ///< beta c: f = max(0, 1 - (ds_min / (beta c dt))^2)
  double min_spacing_m_ = 0.0;
  bool direct_active_ = false;

  Eigen::SparseMatrix<double> matrix_;
  Eigen::SparseMatrix<double> hessian_; ///< frozen H of the current step (for theta < 1)
  Eigen::SparseMatrix<double> bound_;   ///< S(X^n) of the stabilized tension
  Eigen::VectorXd base_values_;         ///< masses, damping and bending for base_dt_
  double base_dt_ = -1.0;
  std::unique_ptr<Slots> slots_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  bool ldlt_analysed_ = false;
};

} // namespace fsi::structure
