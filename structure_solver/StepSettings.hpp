#pragma once
// What every tension scheme of the step of Eq. (4) is built from: the elastic terms, the point
// measures and material densities, the prescribed (pinned/clamped) points, the linear solver and
// the time scheme.

#include "ElasticTerms.hpp"
#include "SolverChoices.hpp"

#include <vector>

namespace fsi::structure {

struct StepSettings {
  const ElasticTerms &terms;
  const Eigen::VectorXd &point_measures; ///< A: area (m^2) or length (m) per point
  double mass_per_measure = 0.0;         ///< rho_1 (kg/m^2 or kg/m)
  double damping_per_measure = 0.0;      ///< lambda (kg/(m^2 s) or kg/(m s))
  const std::vector<bool> &prescribed;   ///< per point: pinned or clamped
  LinearSolver linear_solver = LinearSolver::automatic;
  TimeScheme time_scheme = TimeScheme::paper;
};

} // namespace fsi::structure
