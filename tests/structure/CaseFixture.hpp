#pragma once
// Test support: writes a case.yaml into a fresh temporary folder and builds the scene
// through the real parser, so tests exercise the same path as `fsi-structure CASE_DIR`; runs
// the real executable.

#include "case/CaseConfig.hpp"
#include "case/ModuleSetups.hpp"
#include "structure_solver/LagrangianSheet.hpp"
#include "structure_solver/Scene.hpp"
#include "tests/support/TempPath.hpp"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

namespace fsi::structure::testing {

inline std::filesystem::path make_case_dir(const std::string &yaml) {
  const auto dir = fsi::test_support::temp_path("fsi-test-");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "case.yaml") << yaml;
  return dir;
}

/// The structure solver's part of the case, through the real parser (case/ModuleSetups.hpp).
inline StructureSetup load_case(const std::string &yaml) {
  return case_config::structure_setup(case_config::CaseConfig::load(make_case_dir(yaml)));
}

/// Exit code and everything printed (stdout and stderr) of one run of the executable.
struct SolverOutcome {
  int exit_code;
  std::string output;
};

/// Runs `prefix fsi-structure arguments` (prefix: e.g. a `timeout` command) and waits for it.
inline SolverOutcome run_structure_solver(const std::string &arguments, const std::string &prefix = "") {
  const std::string command = prefix + std::string(FSI_STRUCTURE_EXE) + " " + arguments + " 2>&1";
  FILE *pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe))
    output += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), output};
}

inline LagrangianSheet &sheet(const Scene &scene, std::size_t index = 0) {
  return dynamic_cast<LagrangianSheet &>(*scene.structures().at(index));
}

/// Times at which `signal` crosses zero upward (linear interpolation between samples).
inline std::vector<double> upward_crossings(const std::vector<double> &time, const std::vector<double> &signal) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < signal.size(); ++i)
    if (signal[i - 1] < 0.0 && signal[i] >= 0.0)
      crossings.push_back(time[i - 1] + (time[i] - time[i - 1]) * (-signal[i - 1]) / (signal[i] - signal[i - 1]));
  return crossings;
}

/// Mean period from upward zero crossings (needs at least two).
inline double mean_period(const std::vector<double> &crossings) {
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

} // namespace fsi::structure::testing
