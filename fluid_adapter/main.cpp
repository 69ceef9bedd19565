// fsi-openfoam-fluid: the OpenFOAM fluid participant (PIMPLE, incompressible) with the diffuse
// immersed-boundary forcing of Eqs. (6-8). The case's `fluid.openfoam.case_directory` is
// copied to <output>/openfoam, meshed with blockMesh when it has no mesh, and run there.
//   fsi-openfoam-fluid CASE_DIR [--endpoint E] [-o DIR] [-v]
// With fluid.openfoam.mpi_ranks = N > 1 it prepares and decomposes the case, then replaces
// itself by `mpirun -np N fsi-openfoam-fluid ... --mpi-rank` (same process id, so signals and
// the exit code reach the launcher); rank 0 talks to the coupler, the others follow it.
// Exit codes: 0 success, 1 the run stopped (coupler lost, another participant failed, OpenFOAM
// failed), 2 bad input, 130 interrupted.

#include "FoamFlow.hpp"
#include "OpenFoamFluidModel.hpp"
#include "structure_solver/ParticipantSettings.hpp"
#include "common/ConfigError.hpp"
#include "common/MotionFactory.hpp"
#include "common/Logging.hpp"
#include "proto/FluidParticipant.hpp"
#include "proto/TransportError.hpp"
#include "proto/ZmqContext.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <unistd.h>
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
std::vector<std::unique_ptr<fsi::fluid::rigid::RigidBody>> rigid_bodies(const fsi::structure::CaseConfig &config) {
  std::vector<std::unique_ptr<fsi::fluid::rigid::RigidBody>> bodies;
  if (!config.collisions)
    return bodies;
  for (std::size_t i = 0; i < config.collisions->surfaces.size(); ++i) {
    const auto &surface = config.collisions->surfaces[i];
    const std::string name = "surface" + std::to_string(i);
    if (!surface.mesh) {
      spdlog::warn("collisions.surfaces[{}] is an analytic surface: the fluid does not see it (give it as a closed STL "
                   "mesh to penalize it, or make it a wall of the OpenFOAM mesh)",
                   i);
      continue;
    }
    if (surface.mesh->fluid_side != fsi::structure::FluidSide::outside) {
      spdlog::warn("collisions.surfaces[{}] has the fluid inside: it is a container, left to the OpenFOAM mesh", i);
      continue;
    }
    auto motion = surface.motion ? fsi::common::make_motion(*surface.motion, config.gravity_m_per_s2.norm())
                                 : std::make_shared<const fsi::common::StaticPose>();
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
  std::string case_dir, output_dir, endpoint;
  bool verbose = false, mpi_rank = false;
  app.add_option("case_dir", case_dir, "Case folder holding case.yaml")->required();
  app.add_option("--endpoint", endpoint, "Coupler endpoint (default: coupling.endpoint of the case)");
  app.add_option("-o,--output-dir", output_dir, "Results folder (default: run.output_directory)");
  app.add_flag("-v,--verbose", verbose, "Debug logging");
  app.add_flag("--mpi-rank", mpi_rank, "Internal: this process is one rank under mpirun (the case is prepared)")
      ->group("");
  std::string preset;
  app.add_option("--resolution,--preset", preset,
                 "Preset of the case: presets/<NAME>.yaml merged over case.yaml (e.g. coarse, medium, fine)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    return e.get_exit_code() == 0 ? app.exit(e) : (app.exit(e), fsi::common::exit_code_bad_input);
  }
  fsi::common::setup_logging("fluid", verbose);
  // Debian's OpenFOAM finds its etc/ through WM_PROJECT_DIR, read while its libraries load
  // (before main): the launcher sets it; blockMesh, started from here, needs it as well.
  if (!std::getenv("WM_PROJECT_DIR")) {
    std::cerr << "fsi-openfoam-fluid: WM_PROJECT_DIR is not set; start it through ./fsi run, or export "
                 "WM_PROJECT_DIR=/usr/share/openfoam\n";
    return fsi::common::exit_code_bad_input;
  }
  try {
    const auto config = fsi::structure::CaseConfig::load(case_dir, preset);
    if (!config.fluid || !config.fluid->openfoam) {
      spdlog::error("case {} has no `fluid.openfoam` section: there is no OpenFOAM fluid to run", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    const std::filesystem::path out = config.output_directory(case_dir, output_dir);
    std::filesystem::create_directories(out);
    const int n_ranks = config.fluid->openfoam->mpi_ranks;
    if (!mpi_rank)
      fsi::common::add_log_file(out / "fluid.log");
    auto settings = fsi::structure::participant_settings(config, endpoint);
    const auto foam_case = mpi_rank ? out / "openfoam"
                                    : prepare_openfoam_case(case_dir, config.fluid->openfoam->case_directory, out);
    if (n_ranks > 1 && !mpi_rank) {
      decompose(foam_case, n_ranks);
      exec_mpirun(n_ranks, argc, argv);
    }
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    auto flow = fsi::fluid::FoamFlow::create(
        {std::filesystem::absolute(foam_case), config.run.time_step_s, config.run.end_time_s, mpi_rank});
    fsi::fluid::OpenFoamFluidModel model(*config.fluid->openfoam, *flow, rigid_bodies(config));
    if (flow->rank() != 0) { // MPI: only rank 0 talks to the coupler
      spdlog::set_level(spdlog::level::warn);
      model.follow();
      return 0;
    }
    if (mpi_rank)
      fsi::common::add_log_file(out / "fluid.log");
    fsi::proto::FluidParticipant participant(model, std::move(settings));
    return participant.run();
  } catch (const fsi::common::ConfigError &e) {
    spdlog::error("{}", e.what());
    return fsi::common::exit_code_bad_input;
  } catch (const fsi::proto::TransportError &e) {
    spdlog::error("{}", e.what());
    return fsi::common::exit_code_bad_input;
  } catch (const std::exception &e) {
    spdlog::error("OpenFOAM fluid failed: {}", e.what());
    return fsi::common::exit_code_run_failed;
  }
}
