#pragma once
// The command-line options every process of a run takes to find its case (fsi-structure,
// fsi-coupler, fsi-prescribed-flow, fsi-openfoam-fluid): the case folder, the results folder,
// the preset, keys set on the command line, an earlier end time, a restart, the coupler's
// endpoint and debug logging. The launcher passes the same values to every process,
// so all of them load the same configuration (and agree on its fingerprint). Header-only: only
// the executables link CLI11.

#include "CaseConfig.hpp"
#include "common/ConfigError.hpp"
#include "common/ExitCodes.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fsi::case_config {

struct CaseOptions {
  std::string case_dir, output_dir, preset;
  std::vector<std::string> assignments; ///< --set KEY=VALUE, in order, over the preset
  double end_time_s = 0.0; ///< 0: run.end_time_s of the case
  bool restart = false;    ///< resume from the newest complete checkpoint in the results folder
  std::string endpoint;    ///< --endpoint: "" for coupling.endpoint of the case
  bool verbose = false;    ///< -v: debug logging

  /// endpoint_help: what --endpoint means for this process (the coupler binds it, a participant
  /// connects to it).
  void add_to(CLI::App &app, bool case_required = true,
              const std::string &endpoint_help = "Coupler endpoint (default: coupling.endpoint of the case)") {
    auto *option = app.add_option("case_dir", case_dir, "Case folder holding case.yaml");
    if (case_required)
      option->required();
    app.add_option("-o,--output-dir", output_dir, "Results folder (default: run.output_directory of the case)");
    app.add_option("--resolution,--preset", preset,
                   "Preset of the case: presets/<NAME>.yaml merged over case.yaml (e.g. coarse, medium, fine)");
    app.add_option("--set", assignments,
                   "Set a key of the case over case.yaml and the preset, e.g. --set "
                   "fluid.openfoam.operating_point.flow_rate_m3_per_s=0.0076 (repeatable; checked as in the file)")
        ->allow_extra_args(false);
    app.add_option("--end-time", end_time_s,
                   "Stop at this simulated time (s) instead of run.end_time_s (a quick look, or a few steps in CI)")
        ->check(CLI::Validator(
            [](const std::string &text) {
              double value = 0.0;
              return CLI::detail::lexical_cast(text, value) && value > 0.0
                         ? std::string()
                         : "must be a time in seconds > 0, got '" + text + "'";
            },
            "SECONDS > 0"));
    app.add_flag("--restart", restart,
                 "Resume from the newest complete checkpoint in the results folder (run.checkpoint_interval_s), "
                 "appending to its results");
    app.add_option("--endpoint", endpoint, endpoint_help);
    app.add_flag("-v,--verbose", verbose, "Debug logging");
  }

  /// The case file with the preset merged over it and the end time applied.
  CaseConfig load() const {
    CaseConfig config = CaseConfig::load(case_dir, preset, assignments);
    if (end_time_s > 0.0)
      config.run.end_time_s = end_time_s;
    return config;
  }

  std::filesystem::path output_directory(const CaseConfig &config) const {
    return config.output_directory(case_dir, output_dir);
  }
};

/// CLI11's parse with the project's exit codes: -1 to go on, else the code to exit with
/// (0 after --help, exit_code_bad_input for a bad command line).
inline int parse_command_line(CLI::App &app, int argc, char **argv) {
  try {
    app.parse(argc, argv);
    return -1;
  } catch (const CLI::ParseError &e) {
    const int code = app.exit(e);
    return e.get_exit_code() == 0 ? code : common::exit_code_bad_input;
  }
}

} // namespace fsi::case_config
