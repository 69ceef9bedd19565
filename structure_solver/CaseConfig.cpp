#include "CaseConfig.hpp"

#include "common/ConfigEmitter.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <cstdio>
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
  if (fluid && !coupling)
    v.fail_value("fluid", "needs a `coupling` section (at least `coupling: {law: penalty}`).");
  if (coupling && !fluid)
    v.fail_value("coupling", "is given but there is no `fluid` section: remove it for a structure-only run, or add "
                             "`fluid`.");
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

std::string CaseConfig::fingerprint() const {
  // The emitter only reads; visit() is non-const because the reader shares it.
  YAML::Node node = YAML::Load(common::to_yaml(const_cast<CaseConfig &>(*this)));
  node["run"].remove("output_directory");
  node["run"].remove("progress_interval_s");
  if (node["coupling"])
    node["coupling"].remove("endpoint");
  const std::string text = YAML::Dump(node);
  std::uint64_t hash = 14695981039346656037ull; // FNV-1a, 64 bit: stable across builds
  for (const unsigned char c : text)
    hash = (hash ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

} // namespace fsi::structure
