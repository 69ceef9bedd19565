#pragma once
// The checkpoints of a coupled run (docs/restart.md): which steps are checkpointed
// (run.checkpoint_interval_s), the set of step n (every participant's part, then the coupler's
// own, then the manifest) and, for --restart, the newest complete set to resume from.

#include "CouplingResults.hpp"
#include "CouplingSetup.hpp"
#include "ParticipantTable.hpp"
#include "Roster.hpp"
#include "checkpoint/CheckpointSet.hpp"
#include "checkpoint/StateArchive.hpp"

#include <filesystem>
#include <optional>

namespace fsi::coupler {

class RunCheckpoints {
public:
  RunCheckpoints(const std::filesystem::path &output_dir, const CouplingSetup &setup);

  /// --restart: finds the newest complete set (its step becomes first_step()); throws
  /// HandshakeRefused when there is none, or when it is of the run's last step.
  void find_restart(long n_steps);
  /// The set a restart resumes from (empty: a new run).
  const std::optional<checkpoint::CheckpointSet::Found> &restart() const { return restart_; }
  /// The coupler's own part of the restart's set.
  checkpoint::StateArchive restart_state() const;
  long first_step() const { return first_step_; }
  bool enabled() const { return every_ > 0; }
  /// Step n ends with a set: every interval, at the run's end (a later --restart with a later
  /// end time runs further), and when a signal stops the run.
  bool due(long n, long n_steps, bool stopping) const {
    return checkpoint::CheckpointSet::due(n, every_, n_steps, stopping);
  }
  /// The set of step n: asks both participants for their parts and waits for them
  /// (coupling.step_timeout_s), writes `own` (the coupler's part), flushes coupling.h5 and
  /// completes the manifest.
  void write(long n, double time_s, ParticipantTable &participants, const Roster &roster,
             const checkpoint::StateArchive &own, CouplingResults &results);

private:
  /// The participants' parts of step n, in whichever order they come.
  std::vector<checkpoint::CheckpointPart> collect_parts(long n, ParticipantTable &participants, const Roster &roster);

  checkpoint::CheckpointSet set_;
  long every_ = 0; ///< steps (0: none)
  double step_timeout_s_ = 0.0;
  long first_step_ = 0;
  std::optional<checkpoint::CheckpointSet::Found> restart_;
};

} // namespace fsi::coupler
