#pragma once
// The coupler daemon's run: it binds the endpoint of the case, accepts the fluid and structure
// participants (protocol version and case fingerprint must match), then drives the coupling
// sequence of section 2.3 every step, writes coupling.h5 (timings, total FSI force) and logs
// progress with an ETA. On any failure it tells the participants to stop, keeps what it wrote,
// and returns non-zero naming the participant and the step.

#include "Accelerator.hpp"
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
  /// Implicit coupling: step n advanced again and again until the law at its end agrees.
  void advance_implicit_step(long n);
  /// U_ib at `points` at time t (rigid bodies at t), into u_ib_.
  void interpolate_fluid_velocity(long n, double t, const PointArray &points);
  /// The law with X^n = x_now_, X^{n-1} = x_prev_, U_ib = u_ib_.
  void apply_coupling_law(CouplingOutputs &out);
  /// Both participants advance step n under coupled_ (repeat: again, from its start).
  void advance_fluid_and_structure(long n, bool repeat);

  // Helpers.
  int interrupted(long step);
  /// A stop signal ended the run at the boundary after step n (its checkpoint written).
  int interrupted_at_boundary(long n);
  /// How long a stop signal lets the participants finish the step and its checkpoint.
  static constexpr std::chrono::milliseconds clean_stop_grace{60000};
  bool accept_hello(const proto::Incoming &incoming);
  void refuse(const std::string &peer, const std::string &message);
  void welcome(const std::string &id, bool with_structures, const std::string &part);
  /// A restart: the newest complete checkpoint set; takes the coupler's own part.
  void find_restart_set();
  /// Every participant's part, then the coupler's, then the manifest: the set of step n.
  void checkpoint(long n);
  proto::Message &await(const std::string &peer, proto::v2::Envelope::BodyCase body, long step, const std::string &what);
  /// Logs each structure's stability limit of the law; beyond it (explicit), warns and keeps
  /// the note for the error should the run fail.
  void check_stability();
  /// run.stop_when_past holds for the structures' latest positions.
  bool structures_past_stop_plane() const;
  void record_step(long n);
  /// The fluid's forces on the rigid bodies of the step's (last) advance, into coupling.h5.
  void record_rigid_body_loads();
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

  proto::Message request_, fluid_advance_, fluid_advance_spread_, structure_advance_; // headers reused step to step

  // Implicit coupling (coupling.scheme: implicit).
  bool implicit_ = false;
  std::unique_ptr<Accelerator> accelerator_;
  CouplingOutputs evaluated_;         ///< F~ = H(F): the law at the end of the step
  PointArray guess_;                  ///< the next step's F_0
  bool have_guess_ = false;
  Eigen::VectorXd next_force_;
  int iterations_ = 1;                ///< of the last step
  double residual_ = 0.0;             ///< |F~ - F| / |F~| of the last step's last iteration
  long iterations_sum_ = 0;           ///< since the last progress line
  long unconverged_steps_ = 0;
  std::string stability_note_; ///< explicit beyond the law's limit: the likely cause of a failure
  google::protobuf::RepeatedPtrField<proto::v2::RigidBodyLoad> fluid_loads_; ///< of the step's last advance
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
