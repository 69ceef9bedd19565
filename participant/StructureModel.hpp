#pragma once
// What a structure computes for a coupled run, in domain types: StructureParticipant reads the
// coupler's requests and calls these. Our model is the membrane solver (structure_solver/
// CoupledStructure); a user's own structure implements the same (docs/protocol.md). All
// arrays are N x 3, SI, all structures concatenated in the order of topology().

#include "Model.hpp"
#include "proto/BodyPose.hpp"
#include "proto/PackedPoints.hpp"

#include <cstdint>
#include <vector>

namespace fsi::participant {

/// One step of the structure, from t^n to t^{n+1}.
struct StructureStep {
  long step = 0;       ///< n
  double time_s = 0.0; ///< t^n
  double dt_s = 0.0;
  /// The moving rigid surfaces at t^{n+1}, where Eq. (11) corrects against them (every moving
  /// surface of the case, nothing else).
  std::vector<proto::BodyPose> surfaces;
  /// false under implicit coupling: the step may be repeated, so its output waits for
  /// Model::accept_step.
  bool record = true;
  /// The structures the coupler holds idle this step (waiting or gone, ascending indices).
  std::vector<std::uint32_t> idle_structures;
};

class StructureModel : public Model {
public:
  /// The structures, declared to the coupler at the handshake (Hello); fixed for the run.
  virtual std::vector<StructureTopology> topology() const = 0;

  /// The state: X (m) and V (m/s) of every point, and the time it is at (s).
  virtual void positions(proto::MutablePointsView x_m) const = 0;
  virtual void velocities(proto::MutablePointsView v_m_per_s) const = 0;
  virtual double time_s() const = 0;
  /// Per structure (topology order), its largest stretch ratio when it can tear off the scene
  /// (LifeSpec::tear_above_stretch_ratio), 1 otherwise: the coupler's life cycle tears from these
  /// the structures this model's own tears (AdvanceReply.max_stretch_ratio). Empty: none can.
  virtual std::vector<double> max_stretch_ratios() const { return {}; }

  /// Advances Eq. (4) and the collisions of Eq. (11) under the load -F_fsi^n (N per unit
  /// measure). Throws Diverged, the last good state kept.
  virtual void advance(const StructureStep &step, proto::PointsView load_density_n_per_measure) = 0;
};

} // namespace fsi::participant
