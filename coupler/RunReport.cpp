#include "RunReport.hpp"

#include "common/FormatDuration.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace fsi::coupler {

RunReport::RunReport(CouplingResults &results, long n_steps, double time_step_s, double progress_interval_s,
                     long first_step)
    : results_(results), n_steps_(n_steps), first_step_(first_step), dt_(time_step_s),
      interval_s_(progress_interval_s) {}

void RunReport::start() { start_ = last_ = std::chrono::steady_clock::now(); }

void RunReport::record_step(long n, const StepTimings &timings, const StepScheme &scheme,
                            const PointArray &force_density, const Eigen::VectorXd &measures) {
  double force[3] = {0.0, 0.0, 0.0};
  const Vec3 total = (force_density.array().colwise() * measures.array()).colwise().sum();
  for (int k = 0; k < 3; ++k)
    force[k] = total[k];
  results_.write_step(n, static_cast<double>(n) * dt_, timings, force, scheme.iterations(), scheme.residual());
  sum_ += timings;
  ++count_;
  iterations_ += scheme.iterations();
}

void RunReport::progress(long n, bool force, const StepScheme &scheme) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && std::chrono::duration<double>(now - last_).count() < interval_s_)
    return;
  last_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double eta = wall * static_cast<double>(n_steps_ - n) / static_cast<double>(std::max(1L, n - first_step_));
  const double per_step_ms = 1e3 / static_cast<double>(std::max(1L, count_));
  spdlog::info("step {}/{}  t = {:.5g} s ({:.0f}%)  wall {}  ETA {}  {:.3g} ms/step: fluid {:.3g}, structure {:.3g}, "
               "coupling overhead {:.3g}{}",
               n, n_steps_, static_cast<double>(n) * dt_, 100.0 * static_cast<double>(n) / static_cast<double>(n_steps_),
               common::format_duration(wall), common::format_duration(eta), per_step_ms * sum_.step_wall_s,
               per_step_ms * (sum_.interpolation_s + sum_.fluid_solve_s), per_step_ms * sum_.structure_solve_s,
               per_step_ms * sum_.overhead_s(),
               scheme.progress_note(static_cast<double>(iterations_) / static_cast<double>(std::max(1L, count_))));
  iterations_ = 0;
  sum_ = StepTimings{};
  count_ = 0;
}

} // namespace fsi::coupler
