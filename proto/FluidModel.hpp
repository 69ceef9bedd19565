#pragma once
// What a fluid participant computes, apart from the protocol: FluidParticipant runs the
// protocol loop and calls these. Models: the prescribed flow (prescribed_flow/) and the
// OpenFOAM solver (fluid_adapter/). All arrays are N x 3, SI, all structures concatenated.

#include "PackedPoints.hpp"
#include "Protocol.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace fsi::proto {

class FluidModel {
public:
  virtual ~FluidModel() = default;
  virtual std::string describe() const = 0;

  /// Once, after the handshake: time step, number of steps and the structures' topology
  /// (point measures, to turn force densities into forces).
  virtual void start(const v2::Welcome &welcome) = 0;

  /// U_ib^n: the fluid velocity at the points at time t (m/s), with the rigid-body poses at t.
  virtual void interpolate(const v2::InterpolateRequest &request, PointsView x_m, MutablePointsView u_m_per_s) = 0;

  /// The next advance() spreads at these points (X^n), not at those of the last interpolate()
  /// (the coupling law two_point_sets samples U_ib at its own points).
  virtual void spread_at(PointsView x_m) = 0;

  /// Spreads F_fsi^n (Eq. 8) at the points of the last interpolate() (or of spread_at()) and advances the flow
  /// from t to t + dt; may fill rigid_body_loads of the reply.
  virtual void advance(const v2::FluidAdvance &request, PointsView force_density_n_per_measure, v2::AdvanceReply &reply) = 0;

  /// A checkpoint after `n_completed` steps (docs/restart.md): writes this model's part of the
  /// set and returns its file name and checksum. By default a fluid cannot checkpoint.
  virtual std::pair<std::string, std::string> write_checkpoint(long n_completed) {
    throw std::runtime_error("this fluid (" + describe() + ") cannot checkpoint (step " + std::to_string(n_completed) +
                             "): docs/restart.md");
  }
  /// A restart from the checkpoint of step `step`: takes this model's part, whose checksum the
  /// coupler's manifest gives. By default a fluid cannot resume.
  virtual void resume(long step, const std::string & /*checksum*/) {
    throw std::runtime_error("this fluid (" + describe() + ") cannot resume from a checkpoint (step " +
                             std::to_string(step) + "): docs/restart.md");
  }

  /// Implicit coupling: keep the state at the start of the step about to be advanced (fields,
  /// old-time fields, time), and put it back before a repeated advance of the same step.
  virtual void save_step_start() {
    throw std::runtime_error("this fluid (" + describe() + ") cannot repeat a step: implicit coupling needs it");
  }
  virtual void restore_step_start() {
    throw std::runtime_error("this fluid (" + describe() + ") cannot repeat a step: implicit coupling needs it");
  }

  /// The run is over (success: completed): write what is worth keeping.
  virtual void finish(bool success) = 0;
};

} // namespace fsi::proto
