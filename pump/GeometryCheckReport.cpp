#include "pump/GeometryCheckReport.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fsi::pump {
namespace {

void emit_number(YAML::Emitter &out, const std::string &key, double value) {
  out << YAML::Key << key << YAML::Value;
  if (std::isnan(value))
    out << YAML::Null;
  else
    out << value;
}

void emit_point(YAML::Emitter &out, const std::string &key, const Vec3 &p) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << p.x() << p.y() << p.z() << YAML::EndSeq;
}

} // namespace

std::string status_name(CheckStatus status) {
  switch (status) {
  case CheckStatus::pass:
    return "pass";
  case CheckStatus::fail:
    return "FAIL";
  case CheckStatus::skipped:
    return "skipped";
  }
  return "unknown";
}

CheckResult &GeometryCheckReport::add(const std::string &name, CheckStatus status, const std::string &value,
                                      const std::string &message) {
  checks.push_back({name, status, value, message});
  return checks.back();
}

bool GeometryCheckReport::passed() const { return first_failure() == nullptr; }

const CheckResult *GeometryCheckReport::first_failure() const {
  const auto failed =
      std::find_if(checks.begin(), checks.end(), [](const CheckResult &c) { return c.status == CheckStatus::fail; });
  return failed == checks.end() ? nullptr : &*failed;
}

std::string GeometryCheckReport::table() const {
  std::size_t name_width = 5, value_width = 5;
  for (const CheckResult &c : checks) {
    name_width = std::max(name_width, c.name.size());
    value_width = std::max(value_width, c.value.size());
  }
  std::ostringstream out;
  const auto row = [&](const std::string &name, const std::string &status, const std::string &value) {
    out << name << std::string(name_width + 2 - name.size(), ' ') << status << std::string(9 - status.size(), ' ')
        << value << '\n';
  };
  row("check", "status", "value");
  row(std::string(name_width, '-'), "-------", std::string(value_width, '-'));
  for (const CheckResult &c : checks)
    row(c.name, status_name(c.status), c.value);
  for (const CheckResult &c : checks)
    if (c.status == CheckStatus::fail)
      out << "\n" << c.name << ": " << c.message << '\n';
  return out.str();
}

std::string GeometryCheckReport::to_yaml() const {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "impeller_file" << YAML::Value << impeller_file;
  out << YAML::Key << "casing_file" << YAML::Value << casing_file;
  out << YAML::Key << "unit_scale" << YAML::Value << unit_scale;
  out << YAML::Key << "passed" << YAML::Value << passed();
  out << YAML::Key << "checks" << YAML::Value << YAML::BeginSeq;
  for (const CheckResult &c : checks) {
    out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << c.name << YAML::Key << "status" << YAML::Value
        << status_name(c.status) << YAML::Key << "value" << YAML::Value << c.value;
    if (!c.message.empty())
      out << YAML::Key << "message" << YAML::Value << c.message;
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "measures" << YAML::Value << YAML::BeginMap;
  emit_number(out, "impeller_volume_m3", impeller_volume_m3);
  emit_number(out, "casing_volume_m3", casing_volume_m3);
  emit_number(out, "min_clearance_m", min_clearance_m);
  emit_point(out, "closest_point_m", closest_point_m);
  emit_number(out, "throat_area_m2", throat_area_m2);
  emit_number(out, "design_throat_area_m2", design_throat_area_m2);
  emit_number(out, "throat_band_min_m2", throat_band_min_m2);
  emit_number(out, "throat_band_max_m2", throat_band_max_m2);
  emit_number(out, "free_passage_m", free_passage_m);
  emit_number(out, "free_passage_error_m", free_passage_error_m);
  emit_point(out, "bottleneck_m", bottleneck_m);
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

} // namespace fsi::pump
