#pragma once
// The structure solver as a participant of a coupled run (fsi-structure --coupled): it joins
// the coupler, sends its topology and initial state, then every step takes the load -F_fsi^n
// from the coupler, advances Eq. (4) and Eq. (11) through StructureRun (same guards, output
// and progress as a standalone run) and answers with X^{n+1}, V^{n+1}.

#include "StructureRun.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/ParticipantSession.hpp"

namespace fsi::structure {

class StructureParticipant {
public:
  StructureParticipant(StructureRun &run, proto::SessionSettings settings);

  /// Returns the exit code: 0 completed, 1 diverged or stopped by the coupler, 130 interrupted.
  int run();

private:
  std::vector<proto::v2::StructureTopology> topology() const;
  /// X (and V, for the initial state only) of all structures, concatenated.
  void send_state(std::uint64_t step, double solve_wall_s, bool with_velocity);
  void check_request(const proto::Envelope &request, long step) const;
  void unpack_loads(const proto::Message &request);
  /// The moving rigid surfaces at the end of the step, from the coupler (section 2.3).
  void take_rigid_poses(const proto::v2::StructureAdvance &advance);
  /// Our part of the checkpoint set after `step` steps; answers CheckpointDone.
  void write_checkpoint(const proto::Envelope &request, long step);

  StructureRun &run_;
  proto::SessionSettings settings_;
  std::unique_ptr<proto::ParticipantSession> session_;
  std::vector<PointArray> loads_;
  proto::Message reply_;
  PointArray gather_;
};

} // namespace fsi::structure
