#pragma once
// A standalone structure run (no fluid): builds the scene of a case, checks the time-step
// rule, steps to the end time with progress and ETA in the log, writes HDF5/XDMF results at
// the output interval, and stops cleanly (last good state on disk, status in the file) on
// divergence or on SIGINT/SIGTERM.

#include "CaseConfig.hpp"
#include "Scene.hpp"
#include "structure_solver/output/ResultsWriter.hpp"

#include <chrono>
#include <filesystem>
#include <optional>

namespace fsi::structure {

/// Why a run stopped early: the step, the structure, the point and a likely cause.
struct Divergence {
  std::string message;
};

class StructureRun {
public:
  StructureRun(CaseConfig config, std::filesystem::path case_dir);
  ~StructureRun();

  /// Runs to the end time; returns the process exit code (0 completed, 1 diverged,
  /// 130 interrupted).
  int run();

  /// Checks the rule Delta s / Delta t >= 100 m/s of section 2.2; returns the warnings.
  static std::vector<std::string> time_step_warnings(const Scene &scene, double time_step_s);

private:
  void open_results();
  void write_state(long step);
  std::optional<Divergence> find_divergence(long step) const;
  void report_progress(long step, long n_steps, bool force);
  void stop_with(const std::string &status, long last_good_step);

  CaseConfig config_;
  std::filesystem::path case_dir_, output_dir_;
  std::string config_yaml_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<output::ResultsWriter> results_;
  std::vector<PointArray> last_good_x_, last_good_v_;
  std::chrono::steady_clock::time_point start_, last_progress_;
  long last_written_step_ = -1;
};

} // namespace fsi::structure
