#include "StructureRun.hpp"

#include "common/ConfigError.hpp"
#include "common/FormatDuration.hpp"
#include "common/Logging.hpp"
#include "common/ExitCodes.hpp"

#include <spdlog/spdlog.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <fstream>

namespace fsi::structure {

namespace {
std::atomic<int> received_stop_signal{0};
extern "C" void on_stop_signal(int signal) { received_stop_signal = signal; }

} // namespace

StructureRun::StructureRun(StructureSetup config, std::filesystem::path case_dir, std::filesystem::path output_dir)
    : config_(std::move(config)), case_dir_(std::move(case_dir)), output_dir_(std::move(output_dir)) {
  config_yaml_ = config_.case_yaml;
}

StructureRun::~StructureRun() = default;

std::vector<std::string> StructureRun::time_step_warnings(const Scene &scene, double time_step_s) {
  std::vector<std::string> warnings;
  for (const auto &s : scene.structures()) {
    const double ds = s->lagrangian_spacing_m(), ratio = ds / time_step_s;
    const double wave_speed = s->tension_wave_speed_m_per_s();
    if (!s->explicit_stretching()) {
      if (ratio < 100.0)
        warnings.push_back(fmt::format("structure '{}': Delta s / Delta t = {:.4g} m/s is below 100 m/s, the rule of "
                                       "section 2.2; solver.tension takes the stretching implicitly, so stretching waves (speed {:.4g} "
                                       "m/s) do not limit the step, but accuracy does: compare with a smaller step.",
                                       s->name(), ratio, wave_speed));
      continue;
    }
    if (ratio < wave_speed)
      warnings.push_back(fmt::format(
          "structure '{}': Delta s / Delta t = {:.4g} m/s is below the stretching-wave speed sqrt(2 phi / rho_1) = "
          "{:.4g} m/s: the semi-implicit step of Eq. (4) is expected to diverge. Use run.time_step_s <= {:.3g} s, or "
          "a smaller tension coefficient, or a coarser Lagrangian grid.",
          s->name(), ratio, wave_speed, ds / wave_speed));
    else if (ratio < 100.0)
      warnings.push_back(fmt::format(
          "structure '{}': Delta s / Delta t = {:.4g} m/s is below 100 m/s, the rule of section 2.2 (Delta s = "
          "{:.4g} m); it stays above the stretching-wave speed {:.4g} m/s, so the step should be stable.",
          s->name(), ratio, ds, wave_speed));
  }
  return warnings;
}

void StructureRun::open_results() {
  std::filesystem::create_directories(output_dir_);
  std::ofstream(output_dir_ / "config.effective.yaml") << config_yaml_ << "\n";
  results_ = std::make_unique<output::ResultsWriter>(output_dir_ / "structure.h5", output_dir_ / "structure.xdmf",
                                                     output::RunMetadata{config_yaml_, FSI_VERSION});
  for (const auto &s : scene_->structures())
    results_->add_structure({s->name(), s->model(), s->grid_shape().first, s->grid_shape().second});
  open_probes();
}

/// The probes of the case in the HDF5 file and in probes.csv; without probes, no /probes
/// group and no probes.csv (one left by an earlier run in this folder is removed).
void StructureRun::open_probes() {
  const auto csv_path = output_dir_ / "probes.csv";
  probes_ = std::make_unique<ProbeSet>(ProbeSet::for_structures(config_.probes, scene_->structures()));
  if (probes_->empty()) {
    std::filesystem::remove(csv_path);
    return;
  }
  for (const std::string &name : probes_->names())
    results_->add_probe(name);
  probe_csv_ = std::make_unique<output::ProbeCsv>(csv_path, probes_->names());
}

std::vector<output::ProbeState> StructureRun::probe_states() const {
  std::vector<output::ProbeState> states;
  for (const ProbeSample &sample : probes_->sample(scene_->structures()))
    states.push_back({sample.position_m, sample.velocity_m_per_s});
  return states;
}

void StructureRun::write_state(long step) {
  output::StepRecord record{step, scene_->time_s(), {}, probe_states()};
  for (const auto &s : scene_->structures()) {
    const StructureEnergy e = s->energy();
    record.structures.push_back(
        {&s->positions_m(), &s->velocities_m_per_s(), s->max_stretch_ratio(), e.kinetic_j, e.elastic_j, e.potential_j});
  }
  results_->write_step(record);
  if (probe_csv_)
    probe_csv_->append(record.time_s, record.probes);
  last_written_step_ = step;
}

std::optional<Divergence> StructureRun::find_divergence(long step) const {
  for (const auto &s : scene_->structures()) {
    const bool finite = s->positions_m().allFinite() && s->velocities_m_per_s().allFinite();
    const double stretch = finite ? s->max_stretch_ratio() : NAN;
    Eigen::Index fastest = 0;
    const double speed = finite ? std::sqrt(s->velocities_m_per_s().rowwise().squaredNorm().maxCoeff(&fastest)) : NAN;
    if (finite && stretch <= s->stretch_limit() && speed <= s->speed_limit_m_per_s())
      continue;
    const bool too_fast = finite && stretch <= s->stretch_limit();
    const int point = too_fast ? static_cast<int>(fastest) : s->worst_point();
    std::string message = "step " + std::to_string(step) + " (t = " + std::to_string(scene_->time_s()) +
                          " s): structure '" + s->name() + "', " + s->describe_point(point) + ": ";
    if (!finite)
      message += "position is not finite";
    else if (too_fast)
      message += "speed " + std::to_string(speed) + " m/s exceeds solver.max_speed_m_per_s = " +
                 std::to_string(s->speed_limit_m_per_s());
    else
      message += "stretch ratio " + std::to_string(stretch) + " exceeds solver.max_stretch_ratio = " +
                 std::to_string(s->stretch_limit());
    message += too_fast ? ". Likely cause: a coupling too stiff for the time step (penalty law: K dt^2 / rho_1 must "
                          "stay below 2; lower coupling.stiffness_n_per_m_per_measure or run.time_step_s)"
                        : ". Likely cause: the time step is too large for the stiffness (tension coefficient) or the "
                          "Lagrangian spacing; reduce run.time_step_s (Delta s / Delta t above the stretching-wave "
                          "speed sqrt(2 phi / rho_1), rule of thumb 100 m/s) or the tension coefficient";
    return Divergence{message + "."};
  }
  return std::nullopt;
}

void StructureRun::report_progress(long step, long n_steps, bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && std::chrono::duration<double>(now - last_progress_).count() < config_.run.progress_interval_s)
    return;
  last_progress_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double eta = step > 0 ? wall * static_cast<double>(n_steps - step) / static_cast<double>(step) : 0.0;
  spdlog::info("step {}/{}  t = {:.5g} s ({:.0f}%)  wall {}  ETA {}  {:.3g} ms/step", step, n_steps, scene_->time_s(),
               100.0 * static_cast<double>(step) / static_cast<double>(n_steps), common::format_duration(wall),
               common::format_duration(eta), step > 0 ? 1e3 * wall / static_cast<double>(step) : 0.0);
}

