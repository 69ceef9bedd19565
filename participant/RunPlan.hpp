#pragma once
// What a participant's model learns of the run at the handshake, and how the run ended: the
// domain side of Hello/Welcome and of the end of a session, free of the protocol's messages.
// SI units.

#include "common/Types.hpp"
#include "participant/LifeCycle.hpp"

#include <string>
#include <vector>

namespace fsi::participant {

/// One structure as the structure participant declares it (Hello) and the fluid learns it
/// (Welcome): its points are i1 * n2 + i2 of an n1 x n2 grid (n2 = 1 for a filament).
struct StructureTopology {
  std::string name;
  std::string model; ///< "membrane", "filament", ...
  int n1 = 0, n2 = 1;
  Eigen::VectorXd point_measure; ///< each point's share of the measure: m^2 (sheet) or m (filament)
  double mass_per_measure = 0.0; ///< rho_1: kg/m^2 (sheet) or kg/m (filament)
  LifeSpec life;                 ///< when it enters the scene and where it leaves it
  Eigen::Index n_points() const { return static_cast<Eigen::Index>(n1) * n2; }
};

/// The run the coupler admitted this participant to (Welcome).
struct RunPlan {
  double time_step_s = 0.0;
  long n_steps = 0;
  /// 0, or the step of the checkpoint a restart resumes from.
  long first_step = 0;
  /// Implicit coupling: a step may be advanced again (Participant's step bookkeeping).
  bool implicit = false;
  /// Every structure of the scene, in the order of the arrays of every step (the fluid learns
  /// them from Welcome, the structure declared them).
  std::vector<StructureTopology> structures;
  Eigen::Index n_points() const;
  /// All structures' point measures, concatenated.
  Eigen::VectorXd point_measures() const;
};

/// How a session ended, for Model::finish.
struct RunEnd {
  enum class Kind { completed, interrupted, stopped, coupler_lost, failed } kind = Kind::completed;
  std::string reason; ///< the coupler's reason, or what failed
  long steps = 0;     ///< steps completed (the state the model holds)
  bool success() const { return kind == Kind::completed; }
  /// One word or phrase for a results file: "completed", "interrupted", "stopped: <reason>", ...
  std::string status() const;
};

} // namespace fsi::participant
