// fsi-openfoam-fluid: the OpenFOAM fluid participant (PIMPLE, incompressible) with the diffuse
// immersed-boundary forcing of Eqs. (6-8). The case's `fluid.openfoam.case_directory` is
// copied to <output>/openfoam, meshed with blockMesh when it has no mesh, and run there.
//   fsi-openfoam-fluid CASE_DIR [--endpoint E] [-o DIR] [-v] [--precursor]
// With fluid.openfoam.precursor_time_s > 0 the flow first runs alone with its rigid bodies in
// <output>/precursor (section 3.2), once: the result is reused while what it depends on is
// unchanged (Precursor.hpp). --precursor runs only that (the launcher does so before it starts
// the coupled processes, so the coupler's handshake does not wait for it).
// With fluid.openfoam.mpi_ranks = N > 1 it prepares and decomposes the case, then runs
// `mpirun -np N fsi-openfoam-fluid ... --mpi-rank` and exits with it, passing a stop signal on as
// SIGUSR1/SIGUSR2 (SelfLaunch.hpp); rank 0 talks to the coupler, the others follow it.
// A case without structures is the flow alone with its rigid bodies (a pump's single-phase
// performance): no coupler, run.time_step_s to run.end_time_s, forces.csv in <output>.
// Exit codes: 0 success, 1 the run stopped (coupler lost, another participant failed, OpenFOAM
// failed), 2 bad input, 130 interrupted.

#include "fluid_adapter/FoamCheckpoint.hpp"
#include "FlowAloneCheckpoints.hpp"
#include "FlowAloneRun.hpp"
#include "fluid_adapter/FoamFlow.hpp"
#include "OpenFoamCase.hpp"
#include "fluid_adapter/OpenFoamFluidModel.hpp"
#include "fluid_adapter/Precursor.hpp"
#include "RigidBodies.hpp"
#include "SelfLaunch.hpp"
#include "case/CaseOptions.hpp"
#include "case/ModuleSetups.hpp"
#include "case/ParticipantSettings.hpp"
#include "checkpoint/CheckpointError.hpp"
#include "common/Allocator.hpp"
#include "common/ConfigEmitter.hpp"
#include "common/ExitCodes.hpp"
#include "common/GuardedMain.hpp"
#include "common/Logging.hpp"
#include "common/UserError.hpp"
#include "participant/FluidParticipant.hpp"
#include "proto/ZmqContext.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>
#include <fstream>
#include <cstdlib>
#include <iostream>

