#pragma once
// What a fluid computes for a coupled run, in domain types: FluidParticipant reads the
// coupler's requests and calls these. Models: the prescribed flow (prescribed_flow/) and the
// OpenFOAM solver (fluid_adapter/); a user's own fluid implements the same (docs/protocol.md).
// All arrays are N x 3, SI, all structures concatenated in the order of RunPlan::structures.

#include "Model.hpp"
#include "proto/BodyPose.hpp"
#include "proto/PackedPoints.hpp"

#include <vector>

namespace fsi::participant {

using proto::BodyPose;
using proto::MutablePointsView;
using proto::PointsView;

/// One step of the fluid, from t^n to t^{n+1}.
struct FluidStep {
  long step = 0;       ///< n
  double time_s = 0.0; ///< t^n
  double dt_s = 0.0;
  /// The moving rigid bodies at t^{n+1}, where Eqs. (9-10) penalize them (every moving body of
  /// the case, nothing else).
  std::vector<BodyPose> bodies;
};

/// The fluid's force and torque on one rigid body over the step (N, N m; about the body's origin).
struct BodyLoad {
  std::string name;
  Vec3 force_n = Vec3::Zero();
  Vec3 torque_n_m = Vec3::Zero();
};

class FluidModel : public Model {
public:
  /// U_ib: the fluid velocity at the points x_m at time time_s (m/s), into u_m_per_s (same size).
  virtual void interpolate(double time_s, PointsView x_m, MutablePointsView u_m_per_s) = 0;

  /// The points of structures out of the scene (a feed's rags waiting or gone; true: idle), for
  /// the next interpolate() and advance(): their force is zero, so a fluid may skip them (their
  /// U_ib is then zero). Called when the set changes; none are idle before the first call.
  virtual void set_idle_points(const std::vector<bool> & /*idle*/) {}

  /// The next advance() spreads at these points (X^n), not at those of the last interpolate()
  /// (the coupling law two_point_sets samples U_ib at its own points).
  virtual void spread_at(PointsView x_m) = 0;

  /// Spreads F_fsi^n (Eq. 8, N per unit measure) at the points of the last interpolate() (or of
  /// spread_at()) and advances the flow over the step; the loads on the step's moving bodies
  /// go into `loads` (empty on entry).
  virtual void advance(const FluidStep &step, PointsView force_density_n_per_measure, std::vector<BodyLoad> &loads) = 0;
};

} // namespace fsi::participant
