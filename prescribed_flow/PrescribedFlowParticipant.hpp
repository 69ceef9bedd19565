#pragma once
// The prescribed-flow fluid participant (fsi-prescribed-flow): it speaks the same protocol as
// the OpenFOAM fluid, but the velocity at the Lagrangian points comes from a FlowField, and the
// FSI force has no effect on the flow (one-way coupling). The coupler still records the total
// force the structures exert on the fluid (coupling.h5), which a two-way model would feel.

#include "FlowField.hpp"
#include "proto/ParticipantSession.hpp"

#include <memory>

namespace fsi::prescribed_flow {

class PrescribedFlowParticipant {
public:
  PrescribedFlowParticipant(std::unique_ptr<FlowField> flow, proto::SessionSettings settings);

  /// Returns the exit code: 0 completed, 1 stopped by the coupler or lost it, 130 interrupted.
  int run();

  /// Set by the signal handler of the process.
  static std::atomic<int> &stop_signal();

private:
  void interpolate(const proto::Envelope &request);
  void advance(const proto::Envelope &request);

  std::unique_ptr<FlowField> flow_;
  proto::SessionSettings settings_;
  std::unique_ptr<proto::ParticipantSession> session_;
  PointArray positions_, velocities_;
  proto::Envelope interpolate_reply_, advance_reply_; // reused: no per-step allocation
  long steps_ = 0;
};

} // namespace fsi::prescribed_flow
