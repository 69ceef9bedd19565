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
// How the tension enters the step is the tension scheme (solver.tension): FrozenTension,
// StabilizedTension, LinearizedTension, chosen through TensionSchemeRegistry; what they share
// (the n x n system) is ScalarStepSystem.

#include "ElasticTerms.hpp"

#include <Eigen/SparseCore>

namespace fsi::structure {

struct StepInputs {
  const PointArray *x_now;
  const PointArray *x_prev;
  const PointArray *nodal_load_n; ///< N per point
  const PointArray *prescribed_next; ///< positions of prescribed points at t^{n+1} (others ignored)
  Eigen::Matrix3d clamp_rotation_next = Eigen::Matrix3d::Identity();
  double dt_s = 0.0;
};

class StepSystem {
public:
  virtual ~StepSystem() = default;

  /// Solves for X^{n+1}; returns the number of CG iterations (0 for the direct solver).
  virtual int solve(const StepInputs &in, PointArray &x_next) = 0;

  /// The n x n matrix of Eq. (4) of the last step (mass, damping, bending, frozen tension).
  virtual const Eigen::SparseMatrix<double> &matrix() const = 0;
  virtual bool using_direct_solver() const = 0;
  /// True when stretching is explicit (frozen tension): the step has a stretching-wave limit.
  virtual bool explicit_stretching() const = 0;
};

} // namespace fsi::structure
