#pragma once
// The checkpoints of the flow alone (a case without structures: no coupler to ask for them,
// docs/restart.md): every run.checkpoint_interval_s, at the run's end and when a signal stops
// it, every rank writes its fields and the master copies them into <output>/checkpoints/
// step-<n>/ (the OpenFOAM part, FoamCheckpoint) and completes the set's manifest. A restart
// takes the newest complete set, as a coupled run's does.

#include "checkpoint/CheckpointSet.hpp"
#include "fluid_adapter/OpenFoamFluidModel.hpp"

#include <filesystem>
#include <string>

namespace fsi::apps {

class FlowAloneCheckpoints {
public:
  /// every_steps: steps between sets (0: none). A run without checkpoints still resumes from
  /// none: `first_step` 0.
  FlowAloneCheckpoints(std::filesystem::path root, checkpoint::CaseIdentity identity, int keep, long every_steps,
                       long first_step);

  /// The step a restart resumes after (0: from the start).
  long first_step() const { return first_step_; }
  bool enabled() const { return every_ > 0; }
  /// Step n ends with a set: every interval, at the run's end, and when a signal stops the run.
  bool due(long n, long n_steps, bool stopping) const {
    return checkpoint::CheckpointSet::due(n, every_, n_steps, stopping);
  }
  /// The set of step n at time_s (every rank calls it; the master completes the manifest).
  void write(fluid::OpenFoamFluidModel &model, int rank, long n, double time_s) const;

private:
  checkpoint::CheckpointSet set_;
  long every_ = 0;
  long first_step_ = 0;
};

} // namespace fsi::apps
