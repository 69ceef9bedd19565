// fsi-coupler: the coupling daemon of a fluid-structure run (section 2.3).
//   fsi-coupler CASE_DIR                 bind coupling.endpoint, wait for the participants, run
//   fsi-coupler CASE_DIR --endpoint E    listen on E instead (e.g. tcp://0.0.0.0:5560 with security: curve)
//   fsi-coupler --make-keys CASE_DIR     make the CURVE keys of coupling.keys_dir (--force: new ones)
//   fsi-coupler CASE_DIR -o DIR          results (coupling.h5, coupler.log, coupler.endpoint) in DIR
//   fsi-coupler --plan CASE_DIR          print the output folder and the processes the scene needs
// Exit codes: 0 success, 1 a participant failed, 2 bad input or refused participant, 130 interrupted.

#include "coupler/CouplingRun.hpp"
#include "common/Allocator.hpp"
#include "common/ConfigError.hpp"
#include "common/Logging.hpp"

#include "proto/CurveKeyFolder.hpp"
#include "proto/ZmqContext.hpp"

#include "case/ChannelSettings.hpp"
#include "structure_solver/MemoryBudget.hpp"
#include "case/CaseOptions.hpp"
#include "case/ModuleSetups.hpp"
#include "common/ExitCodes.hpp"
#include "common/GuardedMain.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <csignal>
#include <iostream>

namespace {

extern "C" void on_stop_signal(int signal) { fsi::coupler::CouplingRun::stop_signal() = signal; }

/// The processes a case needs, for ./fsi run: "model only what a scene needs".
int print_plan(const fsi::case_config::CaseConfig &config, const std::string &case_dir,
               const std::filesystem::path &output_dir) {
  std::cout << "output " << std::filesystem::absolute(output_dir).lexically_normal().string() << "\n";
  if (config.is_coupled()) {
    std::cout << "process coupler fsi-coupler\n";
    std::cout << "process structure fsi-structure\n";
    std::cout << "process fluid " << config.fluid->executable() << "\n";
    if (config.fluid->openfoam && config.fluid->openfoam->precursor_time_s > 0.0)
      std::cout << "precursor fluid\n"; // fsi-openfoam-fluid --precursor, before the others start
    if (config.coupling->security == fsi::coupler::CouplingConfig::Security::curve)
      std::cout << "keys " << std::filesystem::absolute(fsi::case_config::keys_folder(config, case_dir)).lexically_normal().string()
                << "\n"; // made by the launcher when missing (a run on one host)
  } else if (config.is_flow_alone()) {
    std::cout << "process fluid " << config.fluid->executable() << "\n"; // the flow alone with its rigid bodies
  } else {
    std::cout << "process structure fsi-structure\n";
  }
  return 0;
}

/// ./fsi keys CASE: the key pairs of the coupler and each participant, kept when present.
int make_keys(const fsi::case_config::CaseConfig &config, const std::string &case_dir, bool force) {
  const fsi::proto::CurveKeyFolder keys(fsi::case_config::keys_folder(config, case_dir));
  const auto written = keys.make(fsi::case_config::curve_key_names(), force);
  const std::string folder = keys.folder().lexically_normal().string();
  if (written.empty())
    std::cout << "CURVE keys in " << folder << " already made (--force makes new ones)\n";
  else
    std::cout << "made CURVE keys in " << folder << " for: " << fsi::common::join(written) << "\n";
  if (config.coupling->security != fsi::coupler::CouplingConfig::Security::curve)
    std::cout << "note: the case does not use them yet; set coupling.security: curve\n";
  std::cout << "each host needs: the coupler's host coupler.key_secret, structure.key, fluid.key; a participant's "
               "host its <role>.key_secret and coupler.key (docs/security.md)\n";
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  const fsi::proto::ZmqContextCloser zmq_closer; // outlives every channel: last messages get out
  CLI::App app{"fsi-coupler: the coupling daemon of a fluid-structure run"};
  fsi::case_config::CaseOptions options;
  bool plan = false, keys = false, force = false;
  options.add_to(app, true, "Listen here instead of coupling.endpoint");
  app.add_flag("--plan", plan, "Print the output folder and the processes this case needs, then exit");
  app.add_flag("--make-keys", keys, "Make the CURVE keys of coupling.keys_dir (kept when present), then exit");
  app.add_flag("--force", force, "With --make-keys: replace existing keys");
  if (const int code = fsi::case_config::parse_command_line(app, argc, argv); code >= 0)
    return code;
  fsi::common::setup_logging("coupler", options.verbose);
  fsi::common::keep_freed_memory(); // before the solver allocates (common/Allocator.hpp)
  return fsi::common::guarded_main("coupler", [&] {
    auto config = options.load();
    const std::string &case_dir = options.case_dir;
    const std::filesystem::path out = options.output_directory(config);
    if (plan) {
      // Before any process starts or any folder is made: a structure grid that cannot fit.
      fsi::structure::MemoryBudget::check_fits(config.structures, fsi::structure::MemoryBudget::available_bytes());
      return print_plan(config, case_dir, out);
    }
    if (keys && !config.coupling) {
      spdlog::error("case {} has no coupling section: a single process needs no keys", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    if (keys)
      return make_keys(config, case_dir, force);
    if (!config.is_coupled()) {
      spdlog::error("case {} is {}: it needs no coupler; run it with ./fsi run {}", case_dir,
                    config.is_flow_alone() ? "the flow alone (no structure)" : "a structure-only scene", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    auto setup = fsi::case_config::coupling_setup(std::move(config), case_dir);
    setup.restart = options.restart;
    fsi::coupler::CouplingRun run(std::move(setup), out, options.endpoint);
    return run.run();
  });
}
