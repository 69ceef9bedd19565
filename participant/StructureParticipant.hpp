#pragma once
// The structure's role in a coupled run: Participant's loop with one handler, StructureAdvance
// (the load -F_fsi^n and the moving surfaces at t^{n+1} in, X^{n+1} out), translated into a
// StructureModel call. At the handshake it declares the structures' topology and, once
// admitted, sends the initial state X^0, V^0 (on a restart, that of the checkpoint).

#include "Participant.hpp"
#include "StructureModel.hpp"

namespace fsi::participant {

class StructureParticipant final : public Participant {
public:
  StructureParticipant(StructureModel &model, SessionSettings settings);

private:
  std::vector<StructureTopology> declared_structures() const override { return topology_; }
  void joined() override;
  void advance(const proto::Message &request);
  /// X (and V, for the initial state only) of all structures, concatenated.
  void send_state(std::uint64_t step, double solve_wall_s, bool with_velocity);

  StructureModel &model_;
  std::vector<StructureTopology> topology_;
  proto::Message reply_;
};

} // namespace fsi::participant
