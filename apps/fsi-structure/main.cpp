// fsi-structure: the standalone membrane/filament solver.
//   fsi-structure CASE_DIR            run the case (structure only: gravity, motions, collisions)
//   fsi-structure --check CASE_DIR    validate the case and exit
//   fsi-structure -o DIR CASE_DIR     write the results to DIR instead of run.output_directory
//   fsi-structure --schema            print the case-file reference (Markdown)
//   fsi-structure --coupled [--endpoint E] CASE_DIR
//                                     take part in a coupled run: join the coupler at E (default:
//                                     coupling.endpoint of the case) and take the fluid load from it
// Exit codes: 0 success, 1 run failed (diverged, or the coupled run stopped), 2 bad input,
// 130 interrupted.

#include "case/CaseConfig.hpp"
#include "case/CaseOptions.hpp"
#include "case/ModuleSetups.hpp"
#include "case/SchemaDoc.hpp"
#include "case/ParticipantSettings.hpp"
#include "structure_solver/MemoryBudget.hpp"
#include "participant/StructureParticipant.hpp"
#include "structure_solver/CoupledStructure.hpp"
#include "prescribed_flow/FlowFactory.hpp"
#include "structure_solver/StructureRun.hpp"
#include "proto/TransportError.hpp"
#include "geometry/MeshErrors.hpp"
#include "common/Allocator.hpp"
#include "common/ConfigError.hpp"
#include "common/Logging.hpp"

#include "proto/ZmqContext.hpp"
#include "common/ExitCodes.hpp"
#include "common/GuardedMain.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <iostream>

namespace {

/// A grid that cannot fit in memory is refused here, before any output is made.
void check_memory(const fsi::case_config::CaseConfig &config) {
  fsi::structure::MemoryBudget::check_fits(config.structures, fsi::structure::MemoryBudget::available_bytes());
}

int check_case(const fsi::case_config::CaseOptions &options) {
  auto config = options.load();
  check_memory(config);
  const std::string &case_dir = options.case_dir;
  const auto n_structures = config.structures.size();
  const long n_steps = config.run.n_steps();
  const double dt = config.run.time_step_s;
  if (config.fluid && config.fluid->prescribed) // reads a velocity table, if any
    spdlog::info("fluid: prescribed, {}", fsi::prescribed_flow::make_flow(*config.fluid->prescribed)->describe());
  // Builds the geometry: catches missing or open STL meshes too.
  const fsi::structure::Scene scene(fsi::case_config::structure_setup(std::move(config)));
  for (const auto &warning : fsi::structure::StructureRun::time_step_warnings(scene, dt))
    spdlog::warn("{}", warning);
  spdlog::info("case {} is valid: {} structure(s), {} steps", case_dir, n_structures, n_steps);
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  const fsi::proto::ZmqContextCloser zmq_closer; // outlives every channel: last messages get out
  CLI::App app{"fsi-structure: membrane and filament solver with collisions (standalone, no fluid)"};
  fsi::case_config::CaseOptions options;
  bool check = false, schema = false, coupled = false;
  options.add_to(app, false, "Coupler endpoint (with --coupled; default: coupling.endpoint)");
  app.add_flag("--check", check, "Validate the case without running it");
  app.add_flag("--schema", schema, "Print the case-file reference as Markdown");
  app.add_flag("--coupled", coupled, "Take part in a coupled run (the case must have a fluid section)");
  if (const int code = fsi::case_config::parse_command_line(app, argc, argv); code >= 0)
    return code;
  if (schema) {
    std::cout << fsi::case_config::case_schema_markdown();
    return 0;
  }
  const std::string &case_dir = options.case_dir;
  if (case_dir.empty()) {
    std::cerr << "fsi-structure: missing CASE_DIR (a folder holding case.yaml); see --help\n";
    return fsi::common::exit_code_bad_input;
  }
  fsi::common::setup_logging("structure", options.verbose);
  fsi::common::keep_freed_memory(); // before the solver allocates (common/Allocator.hpp)
  return fsi::common::guarded_main("run", [&] {
    if (check)
      return check_case(options);
    auto config = options.load();
    check_memory(config);
    const std::filesystem::path out = options.output_directory(config);
    if (config.is_flow_alone()) {
      spdlog::error("case {} has no structure: its flow runs alone (fsi-openfoam-fluid); run it with ./fsi run {}",
                    case_dir, case_dir);
      return fsi::common::exit_code_bad_input;
    }
    if (!coupled) {
      if (config.is_coupled())
        spdlog::warn("case {} has a fluid section; running the structure alone (no fluid load). Use ./fsi run "
                     "for the coupled run.",
                     case_dir);
      auto setup = fsi::case_config::structure_setup(std::move(config));
      setup.restart = options.restart;
      fsi::structure::StructureRun run(std::move(setup), case_dir, out);
      return run.run();
    }
    if (!config.is_coupled()) {
      spdlog::error("--coupled: case {} has no `fluid` section, so there is nothing to couple to", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    auto settings =
        fsi::case_config::participant_settings(config, options.endpoint, case_dir, fsi::proto::v2::ROLE_STRUCTURE);
    auto setup = fsi::case_config::structure_setup(std::move(config));
    setup.rigid_motions_from_coupler = true;                             // the coupler evaluates the prescribed motions
    settings.stop_signal = &fsi::structure::StructureRun::stop_signal(); // its handler, installed by the run
    fsi::structure::StructureRun run(std::move(setup), case_dir, out);
    fsi::structure::CoupledStructure structure(run);
    fsi::participant::StructureParticipant participant(structure, std::move(settings));
    return participant.run();
  });
}
