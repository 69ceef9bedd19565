#include "StructureRun.hpp"

#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CheckpointError.hpp"
#include "common/ConfigError.hpp"
#include "common/UserError.hpp"
#include "structure_solver/output/ResultsReplay.hpp"
#include "common/FormatDuration.hpp"
#include "common/Logging.hpp"
#include "common/ExitCodes.hpp"
#include "common/Version.hpp"

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

namespace {
constexpr char checkpoint_part[] = "structure.ckpt";
/// The results of the run being resumed, while a restart copies what it keeps of them (a restart
/// stopped during the copy finds them here).
constexpr char results_before_restart[] = "structure.before-restart.h5";
} // namespace

void StructureRun::open_results() {
  std::filesystem::create_directories(output_dir_);
  std::ofstream(output_dir_ / "config.effective.yaml") << config_yaml_ << "\n";
  results_ = std::make_unique<output::ResultsWriter>(output_dir_ / "structure.h5", output_dir_ / "structure.xdmf",
                                                     output::RunMetadata{config_yaml_, common::code_version()});
  for (std::size_t i = 0; i < scene_->structures().size(); ++i) {
    const auto &s = scene_->structures()[i];
    results_->add_structure({s->name(), s->model(), s->grid_shape().first, s->grid_shape().second,
                             scene_->life().release_time_s(i)});
    if (scene_->life().life(i) == Life::gone) // a restart: removed before its checkpoint
      record_exit(i);
  }
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

/// A restart's results: the saved steps up to `last_step` of the run it resumes, then this run's.
void StructureRun::resume_results(long last_step) {
  const auto h5 = output_dir_ / "structure.h5", before = output_dir_ / results_before_restart;
  if (!std::filesystem::exists(before)) {
    if (!std::filesystem::exists(h5))
      throw common::UserError("--restart: the checkpoint is there but its results file " + h5.string() +
                              " is not; a restart continues a results folder as a whole");
    std::filesystem::rename(h5, before);
  }
  open_results();
  std::vector<std::string> structures, probe_names;
  for (const auto &s : scene_->structures())
    structures.push_back(s->name());
  if (!probes_->empty())
    probe_names = probes_->names();
  const auto kept =
      output::replay_results(before, *results_, probe_csv_.get(), structures, probe_names, last_step, output_every());
  std::filesystem::remove(before);
  last_written_step_ = kept.last_step;
}

long StructureRun::output_every() const {
  return std::max(1L, std::lround(config_.run.output_interval_s / config_.run.time_step_s));
}

checkpoint::CheckpointPart StructureRun::write_checkpoint_part(const std::filesystem::path &folder,
                                                               long n_completed) const {
  checkpoint::StateArchive archive;
  archive.put_integer("step", n_completed);
  scene_->save_state(archive);
  return {checkpoint_part, checkpoint::write_archive(folder / checkpoint_part, archive)};
}

void StructureRun::read_checkpoint_part(const std::filesystem::path &folder, long n_completed,
                                        const std::string &checksum) {
  const checkpoint::StateArchive archive = checkpoint::read_archive(folder / checkpoint_part);
  if (!checksum.empty() && checkpoint::archive_checksum(folder / checkpoint_part) != checksum)
    throw checkpoint::CheckpointError((folder / checkpoint_part).string() + ": checksum " +
                                      checkpoint::archive_checksum(folder / checkpoint_part) + ", the coupler's "
                                      "checkpoint says " + checksum + " (a part of another checkpoint)");
  if (archive.integer("step") != n_completed)
    throw checkpoint::CheckpointError((folder / checkpoint_part).string() + ": holds step " +
                                      std::to_string(archive.integer("step")) + ", the set is of step " +
                                      std::to_string(n_completed));
  scene_->load_state(archive);
}

/// A run of its own checkpoints itself: its part, then the set is complete.
void StructureRun::checkpoint_alone(long n_completed) {
  const auto folder = checkpoints_->begin(n_completed);
  checkpoints_->complete(n_completed, scene_->time_s(), {write_checkpoint_part(folder, n_completed)});
  spdlog::debug("checkpoint of step {} in {}", n_completed, folder.string());
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

std::optional<Divergence> StructureRun::find_divergence(long step, bool finite_only) const {
  for (std::size_t i = 0; i < scene_->structures().size(); ++i) {
    const auto &s = scene_->structures()[i];
    const bool finite = s->positions_m().allFinite() && s->velocities_m_per_s().allFinite();
    if (finite && finite_only)
      continue;
    // A structure that tears is torn at the accepted step instead (Scene::tear_overstretched).
    const double stretch = finite ? (scene_->life().tears(i) ? 1.0 : s->max_stretch_ratio()) : NAN;
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
  const long done = step - first_step_; // steps of this process (a restart starts later)
  const double eta = done > 0 ? wall * static_cast<double>(n_steps - step) / static_cast<double>(done) : 0.0;
  spdlog::info("step {}/{}  t = {:.5g} s ({:.0f}%)  wall {}  ETA {}  {:.3g} ms/step", step, n_steps, scene_->time_s(),
               100.0 * static_cast<double>(step) / static_cast<double>(n_steps), common::format_duration(wall),
               common::format_duration(eta), done > 0 ? 1e3 * wall / static_cast<double>(done) : 0.0);
}

void StructureRun::stop_with(const std::string &status, long last_good_step) {
  const double last_good_time = static_cast<double>(last_good_step) * config_.run.time_step_s;
  scene_->restore_states(last_good_x_, last_good_v_, last_good_time);
  if (last_written_step_ != last_good_step)
    write_state(last_good_step);
  results_->set_status(status);
}

const std::atomic<int> &StructureRun::stop_signal() { return received_stop_signal; }

long StructureRun::n_steps() const { return config_.run.n_steps(); }

void StructureRun::start(Resume resume) {
  std::filesystem::create_directories(output_dir_);
  common::add_log_file(output_dir_ / "structure.log");
  spdlog::info("case {}: effective configuration\n{}", case_dir_.string(), config_yaml_);
  scene_ = std::make_unique<Scene>(config_);
  for (const auto &warning : time_step_warnings(*scene_, config_.run.time_step_s))
    spdlog::warn("{}", warning);
  checkpoints_ = std::make_unique<checkpoint::CheckpointSet>(output_dir_ / "checkpoints", config_.restart_identity,
                                                             config_.run.checkpoint_keep);
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  // Coupled: the coupler ends the run on a signal, at a step boundary (ParticipantSession).
  stops_at_signal_ = resume != Resume::when_told;
  start_ = last_progress_ = std::chrono::steady_clock::now();
  last_good_x_.resize(scene_->structures().size());
  last_good_v_.resize(scene_->structures().size());
  if (resume == Resume::when_told)
    return;
  if (!config_.restart) {
    begin_fresh();
    return;
  }
  std::vector<std::string> skipped;
  const auto found = checkpoints_->newest(skipped);
  for (const auto &why : skipped)
    spdlog::warn("restart: skipped a checkpoint: {}", why);
  for (const auto &note : found ? found->notes : std::vector<std::string>{})
    spdlog::warn("restart: {}", note);
  if (!found)
    throw common::UserError("--restart: no complete checkpoint of this case in " + checkpoints_->root().string() +
                            (skipped.empty() ? std::string(" (run.checkpoint_interval_s makes them)")
                                             : " (" + std::to_string(skipped.size()) + " skipped, above)"));
  resume_from(found->step, found->checksum_of(checkpoint_part));
}

void StructureRun::begin_fresh() {
  open_results();
  write_state(0);
}

void StructureRun::resume_from(long step, const std::string &checksum) {
  const auto folder = checkpoints_->folder(step);
  try {
    read_checkpoint_part(folder, step, checksum);
  } catch (const checkpoint::CheckpointError &e) {
    throw common::UserError(std::string("--restart: ") + e.what() +
                            " (a checkpoint this build cannot resume from exactly; remove its folder to resume from "
                            "an older one)");
  }
  first_step_ = step;
  resume_results(step);
  spdlog::info("restart: resumed from the checkpoint of step {} (t = {:g} s) in {}", step, scene_->time_s(),
               folder.string());
}

void StructureRun::save_step_start() {
  step_start_ = checkpoint::StateArchive();
  scene_->save_state(step_start_);
}

void StructureRun::restore_step_start() { scene_->load_state(step_start_); }

StepOutcome StructureRun::advance_step(long n, const std::vector<PointArray> *load_densities, bool record) {
  const long step = n + 1; // the state X^{n+1} this step reaches (saved states are numbered from X^0)
  for (std::size_t i = 0; i < scene_->structures().size(); ++i) {
    last_good_x_[i] = scene_->structures()[i]->positions_m();
    last_good_v_[i] = scene_->structures()[i]->velocities_m_per_s();
  }
  if (load_densities)
    scene_->advance(*load_densities);
  else
    scene_->advance();
  // An iterate of implicit coupling (record = false) is no state yet: only non-finite values
  // stop it; the stretch and speed guards judge the step the coupler accepts (accept_step).
  if (const auto divergence = find_divergence(step, !record))
    return diverged(*divergence, step);
  if (received_stop_signal != 0 && stops_at_signal_) {
    write_state(step);
    results_->set_status("interrupted");
    spdlog::warn("interrupted by signal {} at step {}; results so far are in {}", int(received_stop_signal), step,
                 results_->h5_path().string());
    return {StepOutcome::Kind::interrupted, "interrupted by signal " + std::to_string(int(received_stop_signal))};
  }
  if (record)
    record_step(n);
  return {};
}

StepOutcome StructureRun::diverged(const Divergence &divergence, long step) {
  spdlog::error("diverged at {}", divergence.message);
  stop_with("diverged: " + divergence.message, step - 1);
  spdlog::error("the last good state (step {}) is in {}", step - 1, results_->h5_path().string());
  return {StepOutcome::Kind::diverged, divergence.message};
}

StepOutcome StructureRun::accept_step(long n) {
  if (const auto divergence = find_divergence(n + 1, false))
    return diverged(*divergence, n + 1);
  record_step(n);
  return {};
}

void StructureRun::record_exit(std::size_t i) {
  const auto &life = scene_->life();
  results_->set_exit(i, life.exit_time_s(i), participant::exit_reason_name(life.exit_reason(i)));
}

void StructureRun::record_step(long n) {
  const long step = n + 1, n_total = n_steps();
  for (const std::size_t i : scene_->remove_past_planes())
    record_exit(i);
  for (const std::size_t i : scene_->tear_overstretched())
    record_exit(i);
  if (step % output_every() == 0 || step == n_total)
    write_state(step);
  report_progress(step, n_total, step == n_total);
}

void StructureRun::finish(const std::string &status, long n_completed) {
  if (!results_) // a coupled run that ended before its results were opened (a refused handshake)
    return;
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
  const long n = n_steps(), every = config_.run.checkpoint_every();
  for (long step = first_step_; step < n; ++step) {
    const StepOutcome outcome = advance_step(step, nullptr);
    if (outcome.kind == StepOutcome::Kind::diverged)
      return common::exit_code_run_failed;
    if (outcome.kind == StepOutcome::Kind::interrupted) {
      if (every > 0) { // a clean stop: resume from here
        checkpoint_alone(step + 1);
        spdlog::warn("checkpoint of step {} written: ./fsi run --restart resumes from it", step + 1);
      }
      return common::exit_code_interrupted;
    }
    // Every interval, and at the end: a later --restart with a later end time runs further.
    if (every > 0 && ((step + 1) % every == 0 || step + 1 == n))
      checkpoint_alone(step + 1);
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
