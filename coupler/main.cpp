// fsi-coupler: the coupling daemon of a fluid-structure run (section 2.3).
//   fsi-coupler CASE_DIR                 bind coupling.endpoint, wait for the participants, run
//   fsi-coupler CASE_DIR --endpoint E    listen on E instead (e.g. tcp://0.0.0.0:5560 with allow_remote)
//   fsi-coupler CASE_DIR -o DIR          results (coupling.h5, coupler.log, coupler.endpoint) in DIR
//   fsi-coupler --plan CASE_DIR          print the output folder and the processes the scene needs
// Exit codes: 0 success, 1 a participant failed, 2 bad input or refused participant, 130 interrupted.

#include "CouplingRun.hpp"
#include "common/Allocator.hpp"
#include "common/ConfigError.hpp"
#include "common/Logging.hpp"

#include "proto/ZmqContext.hpp"

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
int print_plan(const fsi::case_config::CaseConfig &config, const std::filesystem::path &output_dir) {
  std::cout << "output " << std::filesystem::absolute(output_dir).lexically_normal().string() << "\n";
  if (config.is_coupled()) {
    std::cout << "process coupler fsi-coupler\n";
    std::cout << "process structure fsi-structure\n";
    std::cout << "process fluid " << config.fluid->executable() << "\n";
    if (config.fluid->openfoam && config.fluid->openfoam->precursor_time_s > 0.0)
      std::cout << "precursor fluid\n"; // fsi-openfoam-fluid --precursor, before the others start
  } else if (config.is_flow_alone()) {
    std::cout << "process fluid " << config.fluid->executable() << "\n"; // the flow alone with its rigid bodies
  } else {
    std::cout << "process structure fsi-structure\n";
  }
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  const fsi::proto::ZmqContextCloser zmq_closer; // outlives every channel: last messages get out
  CLI::App app{"fsi-coupler: the coupling daemon of a fluid-structure run"};
  fsi::case_config::CaseOptions options;
  std::string endpoint;
  bool plan = false, verbose = false;
  options.add_to(app);
  app.add_option("--endpoint", endpoint, "Listen here instead of coupling.endpoint");
  app.add_flag("--plan", plan, "Print the output folder and the processes this case needs, then exit");
  app.add_flag("-v,--verbose", verbose, "Debug logging");
  if (const int code = fsi::case_config::parse_command_line(app, argc, argv); code >= 0)
    return code;
  fsi::common::setup_logging("coupler", verbose);
  fsi::common::keep_freed_memory(); // before the solver allocates (common/Allocator.hpp)
  return fsi::common::guarded_main("coupler", [&] {
    auto config = options.load();
    const std::string &case_dir = options.case_dir;
    const std::filesystem::path out = options.output_directory(config);
    if (plan)
      return print_plan(config, out);
    if (!config.is_coupled()) {
      spdlog::error("case {} is {}: it needs no coupler; run it with ./fsi run {}", case_dir,
                    config.is_flow_alone() ? "the flow alone (no structure)" : "a structure-only scene", case_dir);
      return fsi::common::exit_code_bad_input;
    }
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    auto setup = fsi::case_config::coupling_setup(std::move(config));
    setup.restart = options.restart;
    fsi::coupler::CouplingRun run(std::move(setup), out, endpoint);
    return run.run();
  });
}
