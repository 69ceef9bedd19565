#pragma once
// The fluid's role in a coupled run: Participant's loop with two handlers, InterpolateRequest
// (U_ib at the points) and FluidAdvance (spread F_fsi, advance the flow, loads on the moving
// bodies), each translated into a FluidModel call. The same role serves the prescribed flow
// and the OpenFOAM solver.

#include "FluidModel.hpp"
#include "Participant.hpp"

#include <atomic>
#include <cstdint>
#include <vector>

namespace fsi::participant {

class FluidParticipant final : public Participant {
public:
  /// settings.stop_signal, when not set, is stop_signal().
  FluidParticipant(FluidModel &model, SessionSettings settings);

  /// Set by the signal handler of a fluid process.
  static std::atomic<int> &stop_signal();

private:
  void interpolate(const proto::Message &request);
  void advance(const proto::Message &request);
  /// Tells the model which points are idle when the coupler's list of idle structures changes.
  void take_idle(const google::protobuf::RepeatedField<std::uint32_t> &idle_structures);

  FluidModel &model_;
  std::vector<std::uint32_t> idle_structures_; ///< the last list the model was told
  proto::Message interpolate_reply_, advance_reply_; // reused: no per-step allocation of the headers
  std::vector<BodyLoad> loads_;
};

} // namespace fsi::participant
