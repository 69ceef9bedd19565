// fsi-openfoam-fluid: the OpenFOAM fluid participant (PIMPLE, incompressible) with the diffuse
// immersed-boundary forcing of Eqs. (6-8). The case's `fluid.openfoam.case_directory` is
// copied to <output>/openfoam, meshed with blockMesh when it has no mesh, and run there.
//   fsi-openfoam-fluid CASE_DIR [--endpoint E] [-o DIR] [-v] [--precursor]
// With fluid.openfoam.precursor_time_s > 0 the flow first runs alone with its rigid bodies in
// <output>/precursor (section 3.2), once: the result is reused while what it depends on is
// unchanged (Precursor.hpp). --precursor runs only that (the launcher does so before it starts
// the coupled processes, so the coupler's handshake does not wait for it).
// With fluid.openfoam.mpi_ranks = N > 1 it prepares and decomposes the case, then replaces
// itself by `mpirun -np N fsi-openfoam-fluid ... --mpi-rank` (same process id, so signals and
// the exit code reach the launcher); rank 0 talks to the coupler, the others follow it.
// Exit codes: 0 success, 1 the run stopped (coupler lost, another participant failed, OpenFOAM
// failed), 2 bad input, 130 interrupted.

#include "FoamFlow.hpp"
#include "OpenFoamFluidModel.hpp"
#include "Precursor.hpp"
#include "case/ParticipantSettings.hpp"
#include "common/ConfigError.hpp"
#include "motion/MotionFactory.hpp"
#include "common/Logging.hpp"
#include "proto/FluidParticipant.hpp"
#include "proto/TransportError.hpp"
#include "proto/ZmqContext.hpp"

#include "case/CaseOptions.hpp"
#include "case/ModuleSetups.hpp"
#include "common/ExitCodes.hpp"
#include "common/GuardedMain.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <iostream>

