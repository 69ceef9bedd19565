#pragma once
// A standalone structure run (no fluid): builds the scene of a case, checks the time-step
// rule, steps to the end time with progress and ETA in the log, writes HDF5/XDMF results (and
// the probes of the case: /probes in the HDF5 file, probes.csv) at the output interval, and
// stops cleanly (last good state on disk, status in the file) on divergence or on SIGINT/SIGTERM.
// With run.checkpoint_interval_s it checkpoints its whole state (docs/restart.md); with
// StructureSetup::restart it resumes from the newest complete checkpoint, exactly.

#include "ProbeSet.hpp"
#include "Scene.hpp"
#include "StructureSetup.hpp"
#include "structure_solver/output/ProbeCsv.hpp"
#include "structure_solver/output/ResultsWriter.hpp"

#include "checkpoint/CheckpointSet.hpp"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <optional>

namespace fsi::structure {

/// Why a run stopped early: the step, the structure, the point and a likely cause.
struct Divergence {
  std::string message;
};

/// What one step came to.
struct StepOutcome {
  enum class Kind { advanced, diverged, interrupted } kind = Kind::advanced;
  std::string message; ///< for diverged: the step, structure, point and likely cause
};

class StructureRun {
public:
  /// output_dir: where results go (absolute, or relative to the working folder).
  StructureRun(StructureSetup setup, std::filesystem::path case_dir, std::filesystem::path output_dir);
  ~StructureRun();

  /// Runs to the end time; returns the process exit code (0 completed, 1 diverged,
  /// 130 interrupted).
  int run();

  // The pieces of run(), for drivers that take the loads from elsewhere (a coupled run):
  /// Where a restart's checkpoint comes from: the newest complete set of the results folder (a
  /// run of its own), or the one the coupler names in its Welcome (a coupled run).
  enum class Resume { newest_set, when_told };
  /// Builds the scene, opens the results, writes step 0, installs the stop-signal handler. On a
  /// restart of a run of its own: takes the state of the newest complete checkpoint, keeps the
  /// results up to it. With Resume::when_told the results wait for resume_from() or begin().
  void start(Resume resume = Resume::newest_set);
  /// A coupled run that starts from step 0 (after start(Resume::when_told)): the results from X^0.
  void begin_fresh();
  /// The first step to advance: 0, or the checkpoint's step on a restart.
  long first_step() const { return first_step_; }
  /// This process's part of a checkpoint set (structure.ckpt in `folder`): every structure's
  /// state after `n_completed` steps. Returns the part's file name and checksum.
  checkpoint::CheckpointPart write_checkpoint_part(const std::filesystem::path &folder, long n_completed) const;
  /// Takes the state of a checkpoint set's part (after start()'s scene is built), which must
  /// have `checksum` (empty: not checked).
  void read_checkpoint_part(const std::filesystem::path &folder, long n_completed, const std::string &checksum);
  /// A coupled restart, after start(Resume::when_told): the coupler has chosen the set of step
  /// `step`; takes its part (with the checksum the coupler's manifest gives) and keeps the
  /// results up to it.
  void resume_from(long step, const std::string &checksum);
  /// The run's checkpoint sets (<output>/checkpoints).
  const checkpoint::CheckpointSet &checkpoints() const { return *checkpoints_; }
  /// Advances step n, from t^n to t^{n+1} (0-based, as Envelope.step of the protocol), under
  /// the given load densities (nullptr: none), checks for divergence (then the last good state
  /// is on disk), writes results at the output interval. Saved states are numbered as the
  /// positions they hold: step n writes X^{n+1}.
  /// With record = false (implicit coupling: the step may be repeated) the output and progress
  /// of the step wait for accept_step(n), once the coupler has accepted it.
  StepOutcome advance_step(long n, const std::vector<PointArray> *load_densities, bool record = true);
  /// Implicit coupling: the coupler accepted step n (advanced with record = false): the
  /// stretch and speed guards, then its output and progress.
  StepOutcome accept_step(long n);
  /// Implicit coupling: keeps the state at the start of the step (what a checkpoint keeps, in
  /// memory), and puts it back before the step is advanced again.
  void save_step_start();
  void restore_step_start();
  /// After n_completed steps: writes X^{n_completed} if not written yet and sets the status.
  void finish(const std::string &status, long n_completed);
  /// run.stop_when_past holds for every structure (a run without a coupler checks it itself).
  bool structures_past_stop_plane() const;
  Scene &scene() { return *scene_; }
  long n_steps() const;
  const StructureSetup &config() const { return config_; }
  /// The signal (SIGINT, SIGTERM) that asked to stop, 0 if none.
  static const std::atomic<int> &stop_signal();

  /// Checks the rule Delta s / Delta t >= 100 m/s of section 2.2; returns the warnings.
  static std::vector<std::string> time_step_warnings(const Scene &scene, double time_step_s);

private:
  void open_results();
  void resume_results(long last_step);
  /// Steps between saved steps (run.output_interval_s in whole steps).
  long output_every() const;
  void checkpoint_alone(long n_completed);
  void open_probes();
  void write_state(long step);
  std::vector<output::ProbeState> probe_states() const;
  /// finite_only: only non-finite positions or velocities (an iterate of implicit coupling).
  std::optional<Divergence> find_divergence(long step, bool finite_only = false) const;
  StepOutcome diverged(const Divergence &divergence, long step);
  /// Output and progress of step n (when due).
  void record_step(long n);
  /// structure.h5's exit time and reason of structure i, gone.
  void record_exit(std::size_t i);
  void report_progress(long step, long n_steps, bool force);
  void stop_with(const std::string &status, long last_good_step);

  StructureSetup config_;
  std::filesystem::path case_dir_, output_dir_;
  std::string config_yaml_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<output::ResultsWriter> results_;
  std::unique_ptr<ProbeSet> probes_;
  std::unique_ptr<output::ProbeCsv> probe_csv_; ///< null without probes
  std::vector<PointArray> last_good_x_, last_good_v_;
  checkpoint::StateArchive step_start_; ///< implicit coupling: the state at the start of the step
  std::chrono::steady_clock::time_point start_, last_progress_;
  long last_written_step_ = -1;
  long first_step_ = 0;
  /// A run of its own stops within advance_step() on a signal; a coupled one leaves it to the coupler.
  bool stops_at_signal_ = true;
  std::unique_ptr<checkpoint::CheckpointSet> checkpoints_;
};

} // namespace fsi::structure