namespace {

namespace fs = std::filesystem;
using fsi::case_config::CaseConfig;
using fsi::fluid::Precursor;

extern "C" void on_stop_signal(int signal) { fsi::participant::FluidParticipant::stop_signal() = signal; }
/// On a rank under mpirun: the stop signal the supervising process passed on (SelfLaunch.hpp).
extern "C" void on_rank_stop_signal(int signal) {
  fsi::participant::FluidParticipant::stop_signal() = fsi::apps::rank_stop_signal(signal);
}

/// What this process runs: the coupled participant, the precursor (the flow with its rigid
/// bodies alone, section 3.2), or a case without structures (the flow alone, to its end).
/// Each prepares the OpenFOAM case itself, or is one rank under mpirun on a case already
/// prepared (--mpi-rank).
enum class Role { coupled, precursor, alone };

struct Process {
  Role role = Role::coupled;
  bool under_mpirun = false;
  bool restart = false; ///< --restart (a coupled run, the flow alone): start from the newest complete checkpoint
  int argc = 0;
  char **argv = nullptr;
};

/// The launcher-facing process: copies and meshes the case, runs the precursor first when the
/// coupled run needs one and it is not up to date, installs its fields, decomposes for MPI and
/// then replaces itself by mpirun (n ranks > 1). Returns the OpenFOAM case folder.
fs::path prepare_case(const Process &process, const CaseConfig &config, const std::string &case_dir,
                      const fs::path &base, const Precursor &precursor, long &restart_step) {
  const auto &foam = *config.fluid->openfoam;
  if (process.restart && process.role != Role::precursor) {
    // The case of the run it resumes, as it is (its mesh, the fields it wrote), started from the
    // newest complete checkpoint's fields; in a coupled run the coupler must name the same one.
    const fs::path foam_case = base / "openfoam";
    if (!fs::exists(foam_case / "constant" / "polyMesh" / "owner"))
      throw fsi::common::UserError("--restart: " + foam_case.string() + " has no mesh: there is no run to resume");
    const fsi::checkpoint::CheckpointSet sets(base / "checkpoints", config.restart_identity(),
                                              config.run.checkpoint_keep);
    std::vector<std::string> skipped;
    const auto found = sets.newest(skipped);
    for (const auto &why : skipped)
      spdlog::warn("restart: skipped a checkpoint: {}", why);
    for (const auto &note : found ? found->notes : std::vector<std::string>{})
      spdlog::warn("restart: {}", note);
    if (!found)
      throw fsi::common::UserError("--restart: no complete checkpoint of this case in " + sets.root().string() +
                                   (config.run.checkpoint_every() == 0 ? " (run.checkpoint_interval_s makes them)" : ""));
    if (process.role == Role::alone && found->step >= config.run.n_steps())
      throw fsi::common::UserError("--restart: the newest checkpoint is of step " + std::to_string(found->step) +
                                   " (t = " + std::to_string(found->time_s) + " s), the run's end at run.end_time_s = " +
                                   std::to_string(config.run.end_time_s) + " s: give a later --end-time to run further");
    try {
      const std::string time =
          fsi::fluid::FoamCheckpoint::install(found->folder, foam_case, foam.mpi_ranks, found->step,
                                              found->checksum_of(fsi::fluid::FoamCheckpoint::part_name));
      spdlog::info("restart: the fields of t = {} s (step {}) from {}", time, found->step, found->folder.string());
    } catch (const fsi::checkpoint::CheckpointError &e) {
      throw fsi::common::UserError(std::string("--restart: ") + e.what());
    }
    restart_step = found->step;
    if (foam.mpi_ranks > 1) // the same decomposition, its processor folders restored: no decomposePar
      fsi::apps::run_mpirun(foam.mpi_ranks, process.argc, process.argv);
    return foam_case;
  }
  const fs::path foam_case = fsi::apps::prepare_openfoam_case(case_dir, foam, base);
  // A warm start: the fields of another run mapped onto this mesh. With a precursor they start the
  // precursor (a finer mesh then spins up from a coarser run's developed flow, not from rest),
  // whose last fields start the coupled run.
  const bool precursor_first = process.role != Role::alone && precursor.wanted();
  if (!foam.initial_fields_from.empty() && (process.role == Role::precursor || !precursor_first)) {
    fs::path source = foam.initial_fields_from;
    if (source.is_relative())
      source = fs::path(case_dir) / source;
    spdlog::info("warm start: the fields of t = {} s of {} mapped onto this mesh (log: {})",
                 fsi::apps::map_initial_fields(foam_case, source), source.string(),
                 (foam_case / "log.mapFields").string());
  }
  if (process.role == Role::coupled && precursor.wanted() && !precursor.is_current()) {
    spdlog::info("precursor: running the flow alone for {} s first (fsi-openfoam-fluid --precursor)",
                 precursor.end_time_s());
    const int code = fsi::apps::run_self(process.argc, process.argv, {"--precursor"});
    if (code != 0 || !precursor.is_current())
      throw std::runtime_error("the precursor run failed (exit code " + std::to_string(code) + "; see " +
                               (precursor.folder() / "fluid.log").string() + ")");
  }
  if (foam.mpi_ranks > 1)
    fsi::apps::decompose(foam_case, foam.mpi_ranks);
  if (process.role == Role::coupled && precursor.wanted())
    spdlog::info("precursor: {} fields of t = {} s installed as the initial fields",
                 precursor.install_fields(foam_case, foam.mpi_ranks), precursor.end_time_s());
  if (foam.mpi_ranks > 1)
    fsi::apps::run_mpirun(foam.mpi_ranks, process.argc, process.argv);
  return foam_case;
}

/// The precursor on every rank; the master records it as complete.
int run_precursor(const Process &process, fsi::fluid::OpenFoamFluidModel &model, fsi::fluid::FoamFlow &flow,
                  const Precursor &precursor, double coupled_time_step_s) {
  if (flow.rank() != 0)
    spdlog::set_level(spdlog::level::warn);
  else if (process.under_mpirun)
    fsi::common::add_log_file(precursor.folder() / "fluid.log", fsi::common::LogFile::append); // begun before mpirun
  spdlog::info("precursor: {} to t = {} s, dt = {} s (the last {} steps at the coupled run's {} s)", flow.describe(),
               precursor.end_time_s(), precursor.time_step_s(), Precursor::handover_steps, coupled_time_step_s);
  const int code = fsi::apps::run_flow_alone(model, flow, {"precursor", precursor.folder(), precursor.step_sizes()});
  if (code == 0 && flow.rank() == 0) {
    precursor.mark_complete();
    spdlog::info("precursor: fields of t = {} s written in {}", flow.time_s(), precursor.foam_case().string());
  }
  return code;
}

/// A case without structures: the flow with its rigid bodies to run.end_time_s, every rank,
/// checkpointed every run.checkpoint_interval_s; a restart resumes after restart_step.
int run_alone(const Process &process, fsi::fluid::OpenFoamFluidModel &model, fsi::fluid::FoamFlow &flow,
              const CaseConfig &config, const fs::path &out, long restart_step) {
  if (flow.rank() != 0)
    spdlog::set_level(spdlog::level::warn);
  else if (process.under_mpirun)
    fsi::common::add_log_file(out / "fluid.log", fsi::common::LogFile::append);
  spdlog::info("flow alone (no structure): {} to t = {} s, dt = {} s", flow.describe(), config.run.end_time_s,
               config.run.time_step_s);
  // What this run ran with (the structure saves it in a coupled run): its postprocessing reads
  // the operating point from here.
  if (flow.rank() == 0)
    std::ofstream(out / "config.effective.yaml") << fsi::common::to_yaml(const_cast<CaseConfig &>(config)) << "\n";
  const auto steps =
      restart_step > 0
          ? fsi::apps::resumed_steps(config.run.time_step_s, config.run.end_time_s, restart_step, flow.time_s())
          : fsi::apps::uniform_steps(config.run.time_step_s, config.run.end_time_s);
  const fsi::apps::FlowAloneCheckpoints checkpoints(out / "checkpoints", config.restart_identity(),
                                                    config.run.checkpoint_keep, config.run.checkpoint_every(),
                                                    restart_step);
  if (restart_step > 0)
    spdlog::info("restart: resumed from the checkpoint of step {} (t = {:.6g} s)", restart_step, flow.time_s());
  return fsi::apps::run_flow_alone(model, flow, {"flow", out, steps, &checkpoints});
}

/// The coupled participant: rank 0 talks to the coupler, the other ranks follow it.
int run_coupled(const Process &process, fsi::fluid::OpenFoamFluidModel &model, fsi::fluid::FoamFlow &flow,
                const CaseConfig &config, const std::string &case_dir, const fs::path &out,
                const std::string &endpoint) {
  if (flow.rank() != 0) {
    spdlog::set_level(spdlog::level::warn);
    model.follow();
    return fsi::common::exit_code_success;
  }
  if (process.under_mpirun)
    fsi::common::add_log_file(out / "fluid.log", fsi::common::LogFile::append); // begun before mpirun
  fsi::participant::FluidParticipant participant(
      model, fsi::case_config::participant_settings(config, endpoint, case_dir, fsi::proto::v2::ROLE_FLUID));
  return participant.run();
}

/// The bodies to penalize; in the coupled run the coupler moves them (section 2.3), in the
/// precursor (no coupler) they follow their declared motions.
std::vector<std::unique_ptr<fsi::fluid::rigid::RigidBody>> bodies_for(Role role, const CaseConfig &config) {
  auto bodies = fsi::apps::rigid_bodies(config.collisions ? config.collisions->surfaces
                                                          : std::vector<fsi::geometry::SurfaceConfig>{},
                                        config.gravity_m_per_s2.norm());
  if (role == Role::coupled)
    for (auto &body : bodies)
      if (!body->motion().is_static())
        body->take_poses_from_coupler();
  return bodies;
}

} // namespace

