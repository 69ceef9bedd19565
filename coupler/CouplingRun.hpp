#pragma once
// The coupler daemon's run: it binds the endpoint of the case, admits the fluid and structure
// participants (Admission: protocol version and case fingerprint must match), then drives the
// coupling sequence of section 2.3 every step (a StepScheme over the StepExchange with both),
// checkpoints (RunCheckpoints), writes coupling.h5 and logs progress with an ETA (RunReport).
// On any failure it tells the participants to stop, keeps what it wrote, and returns non-zero
// naming the participant and the step.

#include "CouplingLaw.hpp"
#include "CouplingResults.hpp"
#include "CouplingSetup.hpp"
#include "ParticipantTable.hpp"
#include "Roster.hpp"
#include "RunCheckpoints.hpp"
#include "RunReport.hpp"
#include "StepExchange.hpp"
#include "StepScheme.hpp"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

namespace fsi::coupler {

class CouplingRun {
public:
  /// endpoint_override: "" to use coupling.endpoint of the case.
  CouplingRun(CouplingSetup setup, std::filesystem::path output_dir, std::string endpoint_override);
  ~CouplingRun();

  /// Returns the exit code: 0 completed, 1 a participant failed, 2 refused handshake, 130 interrupted.
  int run();

  /// Set by the signal handler of the process (SIGINT, SIGTERM).
  static std::atomic<int> &stop_signal();

private:
  // The run, step by step.
  void open();
  void admit();
  void receive_initial_state();
  /// The steps from the first to the end (or run.stop_when_past, or a stop signal at a step
  /// boundary); `step` follows the loop (the failure handlers name it). Returns the exit code.
  int run_steps(long &step);
  /// Section 2.3, one step: the scheme advances both participants, then the rigid-body loads.
  void advance_one_step(long n);

  // Helpers.
  int completed(long n_done);
  int failed(const std::string &participant, const std::string &what, long step);
  int refused(const std::string &what, long step);
  int interrupted(long step);
  /// A stop signal ended the run at the boundary after step n (its checkpoint written).
  int interrupted_at_boundary(long n);
  /// How long a stop signal lets the participants finish the step and its checkpoint.
  static constexpr std::chrono::milliseconds clean_stop_grace{60000};
  /// A restart: the coupler's own state (X^k, X^{k-1}, the law's and the scheme's) from its
  /// part of the set; the structure's X^k must be the same, bit for bit.
  void resume_state(const proto::Message &message);
  /// The coupler's part of the set of step n.
  void checkpoint(long n);
  /// Logs each structure's stability limit of the law; beyond it (explicit), warns and keeps
  /// the note for the error should the run fail.
  void check_stability();
  /// run.stop_when_past holds for the structures' latest positions.
  bool structures_past_stop_plane() const;
  /// The fluid's forces on the rigid bodies of the step's (last) advance, into coupling.h5.
  void record_rigid_body_loads();
  void write_endpoint_file(const std::string &endpoint) const;
  MovingBodies moving_bodies() const;

  CouplingSetup config_;
  std::filesystem::path output_dir_;
  std::string endpoint_override_;
  long n_steps_ = 0;
  double dt_ = 0.0;

  std::unique_ptr<proto::CouplerChannel> channel_;
  std::unique_ptr<ParticipantTable> participants_;
  std::unique_ptr<RunCheckpoints> checkpoints_;
  std::unique_ptr<CouplingResults> results_;
  std::unique_ptr<CouplingLaw> law_;
  std::unique_ptr<StepScheme> scheme_;
  Roster roster_;
  std::unique_ptr<StepExchange> exchange_;
  std::unique_ptr<RunReport> report_;
  std::string stability_note_; ///< explicit beyond the law's limit: the likely cause of a failure
};

} // namespace fsi::coupler
