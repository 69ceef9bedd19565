#include "CaseConfig.hpp"

#include "common/ConfigEmitter.hpp"
#include "common/DidYouMean.hpp"
#include "common/Fnv1a.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <cstdio>
#include <algorithm>
#include <set>

namespace fsi::case_config {

void CaseConfig::validate(common::ConfigReader &v) const {
  if (structures.empty() && !(fluid && fluid->openfoam))
    v.fail_value("structures", "must list at least one structure (none only with `fluid.openfoam`: the flow alone with "
                               "its rigid bodies, as in cases/centrifugal-pump).");
  std::set<std::string> names;
  for (const auto &s : structures)
    if (!names.insert(s.name).second)
      v.fail_value("structures", "has two structures named '" + s.name + "'; names must be unique" +
                                     (n_fed > 0 ? " (the feed names its rags after their kind: rag01, rag02, ...)."
                                                : "."));
  if (run.output_interval_s < run.time_step_s)
    v.fail_value("run", "output_interval_s must be at least time_step_s.");
  if (fluid && !coupling && !structures.empty())
    v.fail_value("fluid", "needs a `coupling` section (at least `coupling: {law: penalty}`).");
  if (coupling && !fluid)
    v.fail_value("coupling", "is given but there is no `fluid` section: remove it for a structure-only run, or add "
                             "`fluid`.");
  if (run.end_time_s < run.time_step_s)
    v.fail_value("run", "end_time_s must be at least one time step.");
  validate_probes(v);
}

void CaseConfig::expand_feed(common::ConfigReader &v) {
  std::vector<structure::feed::Release> releases;
  try {
    releases = structure::feed::draw_releases(feed->plan());
  } catch (const std::invalid_argument &e) {
    v.fail_value("feed", std::string("cannot be drawn: ") + e.what() + ".");
  }
  YAML::Node root = v.node();
  if (!root["structures"])
    root["structures"] = YAML::Node(YAML::NodeType::Sequence);
  YAML::Node list = root["structures"];
  const YAML::Node kinds = root["feed"]["kinds"];
  const auto vec = [](const Vec3 &x) {
    YAML::Node n(YAML::NodeType::Sequence);
    for (int k = 0; k < 3; ++k)
      n.push_back(x[k]);
    n.SetStyle(YAML::EmitterStyle::Flow);
    return n;
  };
  for (const auto &r : releases) {
    YAML::Node rag = YAML::Clone(kinds[static_cast<std::size_t>(r.kind)]);
    const std::string base = rag["name"] ? rag["name"].as<std::string>() : "rag";
    rag["name"] = fmt::format("{}{:02d}", base, r.index + 1);
    rag["release_time_s"] = r.time_s;
    const Eigen::AngleAxisd turn(r.turn);
    YAML::Node placement;
    placement["centre_m"] = vec(r.centre_m);
    placement["turn_axis"] = vec(turn.axis());
    placement["turn_angle_deg"] = turn.angle() * 180.0 / M_PI;
    rag["placement"] = placement;
    if (!rag["remove_when_past"] && feed->remove_when_past) {
      YAML::Node plane;
      plane["point_m"] = vec(feed->remove_when_past->point_m);
      plane["normal"] = vec(feed->remove_when_past->normal);
      rag["remove_when_past"] = plane;
    }
    list.push_back(rag);
  }
  n_fed = releases.size();
}

void CaseConfig::validate_probes(const common::ConfigReader &v) const {
  std::set<std::string> names;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const common::ConfigReader item = v.list_item("probes", i);
    if (!names.insert(probes[i].name).second)
      item.fail_value("name", "= '" + probes[i].name + "' is used by two probes; probe names must be unique.");
    probes[i].check_against(structures, item);
  }
}

