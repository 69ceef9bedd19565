#pragma once
// The coupler daemon's run: it binds the endpoint of the case, accepts the fluid and structure
// participants (protocol version and case fingerprint must match), then drives the coupling
// sequence of section 2.3 every step, writes coupling.h5 (timings, total FSI force) and logs
// progress with an ETA. On any failure it tells the participants to stop, keeps what it wrote,
// and returns non-zero naming the participant and the step.

#include "CouplingLaw.hpp"
#include "CouplingResults.hpp"
#include "ParticipantTable.hpp"
#include "CouplingSetup.hpp"
#include "checkpoint/CheckpointSet.hpp"
#include "motion/RigidMotion.hpp"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

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
  void handshake();
  void receive_initial_state();
  void advance_one_step(long n);
  void interpolate_fluid_velocity(long n);
  void apply_coupling_law();
  void advance_fluid_and_structure(long n);

  // Helpers.
  int interrupted(long step);
  bool accept_hello(const proto::Incoming &incoming);
  void refuse(const std::string &peer, const std::string &message);
  void welcome(const std::string &id, bool with_structures, const std::string &part);
  /// A restart: the newest complete checkpoint set; takes the coupler's own part.
  void find_restart_set();
  /// Every participant's part, then the coupler's, then the manifest: the set of step n.
  void checkpoint(long n);
  proto::Message &await(const std::string &peer, proto::v2::Envelope::BodyCase body, long step, const std::string &what);
  void check_stability() const;
  /// run.stop_when_past holds for the structures' latest positions.
  bool structures_past_stop_plane() const;
  void record_step(long n);
  void record_rigid_body_loads(const proto::v2::AdvanceReply &reply);
  void report_progress(long n, bool force);
  void write_endpoint_file(const std::string &endpoint) const;

  CouplingSetup config_;
  std::filesystem::path output_dir_;
  std::string endpoint_override_, config_yaml_;
  long n_steps_ = 0;
  double dt_ = 0.0;

  std::unique_ptr<proto::CouplerChannel> channel_;
  std::unique_ptr<ParticipantTable> participants_;
  std::unique_ptr<CouplingResults> results_;
  std::unique_ptr<CouplingLaw> law_;
  std::string fluid_id_, structure_id_;
  std::vector<proto::v2::StructureTopology> topology_;
  std::vector<std::pair<std::string, std::shared_ptr<const motion::RigidMotion>>> moving_bodies_;

  // Lagrangian state of all structures, concatenated (N x 3, SI).
  PointArray x_now_, x_prev_, u_ib_;
  PointArray x_next_; ///< a structure reply, checked before it becomes X^{n+1}
  Eigen::VectorXd measures_;
  CouplingOutputs coupled_;

  proto::Message request_, fluid_advance_, structure_advance_; // headers reused step to step
  StepTimings timings_;
  StepTimings timings_sum_;   ///< since the last progress line
  long timings_count_ = 0;
  std::chrono::steady_clock::time_point start_, last_progress_;

  std::unique_ptr<checkpoint::CheckpointSet> checkpoints_;
  long checkpoint_every_ = 0;                          ///< steps (0: none)
  long first_step_ = 0;                                ///< 0, or the restart's step
  std::optional<checkpoint::CheckpointSet::Found> restart_set_;
};

} // namespace fsi::coupler