int main(int argc, char **argv) {
  const fsi::proto::ZmqContextCloser zmq_closer; // outlives every channel: last messages get out
  CLI::App app{"fsi-openfoam-fluid: OpenFOAM fluid participant with the diffuse immersed boundary"};
  fsi::case_config::CaseOptions options;
  bool mpi_rank = false, precursor_only = false;
  options.add_to(app);
  app.add_flag("--mpi-rank", mpi_rank, "Internal: this process is one rank under mpirun (the case is prepared)")
      ->group("");
  app.add_flag("--precursor", precursor_only,
               "Run only the precursor (fluid.openfoam.precursor_time_s: the flow with its rigid bodies, no "
               "structure, no coupler) in <output>/precursor, unless it is up to date");
  if (const int code = fsi::case_config::parse_command_line(app, argc, argv); code >= 0)
    return code;
  fsi::common::setup_logging("fluid", options.verbose);
  fsi::common::keep_freed_memory(); // OpenFOAM's per-step fields: 2x faster here (common/Allocator.hpp)
  // Debian's OpenFOAM finds its etc/ through WM_PROJECT_DIR, read while its libraries load
  // (before main): the launcher sets it; blockMesh, started from here, needs it as well.
  if (!std::getenv("WM_PROJECT_DIR")) {
    std::cerr << "fsi-openfoam-fluid: WM_PROJECT_DIR is not set; start it through ./fsi run, or export "
                 "WM_PROJECT_DIR=/usr/share/openfoam\n";
    return fsi::common::exit_code_bad_input;
  }
  return fsi::fluid::FoamFlow::end_process(fsi::common::guarded_main("OpenFOAM fluid", [&] {
    const auto config = options.load();
    const Process process{precursor_only           ? Role::precursor
                          : config.is_flow_alone() ? Role::alone
                                                   : Role::coupled,
                          mpi_rank, options.restart, argc, argv};
    const std::string &case_dir = options.case_dir;
    if (!config.fluid || !config.fluid->openfoam) {
      spdlog::error("case {} has no `fluid.openfoam` section: there is no OpenFOAM fluid to run", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    const fs::path out = options.output_directory(config);
    fs::create_directories(out);
    const Precursor precursor(fsi::case_config::precursor_inputs(config), case_dir, out);
    if (process.role == Role::precursor && !precursor.wanted()) {
      spdlog::error("case {}: --precursor needs fluid.openfoam.precursor_time_s > 0", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    const fs::path base = process.role == Role::precursor ? precursor.folder() : out;
    if (process.role == Role::precursor && !process.under_mpirun) {
      if (precursor.is_current()) {
        spdlog::info("precursor: {} is up to date (fingerprint {}): reused", precursor.folder().string(),
                     precursor.fingerprint());
        return fsi::common::exit_code_success;
      }
      precursor.invalidate(); // before its log opens: nothing of an earlier precursor is written into
    }
    if (!process.under_mpirun) {
      fs::create_directories(base);
      fsi::common::add_log_file(base / "fluid.log", process.restart && process.role != Role::precursor
                                                        ? fsi::common::LogFile::append
                                                        : fsi::common::LogFile::truncate);
    }
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    if (process.under_mpirun) {
      std::signal(SIGUSR1, on_rank_stop_signal);
      std::signal(SIGUSR2, on_rank_stop_signal);
    }
    long restart_step = 0;
    const fs::path foam_case = process.under_mpirun
                                   ? base / "openfoam"
                                   : prepare_case(process, config, case_dir, base, precursor, restart_step);
    if (process.under_mpirun && process.restart && process.role != Role::precursor) {
      // The ranks started by mpirun after the install: the same newest set (its step only).
      std::vector<std::string> skipped;
      const auto found =
          fsi::checkpoint::CheckpointSet(base / "checkpoints", config.restart_identity(), config.run.checkpoint_keep)
              .newest(skipped);
      restart_step = found ? found->step : 0;
    }
    const bool precursor_run = process.role == Role::precursor;
    const double dt = precursor_run ? precursor.time_step_s() : config.run.time_step_s;
    const double end_time = precursor_run ? precursor.end_time_s() : config.run.end_time_s;
    auto flow = fsi::fluid::FoamFlow::create({fs::absolute(foam_case), dt, end_time, process.under_mpirun});
    fsi::fluid::OpenFoamFluidModel model(*config.fluid->openfoam, *flow, bodies_for(process.role, config));
    if (process.role != Role::precursor) {
      model.set_checkpoints(out / "checkpoints", restart_step);
      if (config.run.checkpoint_every() > 0 && flow->rank() == 0)
        model.warn_unless_checkpoints_exact();
    }
    if (process.role == Role::alone)
      return run_alone(process, model, *flow, config, out, restart_step);
    return precursor_run ? run_precursor(process, model, *flow, precursor, config.run.time_step_s)
                         : run_coupled(process, model, *flow, config, case_dir, out, options.endpoint);
  }));
}