std::vector<std::string> CaseConfig::presets(const std::filesystem::path &case_dir) {
  std::vector<std::string> names;
  if (std::filesystem::is_directory(case_dir / "presets"))
    for (const auto &entry : std::filesystem::directory_iterator(case_dir / "presets"))
      if (entry.path().extension() == ".yaml")
        names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

CaseConfig CaseConfig::load(const std::filesystem::path &case_dir, const std::string &preset,
                            const std::vector<std::string> &assignments) {
  if (!std::filesystem::is_directory(case_dir))
    throw common::ConfigError(case_dir.string() + ": not a case folder (expected a folder holding case.yaml).");
  const auto overlay = case_dir / "presets" / (preset + ".yaml");
  if (!preset.empty() && !std::filesystem::exists(overlay)) {
    const auto available = presets(case_dir);
    throw common::ConfigError(
        case_dir.string() + ": no preset '" + preset + "' (" + overlay.string() + ")." +
        common::did_you_mean(preset, available) +
        (available.empty() ? " This case has no presets." : " Presets of this case: " + common::join(available) + "."));
  }
  auto reader = (preset.empty() ? common::ConfigReader::from_file(case_dir / "case.yaml")
                                : common::ConfigReader::from_file_with_overlay(case_dir / "case.yaml", overlay))
                    .with_assignments(assignments);
  CaseConfig config;
  config.visit(reader);
  reader.finish();
  return config;
}

namespace {

/// The case's effective configuration without what may differ between runs of the same case.
YAML::Node comparable_node(CaseConfig &config, const std::vector<std::string> &run_keys_left_out) {
  // The emitter only reads; visit() is non-const because the reader shares it.
  YAML::Node node = YAML::Load(common::to_yaml(config));
  node["run"].remove("output_directory");
  node["run"].remove("progress_interval_s");
  for (const auto &key : run_keys_left_out)
    node["run"].remove(key);
  if (node["coupling"])
    node["coupling"].remove("endpoint");
  return node;
}

std::string fingerprint_of(CaseConfig &config, const std::vector<std::string> &run_keys_left_out) {
  const std::string text = YAML::Dump(comparable_node(config, run_keys_left_out));
  common::Fnv1a hash;
  hash.add_bytes(text);
  return hash.hex();
}

/// `node` as "key = value" lines: maps by dotted keys, lists of sections by index
/// (structures[0].name), lists of scalars and empty collections as one value ([0, 0, -9.81]).
void flatten(const YAML::Node &node, const std::string &key, std::string &lines) {
  const auto inline_value = [](const YAML::Node &n) {
    YAML::Emitter out;
    out.SetDoublePrecision(17);
    out << YAML::Flow << n;
    return std::string(out.c_str());
  };
  bool all_scalars = true;
  if (node.IsSequence())
    for (const auto &item : node)
      all_scalars = all_scalars && item.IsScalar();
  if (node.IsMap() && node.size() > 0) {
    for (const auto &entry : node)
      flatten(entry.second, (key.empty() ? "" : key + ".") + entry.first.Scalar(), lines);
  } else if (node.IsSequence() && node.size() > 0 && !all_scalars) {
    for (std::size_t i = 0; i < node.size(); ++i)
      flatten(node[i], key + "[" + std::to_string(i) + "]", lines);
  } else {
    lines += key + " = " + (node.IsScalar() ? node.Scalar() : inline_value(node)) + "\n";
  }
}

} // namespace

std::string CaseConfig::fingerprint() const { return fingerprint_of(const_cast<CaseConfig &>(*this), {}); }

namespace {
// What a restart may change: where the run ends and how often it checkpoints.
const std::vector<std::string> restart_may_change = {"end_time_s", "checkpoint_interval_s", "checkpoint_keep"};
} // namespace

std::string CaseConfig::restart_fingerprint() const {
  return fingerprint_of(const_cast<CaseConfig &>(*this), restart_may_change);
}

checkpoint::CaseIdentity CaseConfig::restart_identity() const {
  std::string keys;
  flatten(comparable_node(const_cast<CaseConfig &>(*this), restart_may_change), "", keys);
  return {restart_fingerprint(), keys};
}

} // namespace fsi::case_config
