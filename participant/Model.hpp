#pragma once
// What every participant's model does besides its physics, in domain types: it describes
// itself, starts from the run plan, checkpoints and resumes, keeps and restores the state at
// the start of a step (implicit coupling), and finishes. FluidModel and StructureModel add the
// requests of their role; Participant calls them from its one loop (docs/protocol.md).

#include "RunPlan.hpp"
#include "checkpoint/CheckpointSet.hpp"

#include <stdexcept>
#include <string>

namespace fsi::participant {

/// A model's step diverged; the model has already kept its last good state and set its
/// status. The participant reports it to the coupler and exits 1.
class Diverged : public std::runtime_error {
public:
  explicit Diverged(const std::string &where) : std::runtime_error(where) {}
};

class Model {
public:
  virtual ~Model() = default;
  virtual std::string describe() const = 0;

  /// Once, after the handshake (before resume() on a restart).
  virtual void start(const RunPlan &plan) = 0;

  /// A restart from the checkpoint of step `step`: takes this model's part, whose checksum the
  /// coupler's manifest gives. By default a model cannot resume.
  virtual void resume(long step, const std::string & /*checksum*/) {
    throw std::runtime_error(describe() + " cannot resume from a checkpoint (step " + std::to_string(step) +
                             "): docs/restart.md");
  }
  /// A checkpoint after `n_completed` steps (docs/restart.md): writes this model's part of the
  /// set and returns its file name and checksum. By default a model cannot checkpoint.
  virtual checkpoint::CheckpointPart write_checkpoint(long n_completed) {
    throw std::runtime_error(describe() + " cannot checkpoint (step " + std::to_string(n_completed) +
                             "): docs/restart.md");
  }

  /// Implicit coupling: keep the state at the start of the step about to be advanced, and put
  /// it back before a repeated advance of the same step (or when the run ends on an iterate).
  virtual void save_step_start() {
    throw std::runtime_error(describe() + " cannot repeat a step: implicit coupling needs it");
  }
  virtual void restore_step_start() {
    throw std::runtime_error(describe() + " cannot repeat a step: implicit coupling needs it");
  }
  /// Implicit coupling: the coupler accepted step `step` (the next request is not a repeat of
  /// it). May throw Diverged.
  virtual void accept_step(long /*step*/) {}

  /// The run is over: write what is worth keeping.
  virtual void finish(const RunEnd &end) = 0;
};

} // namespace fsi::participant