void StructureRun::stop_with(const std::string &status, long last_good_step) {
  const double last_good_time = static_cast<double>(last_good_step) * config_.run.time_step_s;
  for (std::size_t i = 0; i < scene_->structures().size(); ++i)
    scene_->structures()[i]->restore_state(last_good_x_[i], last_good_v_[i], last_good_time);
  if (last_written_step_ != last_good_step)
    write_state(last_good_step);
  results_->set_status(status);
}

const std::atomic<int> &StructureRun::stop_signal() { return received_stop_signal; }

long StructureRun::n_steps() const { return config_.run.n_steps(); }

void StructureRun::start() {
  std::filesystem::create_directories(output_dir_);
  common::add_log_file(output_dir_ / "structure.log");
  spdlog::info("case {}: effective configuration\n{}", case_dir_.string(), config_yaml_);
  scene_ = std::make_unique<Scene>(config_);
  for (const auto &warning : time_step_warnings(*scene_, config_.run.time_step_s))
    spdlog::warn("{}", warning);
  open_results();
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  start_ = last_progress_ = std::chrono::steady_clock::now();
  write_state(0);
  last_good_x_.resize(scene_->structures().size());
  last_good_v_.resize(scene_->structures().size());
}

StepOutcome StructureRun::advance_step(long n, const std::vector<PointArray> *load_densities) {
  const long step = n + 1; // the state X^{n+1} this step reaches (saved states are numbered from X^0)
  for (std::size_t i = 0; i < scene_->structures().size(); ++i) {
    last_good_x_[i] = scene_->structures()[i]->positions_m();
    last_good_v_[i] = scene_->structures()[i]->velocities_m_per_s();
  }
  if (load_densities)
    scene_->advance(*load_densities);
  else
    scene_->advance();
  if (const auto divergence = find_divergence(step)) {
    spdlog::error("diverged at {}", divergence->message);
    stop_with("diverged: " + divergence->message, step - 1);
    spdlog::error("the last good state (step {}) is in {}", step - 1, results_->h5_path().string());
    return {StepOutcome::Kind::diverged, divergence->message};
  }
  if (received_stop_signal != 0) {
    write_state(step);
    results_->set_status("interrupted");
    spdlog::warn("interrupted by signal {} at step {}; results so far are in {}", int(received_stop_signal), step,
                 results_->h5_path().string());
    return {StepOutcome::Kind::interrupted, "interrupted by signal " + std::to_string(int(received_stop_signal))};
  }
  const long n_total = n_steps();
  const long output_every = std::max(1L, std::lround(config_.run.output_interval_s / config_.run.time_step_s));
  if (step % output_every == 0 || step == n_total)
    write_state(step);
  report_progress(step, n_total, step == n_total);
  return {};
}

void StructureRun::finish(const std::string &status, long n_completed) {
  if (last_written_step_ != n_completed)
    write_state(n_completed);
  results_->set_status(status);
}

bool StructureRun::structures_past_stop_plane() const {
  const auto &plane = config_.run.stop_when_past;
  if (!plane)
    return false;
  for (const auto &s : scene_->structures())
    if (!plane->all_past(s->positions_m()))
      return false;
  return !scene_->structures().empty();
}

int StructureRun::run() {
  start();
  const long n = n_steps();
  for (long step = 0; step < n; ++step) {
    const StepOutcome outcome = advance_step(step, nullptr);
    if (outcome.kind == StepOutcome::Kind::diverged)
      return common::exit_code_run_failed;
    if (outcome.kind == StepOutcome::Kind::interrupted)
      return common::exit_code_interrupted;
    if (structures_past_stop_plane()) {
      spdlog::info("every structure point is past run.stop_when_past at t = {} s (step {} of {}): the run ends here",
                   static_cast<double>(step + 1) * config_.run.time_step_s, step + 1, n);
      finish("completed", step + 1);
      break;
    }
  }
  results_->set_status("completed");
  spdlog::info("completed: {} saved steps in {} (open {} in ParaView)", results_->n_saved(),
               results_->h5_path().string(), (output_dir_ / "structure.xdmf").string());
  return 0;
}

} // namespace fsi::structure
