#include "FlowAloneRun.hpp"

#include "common/ExitCodes.hpp"
#include "common/FormatDuration.hpp"
#include "participant/FluidParticipant.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

namespace fsi::apps {

std::vector<double> uniform_steps(double time_step_s, double end_time_s) {
  // Whole steps of exactly dt (a run stopped early by --end-time takes the same steps as the
  // longer run, so that its restart continues it exactly); only a true remainder is shorter.
  const double n_exact = end_time_s / time_step_s;
  auto n = static_cast<long>(std::llround(n_exact));
  if (std::abs(n_exact - static_cast<double>(n)) > 1e-9 * std::max(1.0, n_exact))
    n = static_cast<long>(std::ceil(n_exact));
  std::vector<double> steps(static_cast<std::size_t>(std::max(0L, n)), time_step_s);
  if (!steps.empty())
    steps.back() = std::min(time_step_s, end_time_s - time_step_s * static_cast<double>(n - 1));
  if (!steps.empty() && std::abs(steps.back() - time_step_s) <= 1e-9 * time_step_s)
    steps.back() = time_step_s;
  return steps;
}

std::vector<double> resumed_steps(double time_step_s, double end_time_s, long resumed_step, double resumed_at_s) {
  std::vector<double> steps = uniform_steps(time_step_s, end_time_s);
  double scheduled = 0.0;
  for (long k = 0; k < resumed_step && k < static_cast<long>(steps.size()); ++k)
    scheduled += steps[static_cast<std::size_t>(k)];
  if (std::abs(scheduled - resumed_at_s) <= 1e-6 * time_step_s)
    return steps; // the set is where the schedule puts it: the uninterrupted run's steps
  steps.assign(static_cast<std::size_t>(resumed_step), resumed_at_s / static_cast<double>(resumed_step));
  for (const double dt : uniform_steps(time_step_s, end_time_s - resumed_at_s))
    steps.push_back(dt);
  return steps;
}

namespace {

std::string loads_header(std::size_t n_bodies) {
  std::string header = "time_s";
  for (std::size_t b = 0; b < n_bodies; ++b)
    for (const char *q : {"fx_n", "fy_n", "fz_n", "tx_n_m", "ty_n_m", "tz_n_m"})
      header += ",body" + std::to_string(b) + "." + q;
  return header;
}

/// The torque of each named part of each body split by part (OpenFoamFluidModel::split_loads_by_part).
std::string parts_header(const fluid::OpenFoamFluidModel &model, std::size_t n_bodies) {
  std::string header = "time_s";
  for (std::size_t b = 0; b < n_bodies; ++b)
    for (const auto &part : model.part_names(b))
      for (const char *q : {"tx_n_m", "ty_n_m", "tz_n_m"})
        header += ",body" + std::to_string(b) + "." + part + "." + q;
  return header;
}

bool has_parts(const fluid::OpenFoamFluidModel &model, std::size_t n_bodies) {
  for (std::size_t b = 0; b < n_bodies; ++b)
    if (!model.part_names(b).empty())
      return true;
  return false;
}

/// Keeps the rows of `path` whose time (first column) is at most until_s, under `header`; a line
/// cut short by a stopped run goes too. A table a build with fewer columns wrote (its header a
/// prefix of this one's) gets the new columns as nan in its kept rows. Written aside and
/// renamed: the old file or the new.
void keep_rows_until(const std::filesystem::path &path, double until_s, const std::string &header) {
  std::ifstream in(path);
  const auto aside = std::filesystem::path(path.string() + ".restart");
  std::ofstream out(aside);
  std::string line, padding;
  for (bool first = true; std::getline(in, line); first = false) {
    if (first) {
      if (line != header && header.rfind(line + ",", 0) == 0)
        for (const char c : header.substr(line.size()))
          if (c == ',')
            padding += ",nan";
      out << (padding.empty() ? line : header) << "\n";
      continue;
    }
    if (in.eof() || std::strtod(line.c_str(), nullptr) > until_s)
      break; // in.eof(): the last line had no newline (written in part)
    out << line << padding << "\n";
  }
  out.close();
  std::filesystem::rename(aside, path);
}

/// One table of the run (folder/<name>): new with its header, or on a restart the rows up to
/// the resumed time kept and continued.
void open_table(std::ofstream &table, const std::filesystem::path &path, const std::string &header,
                double resumed_until_s) {
  if (resumed_until_s >= 0.0 && std::filesystem::exists(path)) {
    keep_rows_until(path, resumed_until_s, header);
    table.open(path, std::ios::app);
    return;
  }
  table.open(path);
  table << header << "\n";
}

/// The master's tables: forces.csv, parts.csv, parts_staircase.csv, timings.csv, penalization.csv.
class LoadTables {
public:
  LoadTables(std::filesystem::path folder, double resumed_until_s)
      : folder_(std::move(folder)), resumed_until_s_(resumed_until_s) {}

