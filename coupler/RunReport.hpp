#pragma once
// What a coupled run reports as it goes: each step's timings, coupling iterations and total
// FSI force into coupling.h5, and a progress line every run.progress_interval_s (step, time,
// wall time, ETA, where the time of a step went, the scheme's iterations).

#include "CouplingResults.hpp"
#include "StepScheme.hpp"
#include "StepTimings.hpp"

#include <chrono>

namespace fsi::coupler {

class RunReport {
public:
  /// first_step: 0, or the step a restart resumes from (the ETA counts from there).
  RunReport(CouplingResults &results, long n_steps, double time_step_s, double progress_interval_s, long first_step);

  /// The run's steps start now (the ETA and the first interval count from here).
  void start();
  /// Step n ended: its timings, the scheme's iterations and residual, and the total force
  /// sum_i F_fsi,i A_i (N) of `force_density` over the point measures.
  void record_step(long n, const StepTimings &timings, const StepScheme &scheme, const PointArray &force_density,
                   const Eigen::VectorXd &measures);
  /// The progress line, when the interval has passed or `force`.
  void progress(long n, bool force, const StepScheme &scheme);

private:
  CouplingResults &results_;
  long n_steps_, first_step_;
  double dt_, interval_s_;
  StepTimings sum_; ///< since the last progress line
  long count_ = 0, iterations_ = 0;
  std::chrono::steady_clock::time_point start_, last_;
};

} // namespace fsi::coupler
