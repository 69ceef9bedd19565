#pragma once
// The fluid's side of a coupled run: joins the coupler, then answers each InterpolateRequest
// and FluidAdvance through a FluidModel until the coupler ends the run. The same loop serves
// the prescribed flow and the OpenFOAM solver.

#include "FluidModel.hpp"
#include "ParticipantSession.hpp"

#include <atomic>
#include <memory>

namespace fsi::proto {

class FluidParticipant {
public:
  FluidParticipant(FluidModel &model, SessionSettings settings);

  /// Returns the exit code: 0 completed, 1 stopped by the coupler or lost it (or the model
  /// failed), 130 interrupted.
  int run();

  /// Set by the signal handler of the process.
  static std::atomic<int> &stop_signal();

private:
  void interpolate(const Message &request);
  void advance(const Message &request);
  void checkpoint(const Message &request);

  FluidModel &model_;
  SessionSettings settings_;
  std::unique_ptr<ParticipantSession> session_;
  Message interpolate_reply_, advance_reply_; // reused: no per-step allocation of the headers
  Eigen::Index n_points_ = 0;
  bool implicit_ = false; ///< Welcome.implicit_coupling: advances may repeat a step
  long steps_ = 0;
};

} // namespace fsi::proto
