#include "FlowAloneRun.hpp"

#include "common/ExitCodes.hpp"
#include "common/FormatDuration.hpp"
#include "participant/FluidParticipant.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <fstream>

namespace fsi::apps {

std::vector<double> uniform_steps(double time_step_s, double end_time_s) {
  std::vector<double> steps;
  double t = 0.0;
  while (t < end_time_s * (1.0 - 1e-12)) {
    const double dt = std::min(time_step_s, end_time_s - t);
    if (dt < 1e-9 * time_step_s)
      break;
    steps.push_back(dt);
    t += dt;
  }
  return steps;
}

namespace {

void write_header(std::ofstream &forces, std::size_t n_bodies) {
  forces << "time_s";
  for (std::size_t b = 0; b < n_bodies; ++b)
    for (const char *q : {"fx_n", "fy_n", "fz_n", "tx_n_m", "ty_n_m", "tz_n_m"})
      forces << ",body" << b << "." << q;
  forces << "\n";
}

/// The torque of each named part of each body split by part (OpenFoamFluidModel::split_loads_by_part).
void write_parts_header(std::ofstream &parts, const fluid::OpenFoamFluidModel &model, std::size_t n_bodies) {
  parts << "time_s";
  for (std::size_t b = 0; b < n_bodies; ++b)
    for (const auto &part : model.part_names(b))
      for (const char *q : {"tx_n_m", "ty_n_m", "tz_n_m"})
        parts << ",body" << b << "." << part << "." << q;
  parts << "\n";
}

bool has_parts(const fluid::OpenFoamFluidModel &model, std::size_t n_bodies) {
  for (std::size_t b = 0; b < n_bodies; ++b)
    if (!model.part_names(b).empty())
      return true;
  return false;
}

} // namespace

int run_flow_alone(fluid::OpenFoamFluidModel &model, fluid::FoamFlow &flow, const FlowAloneSchedule &schedule) {
  using Clock = std::chrono::steady_clock;
  const auto &steps = schedule.step_sizes_s;
  const auto n_steps = static_cast<long>(steps.size());
  double end = 0.0;
  for (const double dt : steps)
    end += dt;
  std::ofstream forces, timings, switching, parts;
  model.split_loads_by_part(); // every rank: the split is collective
  const auto start = Clock::now();
  auto last_report = start;
  double t = 0.0;
  for (long step = 0; step < n_steps; ++step) {
    if (participant::FluidParticipant::stop_signal() != 0) {
      spdlog::warn("{} interrupted at t = {:.6g} s", schedule.label, t);
      flow.write_now();
      return common::exit_code_interrupted;
    }
    std::vector<fluid::rigid::BodyLoad> loads;
    try {
      loads = model.advance_without_structure(step + 1, t, steps[static_cast<std::size_t>(step)]);
    } catch (const std::exception &) {
      // A diverged step has put the last good fields back (FoamFlow::advance): they go to disk,
      // as its message promises, before the error ends the run.
      flow.write_now();
      throw;
    }
    t += steps[static_cast<std::size_t>(step)];
    if (flow.rank() != 0)
      continue;
    if (step == 0 && !loads.empty()) {
      forces.open(schedule.folder / "forces.csv");
      write_header(forces, loads.size());
      if (has_parts(model, loads.size())) {
        parts.open(schedule.folder / "parts.csv");
        write_parts_header(parts, model, loads.size());
      }
    }
    if (step == 0) {
      timings.open(schedule.folder / "timings.csv");
      timings << "time_s,penalization_s,fluid_solve_s,loads_s\n";
      if (!loads.empty()) {
        switching.open(schedule.folder / "penalization.csv");
        switching << "time_s,cells_switched_on,cells_switched_off,switching_power_w,transpiration_m3_per_s,"
                     "transpiration_power_w\n";
      }
    }
    const auto &split = model.last_step_timings();
    timings << flow.time_s() << "," << split.penalization_s << "," << split.fluid_solve_s << "," << split.loads_s
            << "\n";
    if (forces.is_open()) {
      forces << flow.time_s();
      for (const auto &load : loads)
        forces << "," << load.force_n.x() << "," << load.force_n.y() << "," << load.force_n.z() << ","
               << load.torque_n_m.x() << "," << load.torque_n_m.y() << "," << load.torque_n_m.z();
      forces << "\n";
      if (parts.is_open()) {
        parts << flow.time_s();
        for (const auto &body_parts : model.last_step_part_loads())
          for (const auto &part : body_parts)
            parts << "," << part.torque_n_m.x() << "," << part.torque_n_m.y() << "," << part.torque_n_m.z();
        parts << "\n";
      }
      const auto &sw = model.last_step_switching();
      switching << flow.time_s() << "," << sw.cells_switched_on << "," << sw.cells_switched_off << "," << sw.power_w
                << "," << sw.transpiration_m3_per_s << "," << sw.transpiration_power_w << "\n";
    }
    const auto now = Clock::now();
    if (now - last_report > std::chrono::seconds(5) || step + 1 == n_steps) {
      last_report = now;
      forces.flush();
      timings.flush();
      switching.flush();
      parts.flush();
      const double wall = std::chrono::duration<double>(now - start).count();
      const double eta = wall / static_cast<double>(step + 1) * static_cast<double>(n_steps - step - 1);
      spdlog::info("{}: t = {:.4g} of {:.4g} s, step {}/{}, {:.1f} ms/step, ETA {}", schedule.label, flow.time_s(), end,
                   step + 1, n_steps, 1e3 * wall / static_cast<double>(step + 1), common::format_duration(eta));
    }
  }
  flow.write_now();
  return 0;
}

} // namespace fsi::apps