  void write(const fluid::OpenFoamFluidModel &model, double time_s, const std::vector<fluid::rigid::BodyLoad> &loads) {
    if (!timings_.is_open())
      open(model, loads.size());
    const auto &split = model.last_step_timings();
    timings_ << time_s << "," << split.penalization_s << "," << split.fluid_solve_s << "," << split.loads_s << "\n";
    if (!forces_.is_open())
      return;
    forces_ << time_s;
    for (const auto &load : loads)
      forces_ << "," << load.force_n.x() << "," << load.force_n.y() << "," << load.force_n.z() << ","
              << load.torque_n_m.x() << "," << load.torque_n_m.y() << "," << load.torque_n_m.z();
    forces_ << "\n";
    if (parts_.is_open()) {
      write_part_torques(parts_, time_s, model.last_step_part_loads());
      write_part_torques(staircase_, time_s, model.last_step_part_staircase_loads());
    }
    const auto &sw = model.last_step_switching();
    switching_ << time_s << "," << sw.cells_switched_on << "," << sw.cells_switched_off << "," << sw.power_w << ","
               << sw.transpiration_m3_per_s << "," << sw.transpiration_power_w << "," << sw.held_fluid_power_w << "\n";
  }

  void flush() {
    for (auto *table : {&forces_, &timings_, &switching_, &parts_, &staircase_})
      table->flush();
  }

private:
  static void write_part_torques(std::ofstream &table, double time_s,
                                 const std::vector<std::vector<fluid::rigid::BodyLoad>> &loads) {
    table << time_s;
    for (const auto &body_parts : loads)
      for (const auto &part : body_parts)
        table << "," << part.torque_n_m.x() << "," << part.torque_n_m.y() << "," << part.torque_n_m.z();
    table << "\n";
  }

  void open(const fluid::OpenFoamFluidModel &model, std::size_t n_bodies) {
    open_table(timings_, folder_ / "timings.csv", "time_s,penalization_s,fluid_solve_s,loads_s", resumed_until_s_);
    if (n_bodies == 0)
      return;
    open_table(forces_, folder_ / "forces.csv", loads_header(n_bodies), resumed_until_s_);
    if (has_parts(model, n_bodies)) {
      open_table(parts_, folder_ / "parts.csv", parts_header(model, n_bodies), resumed_until_s_);
      open_table(staircase_, folder_ / "parts_staircase.csv", parts_header(model, n_bodies), resumed_until_s_);
    }
    open_table(switching_, folder_ / "penalization.csv",
               "time_s,cells_switched_on,cells_switched_off,switching_power_w,transpiration_m3_per_s,"
               "transpiration_power_w,held_fluid_power_w",
               resumed_until_s_);
  }

  std::filesystem::path folder_;
  double resumed_until_s_; ///< a restart's time (the rows up to it kept); < 0: a new run
  std::ofstream forces_, timings_, switching_, parts_, staircase_;
};

/// Whether any rank was told to stop (a signal reaches the ranks at different steps; the
/// checkpoint they then write together must be of one step).
bool stop_requested(const fluid::FoamFlow &flow) {
  double stop = participant::FluidParticipant::stop_signal() != 0 ? 1.0 : 0.0;
  flow.sum_over_ranks(&stop, 1);
  return stop > 0.0;
}

/// Fault hook of the reliability tests: FSI_FAULT_STEP_SLEEP_S=S makes every step S seconds
/// longer (a pump's step, in a test's small case).
void sleep_if_asked() {
  static const char *asked = std::getenv("FSI_FAULT_STEP_SLEEP_S");
  if (asked)
    std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(asked)));
}

} // namespace

int run_flow_alone(fluid::OpenFoamFluidModel &model, fluid::FoamFlow &flow, const FlowAloneSchedule &schedule) {
  using Clock = std::chrono::steady_clock;
  const auto &steps = schedule.step_sizes_s;
  const auto n_steps = static_cast<long>(steps.size());
  const auto *checkpoints = schedule.checkpoints;
  const long first = checkpoints ? checkpoints->first_step() : 0;
  double end = 0.0, t = 0.0;
  for (std::size_t k = 0; k < steps.size(); ++k)
    (static_cast<long>(k) < first ? t : end) += steps[k];
  end += t;
  // A restart's tables keep their rows to its time (written to 6 digits: within a quarter step).
  LoadTables tables(schedule.folder, first > 0 ? t + 0.25 * steps[static_cast<std::size_t>(first)] : -1.0);
  model.split_loads_by_part(); // every rank: the split is collective
  const auto start = Clock::now();
  auto last_report = start;
  for (long step = first; step < n_steps; ++step) {
    if (stop_requested(flow)) {
      spdlog::warn("{} interrupted at t = {:.6g} s after step {}", schedule.label, t, step);
      if (flow.rank() == 0)
        tables.flush(); // the set's tables hold its step
      if (checkpoints && checkpoints->enabled() && step > first)
        checkpoints->write(model, flow.rank(), step, t);
      else
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
    sleep_if_asked();
    if (flow.rank() == 0)
      tables.write(model, flow.time_s(), loads);
    if (checkpoints && checkpoints->due(step + 1, n_steps, false)) {
      if (flow.rank() == 0)
        tables.flush(); // the set's tables hold its step
      checkpoints->write(model, flow.rank(), step + 1, t);
    }
    const auto now = Clock::now();
    if (flow.rank() == 0 && (now - last_report > std::chrono::seconds(5) || step + 1 == n_steps)) {
      last_report = now;
      tables.flush();
      const double wall = std::chrono::duration<double>(now - start).count();
      const double done = static_cast<double>(step + 1 - first);
      const double eta = wall / done * static_cast<double>(n_steps - step - 1);
      spdlog::info("{}: t = {:.4g} of {:.4g} s, step {}/{}, {:.1f} ms/step, ETA {}", schedule.label, flow.time_s(), end,
                   step + 1, n_steps, 1e3 * wall / done, common::format_duration(eta));
    }
  }
  flow.write_now();
  return 0;
}

} // namespace fsi::apps