namespace {

extern "C" void on_stop_signal(int signal) { fsi::proto::FluidParticipant::stop_signal() = signal; }

/// Copies the OpenFOAM case into the output folder and meshes it if it has no mesh yet.
std::filesystem::path prepare_openfoam_case(const std::filesystem::path &case_dir, const std::string &template_dir,
                                            const std::filesystem::path &out) {
  namespace fs = std::filesystem;
  const fs::path source = case_dir / template_dir, target = out / "openfoam";
  if (!fs::is_directory(source / "system") || !fs::is_directory(source / "constant"))
    throw fsi::common::ConfigError((source).string() + ": fluid.openfoam.case_directory must be an OpenFOAM case "
                                                       "(folders system/, constant/ and 0/).");
  fs::remove_all(target);
  fs::create_directories(target);
  fs::copy(source, target, fs::copy_options::recursive);
  if (!fs::exists(target / "constant" / "polyMesh" / "owner")) {
    if (!fs::exists(target / "system" / "blockMeshDict"))
      throw fsi::common::ConfigError(source.string() + ": no mesh (constant/polyMesh) and no system/blockMeshDict.");
    const std::string command = "blockMesh -case '" + target.string() + "' > '" + (target / "log.blockMesh").string() +
                                "' 2>&1";
    spdlog::info("meshing: {}", command);
    if (std::system(command.c_str()) != 0)
      throw std::runtime_error("blockMesh failed: see " + (target / "log.blockMesh").string());
  }
  return target;
}

/// The rigid bodies the fluid penalizes: the closed STL meshes among the collision surfaces,
/// with their motions (the structure collides with the very same surfaces).
std::vector<std::unique_ptr<fsi::fluid::rigid::RigidBody>> rigid_bodies(const fsi::case_config::CaseConfig &config) {
  std::vector<std::unique_ptr<fsi::fluid::rigid::RigidBody>> bodies;
  if (!config.collisions)
    return bodies;
  for (std::size_t i = 0; i < config.collisions->surfaces.size(); ++i) {
    const auto &surface = config.collisions->surfaces[i];
    const std::string name = "surface" + std::to_string(i);
    if (surface.box || surface.plane) { // walls seen from the fluid: the OpenFOAM mesh's own walls
      spdlog::info("collisions.surfaces[{}] ({}) bounds the fluid: left to the walls of the OpenFOAM mesh", i,
                   surface.box ? "box" : "plane");
      continue;
    }
    if (!surface.mesh) {
      spdlog::warn("collisions.surfaces[{}] is an analytic surface: the fluid does not see it (give it as a closed STL "
                   "mesh to penalize it, or make it a wall of the OpenFOAM mesh)",
                   i);
      continue;
    }
    if (surface.mesh->fluid_side != fsi::geometry::FluidSide::outside) {
      spdlog::warn("collisions.surfaces[{}] has the fluid inside: it is a container, left to the OpenFOAM mesh", i);
      continue;
    }
    auto motion = surface.motion ? fsi::motion::make_motion(*surface.motion, config.gravity_m_per_s2.norm())
                                 : std::make_shared<const fsi::motion::StaticPose>();
    bodies.push_back(fsi::fluid::rigid::RigidBody::from_stl(name, surface.mesh->file.string(), std::move(motion)));
  }
  return bodies;
}

/// decomposePar into n subdomains, cut along x (Debian's scotch is a stub).
void decompose(const std::filesystem::path &foam_case, int n) {
  std::ofstream(foam_case / "system" / "decomposeParDict")
      << "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
      << "numberOfSubdomains " << n << ";\nmethod hierarchical;\n"
      << "coeffs { n (" << n << " 1 1); order xyz; }\n";
  const std::string command = "decomposePar -force -case '" + foam_case.string() + "' > '" +
                              (foam_case / "log.decomposePar").string() + "' 2>&1";
  spdlog::info("decomposing for {} MPI ranks: {}", n, command);
  if (std::system(command.c_str()) != 0)
    throw std::runtime_error("decomposePar failed: see " + (foam_case / "log.decomposePar").string());
}

/// Runs this program again with extra arguments and waits for it; a stop signal received
/// meanwhile is passed on. Returns its exit code.
int run_self(int argc, char **argv, const std::vector<std::string> &extra) {
  std::vector<std::string> args = {std::filesystem::read_symlink("/proc/self/exe").string()};
  for (int i = 1; i < argc; ++i)
    args.emplace_back(argv[i]);
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char *> pointers;
  for (auto &a : args)
    pointers.push_back(a.data());
  pointers.push_back(nullptr);
  spdlog::default_logger()->flush();
  const pid_t child = fork();
  if (child < 0)
    throw std::runtime_error(std::string("cannot start the precursor run: ") + std::strerror(errno));
  if (child == 0) {
    execv(pointers[0], pointers.data());
    _exit(127);
  }
  int status = 0;
  bool forwarded = false;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR)
      throw std::runtime_error(std::string("waiting for the precursor run: ") + std::strerror(errno));
    const int signal = fsi::proto::FluidParticipant::stop_signal();
    if (signal != 0 && !forwarded) {
      kill(child, signal);
      forwarded = true;
    }
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// The precursor's time loop on every rank: the flow with its rigid bodies, no structure.
/// Progress (and the rigid-body loads, in precursor/forces.csv) from the master.
int run_precursor_steps(fsi::fluid::OpenFoamFluidModel &model, fsi::fluid::FoamFlow &flow,
                        const fsi::fluid::Precursor &precursor) {
  using Clock = std::chrono::steady_clock;
  const double end = precursor.end_time_s();
  const std::vector<double> steps = precursor.step_sizes();
  const auto n_steps = static_cast<long>(steps.size());
  std::ofstream forces;
  const auto start = Clock::now();
  auto last_report = start;
  double t = 0.0;
  for (long step = 0; step < n_steps; ++step) {
    if (fsi::proto::FluidParticipant::stop_signal() != 0) {
      spdlog::warn("precursor interrupted at t = {:.6g} s; its result is not kept", t);
      return fsi::common::exit_code_interrupted;
    }
    const auto loads = model.advance_without_structure(t, steps[static_cast<std::size_t>(step)]);
    t += steps[static_cast<std::size_t>(step)];
    if (flow.rank() != 0)
      continue;
    if (step == 0 && !loads.empty()) {
      forces.open(precursor.folder() / "forces.csv");
      forces << "time_s";
      for (std::size_t b = 0; b < loads.size(); ++b)
        forces << ",body" << b << ".fx_n,body" << b << ".fy_n,body" << b << ".fz_n";
      forces << "\n";
    }
    if (forces.is_open()) {
      forces << flow.time_s();
      for (const auto &load : loads)
        forces << "," << load.force_n.x() << "," << load.force_n.y() << "," << load.force_n.z();
      forces << "\n";
    }
    const auto now = Clock::now();
    if (now - last_report > std::chrono::seconds(5) || step + 1 == n_steps) {
      last_report = now;
      const double wall = std::chrono::duration<double>(now - start).count();
      const double eta = wall / static_cast<double>(step + 1) * static_cast<double>(n_steps - step - 1);
      spdlog::info("precursor: t = {:.4g} of {:.4g} s, step {}/{}, {:.1f} ms/step, ETA {:.0f} s", flow.time_s(), end,
                   step + 1, n_steps, 1e3 * wall / static_cast<double>(step + 1), eta);
    }
  }
  flow.write_now();
  return 0;
}

/// Replaces this process by mpirun running n ranks of this program on the prepared case.
[[noreturn]] void exec_mpirun(int n, int argc, char **argv) {
  std::vector<std::string> args = {"mpirun", "-np", std::to_string(n), "--oversubscribe", "-x", "WM_PROJECT_DIR",
                                   "-x", "FOAM_ETC"};
  if (geteuid() == 0)
    args.push_back("--allow-run-as-root");
  args.push_back(std::filesystem::read_symlink("/proc/self/exe").string());
  for (int i = 1; i < argc; ++i)
    args.emplace_back(argv[i]);
  args.emplace_back("--mpi-rank");
  std::vector<char *> pointers;
  for (auto &a : args)
    pointers.push_back(a.data());
  pointers.push_back(nullptr);
  spdlog::info("starting {} MPI ranks with mpirun", n);
  spdlog::default_logger()->flush();
  execvp("mpirun", pointers.data());
  throw std::runtime_error(std::string("cannot start mpirun: ") + std::strerror(errno) +
                           " (install the Debian package openmpi-bin)");
}

} // namespace

