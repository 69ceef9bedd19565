#pragma once
// The coupler's results file, coupling.h5: per step, the time, the timing breakdown
// (StepTimings, seconds), the total force the structures exert on the fluid (N), the coupling
// iterations of the step and their last relative residual (implicit coupling); as
// attributes, the effective configuration, the code version and the run status. Flushed at
// most once a second (a flush of 11 datasets costs about 0.1 ms, as much as a whole coupled
// step of 10^3 points) and at every status change: a run that dies loses at most the last
// second of timings. The root attribute `complete_steps`, rewritten after each flush, is the
// number of rows a reader may trust (python/fsi/results_file.py).

#include "StepTimings.hpp"
#include "hdf5/ExtendableDataset.hpp"

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fsi::coupler {

class CouplingResults {
public:
  CouplingResults(const std::filesystem::path &h5_path, const std::string &config_yaml, const std::string &version);
  /// A restart's results: the existing file, its rows of steps up to `last_step` kept, the
  /// rest dropped, and the run appends from there. Throws std::runtime_error naming the file
  /// when it cannot be opened or lacks a step up to `last_step`.
  CouplingResults(const std::filesystem::path &h5_path, long last_step);
  ~CouplingResults();

  /// iterations: the coupling iterations of the step (1: explicit); residual: |F~ - F| / |F~| of
  /// its last iteration (implicit coupling; 0 for explicit).
  void write_step(long step, double time_s, const StepTimings &timings, const double total_force_on_fluid_n[3],
                  int iterations = 1, double residual = 0.0);
  /// Force (N) and torque (N m) of the fluid on a rigid body at this step, in
  /// /rigid_bodies/<name>/ (created at the first call for that name).
  void write_rigid_body_load(const std::string &name, const double force_n[3], const double torque_n_m[3]);
  /// Writes what is buffered to the file (at every checkpoint: the file then holds every step
  /// up to it).
  void flush();
  /// "running", "completed", "failed: ...", "interrupted".
  void set_status(const std::string &status);
  const std::filesystem::path &path() const { return path_; }

private:
  std::filesystem::path path_;
  hdf5::H5Handle file_, timings_group_;
  std::unique_ptr<hdf5::ExtendableDataset> step_, time_, force_, iterations_, residual_;
  std::vector<hdf5::ExtendableDataset> timings_;
  struct BodySeries {
    hdf5::H5Handle group;
    std::unique_ptr<hdf5::ExtendableDataset> force, torque;
  };
  hdf5::H5Handle bodies_group_;
  std::map<std::string, BodySeries> bodies_;
  std::chrono::steady_clock::time_point last_flush_ = std::chrono::steady_clock::now();
  hsize_t kept_rows_ = 0; ///< a restart: rows kept of the run it resumes (rigid-body series opened lazily)
};

} // namespace fsi::coupler
