#include "CaseConfig.hpp"

#include <set>

namespace fsi::structure {

void CaseConfig::validate(common::ConfigReader &v) const {
  if (structures.empty())
    v.fail_value("structures", "must list at least one structure.");
  std::set<std::string> names;
  for (const auto &s : structures)
    if (!names.insert(s.name).second)
      v.fail_value("structures", "has two structures named '" + s.name + "'; names must be unique.");
  if (run.output_interval_s < run.time_step_s)
    v.fail_value("run", "output_interval_s must be at least time_step_s.");
  if (run.end_time_s < run.time_step_s)
    v.fail_value("run", "end_time_s must be at least one time step.");
}

CaseConfig CaseConfig::load(const std::filesystem::path &case_dir) {
  if (!std::filesystem::is_directory(case_dir))
    throw common::ConfigError(case_dir.string() + ": not a case folder (expected a folder holding case.yaml).");
  auto reader = common::ConfigReader::from_file(case_dir / "case.yaml");
  CaseConfig config;
  config.visit(reader);
  reader.finish();
  return config;
}

} // namespace fsi::structure