int main(int argc, char **argv) {
  const fsi::proto::ZmqContextCloser zmq_closer; // outlives every channel: last messages get out
  CLI::App app{"fsi-openfoam-fluid: OpenFOAM fluid participant with the diffuse immersed boundary"};
  fsi::case_config::CaseOptions options;
  std::string endpoint;
  bool verbose = false, mpi_rank = false, precursor_only = false;
  options.add_to(app);
  app.add_option("--endpoint", endpoint, "Coupler endpoint (default: coupling.endpoint of the case)");
  app.add_flag("-v,--verbose", verbose, "Debug logging");
  app.add_flag("--mpi-rank", mpi_rank, "Internal: this process is one rank under mpirun (the case is prepared)")
      ->group("");
  app.add_flag("--precursor", precursor_only,
               "Run only the precursor (fluid.openfoam.precursor_time_s: the flow with its rigid bodies, no "
               "structure, no coupler) in <output>/precursor, unless it is up to date");
  if (const int code = fsi::case_config::parse_command_line(app, argc, argv); code >= 0)
    return code;
  fsi::common::setup_logging("fluid", verbose);
  // Debian's OpenFOAM finds its etc/ through WM_PROJECT_DIR, read while its libraries load
  // (before main): the launcher sets it; blockMesh, started from here, needs it as well.
  if (!std::getenv("WM_PROJECT_DIR")) {
    std::cerr << "fsi-openfoam-fluid: WM_PROJECT_DIR is not set; start it through ./fsi run, or export "
                 "WM_PROJECT_DIR=/usr/share/openfoam\n";
    return fsi::common::exit_code_bad_input;
  }
  return fsi::common::guarded_main("OpenFOAM fluid", [&] {
    const auto config = options.load();
    const std::string &case_dir = options.case_dir;
    if (!config.fluid || !config.fluid->openfoam) {
      spdlog::error("case {} has no `fluid.openfoam` section: there is no OpenFOAM fluid to run", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    const std::filesystem::path out = options.output_directory(config);
    std::filesystem::create_directories(out);
    const int n_ranks = config.fluid->openfoam->mpi_ranks;
    const fsi::fluid::Precursor precursor(fsi::case_config::precursor_inputs(config), case_dir, out);
    if (precursor_only && !precursor.wanted()) {
      spdlog::error("case {}: --precursor needs fluid.openfoam.precursor_time_s > 0", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    const std::filesystem::path base = precursor_only ? precursor.folder() : out;
    if (!mpi_rank) {
      std::filesystem::create_directories(base);
      fsi::common::add_log_file(base / "fluid.log");
    }
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    if (precursor_only && !mpi_rank && precursor.is_current()) {
      spdlog::info("precursor: {} is up to date (fingerprint {}): reused", precursor.folder().string(),
                   precursor.fingerprint());
      return 0;
    }
    std::filesystem::path foam_case = base / "openfoam";
    if (!mpi_rank) {
      if (precursor_only)
        precursor.invalidate();
      foam_case = prepare_openfoam_case(case_dir, config.fluid->openfoam->case_directory, base);
      if (!precursor_only && precursor.wanted() && !precursor.is_current()) {
        spdlog::info("precursor: running the flow alone for {} s first (fsi-openfoam-fluid --precursor)",
                     precursor.end_time_s());
        const int code = run_self(argc, argv, {"--precursor"});
        if (code != 0 || !precursor.is_current())
          throw std::runtime_error("the precursor run failed (exit code " + std::to_string(code) + "; see " +
                                   (precursor.folder() / "fluid.log").string() + ")");
      }
      if (n_ranks > 1)
        decompose(foam_case, n_ranks);
      if (!precursor_only && precursor.wanted())
        spdlog::info("precursor: {} fields of t = {} s installed as the initial fields",
                     precursor.install_fields(foam_case, n_ranks), precursor.end_time_s());
      if (n_ranks > 1)
        exec_mpirun(n_ranks, argc, argv);
    }
    const double dt = precursor_only ? precursor.time_step_s() : config.run.time_step_s;
    const double end_time = precursor_only ? precursor.end_time_s() : config.run.end_time_s;
    auto flow = fsi::fluid::FoamFlow::create({std::filesystem::absolute(foam_case), dt, end_time, mpi_rank});
    auto bodies = rigid_bodies(config);
    if (!precursor_only) // coupled: the coupler moves the bodies (section 2.3), the precursor moves its own
      for (auto &body : bodies)
        if (!body->motion().is_static())
          body->take_poses_from_coupler();
    fsi::fluid::OpenFoamFluidModel model(*config.fluid->openfoam, *flow, std::move(bodies));
    if (precursor_only) {
      if (flow->rank() != 0)
        spdlog::set_level(spdlog::level::warn);
      else if (mpi_rank)
        fsi::common::add_log_file(base / "fluid.log");
      spdlog::info("precursor: {} to t = {} s, dt = {} s (the last {} steps at the coupled run's {} s)",
                   flow->describe(), end_time, dt, fsi::fluid::Precursor::handover_steps, config.run.time_step_s);
      const int code = run_precursor_steps(model, *flow, precursor);
      if (code == 0 && flow->rank() == 0) {
        precursor.mark_complete();
        spdlog::info("precursor: fields of t = {} s written in {}", flow->time_s(), foam_case.string());
      }
      return code;
    }
    if (flow->rank() != 0) { // MPI: only rank 0 talks to the coupler
      spdlog::set_level(spdlog::level::warn);
      model.follow();
      return 0;
    }
    if (mpi_rank)
      fsi::common::add_log_file(out / "fluid.log");
    auto settings = fsi::case_config::participant_settings(config, endpoint);
    fsi::proto::FluidParticipant participant(model, std::move(settings));
    return participant.run();
  });
}
