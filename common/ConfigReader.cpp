#include "ConfigReader.hpp"

#include "DidYouMean.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fsi::common {

ConfigReader::ConfigReader(YAML::Node node, std::filesystem::path file, std::string key_path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(key_path)) {}

namespace {

YAML::Node load_yaml(const std::filesystem::path &file) {
  try {
    return YAML::LoadFile(file.string());
  } catch (const YAML::Exception &e) {
    throw ConfigError(file.string() + ":" + std::to_string(e.mark.line + 1) + ":" +
                      std::to_string(e.mark.column + 1) + ": not valid YAML: " + e.msg + ".");
  }
}

YAML::Node merged(const YAML::Node &base, const YAML::Node &overlay) {
  if (base.IsMap() && overlay.IsMap()) {
    YAML::Node out = YAML::Clone(base);
    for (const auto &item : overlay) {
      const std::string key = item.first.as<std::string>();
      out[key] = base[key] ? merged(base[key], item.second) : YAML::Clone(item.second);
    }
    return out;
  }
  if (base.IsSequence() && overlay.IsSequence() && base.size() == overlay.size()) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (std::size_t i = 0; i < base.size(); ++i)
      out.push_back(merged(base[i], overlay[i]));
    return out;
  }
  return YAML::Clone(overlay);
}

} // namespace

ConfigReader ConfigReader::from_file(const std::filesystem::path &file) {
  if (!std::filesystem::exists(file))
    throw ConfigError(file.string() + ": case file not found. A case folder holds a 'case.yaml'.");
  ConfigReader reader(load_yaml(file), file, "");
  reader.require_mapping();
  return reader;
}

ConfigReader ConfigReader::from_file_with_overlay(const std::filesystem::path &file,
                                                  const std::filesystem::path &overlay) {
  ConfigReader base = from_file(file);
  const YAML::Node top = load_yaml(overlay);
  if (!top.IsMap())
    throw ConfigError(overlay.string() + ": a preset must be a mapping of case keys to override.");
  ConfigReader reader(merged(base.node_, top), file, "");
  reader.require_mapping();
  return reader;
}

ConfigReader ConfigReader::with_assignments(const std::vector<std::string> &assignments) const {
  YAML::Node node = node_;
  for (const auto &assignment : assignments) {
    const auto equals = assignment.find('=');
    const std::string key = assignment.substr(0, equals);
    const auto bad = [&](const std::string &why) {
      return ConfigError("--set '" + assignment + "': " + why +
                         " (expected KEY=VALUE, the key a dotted path of case.yaml such as "
                         "fluid.openfoam.operating_point.flow_rate_m3_per_s).");
    };
    if (equals == std::string::npos || equals + 1 == assignment.size())
      throw bad("no value");
    std::vector<std::string> path;
    std::stringstream parts(key);
    for (std::string part; std::getline(parts, part, '.');)
      path.push_back(part);
    if (key.empty() || key.back() == '.' ||
        std::any_of(path.begin(), path.end(), [](const std::string &part) { return part.empty(); }))
      throw bad("an empty key");
    YAML::Node value;
    try {
      value = YAML::Load(assignment.substr(equals + 1));
    } catch (const YAML::Exception &e) {
      throw bad("the value is not valid YAML: " + e.msg);
    }
    for (auto part = path.rbegin(); part != path.rend(); ++part) {
      YAML::Node level(YAML::NodeType::Map);
      level[*part] = value;
      value = level;
    }
    node = merged(node, value);
  }
  return ConfigReader(node, file_, path_);
}

void ConfigReader::require_mapping() const {
  if (!node_.IsMap())
    fail("must be a mapping of 'key: value' lines.");
}

std::string ConfigReader::location(const YAML::Node &node) const {
  std::string where = file_.string();
  if (node && node.Mark().line >= 0)
    where += ":" + std::to_string(node.Mark().line + 1);
  return where;
}

void ConfigReader::fail_at(const YAML::Node &node, const std::string &key, const std::string &message) const {
  throw ConfigError(location(node) + ": " + path_of(key) + " " + message);
}

void ConfigReader::fail(const std::string &message) const {
  throw ConfigError(location(node_) + ": " + (path_.empty() ? std::string("case") : path_) + " " + message);
}

void ConfigReader::require_exactly_one(std::initializer_list<std::pair<const char *, bool>> sections) const {
  std::vector<std::string> names;
  int given = 0;
  for (const auto &[name, present] : sections) {
    names.emplace_back(name);
    given += present;
  }
  if (given != 1)
    fail("must hold exactly one of: " + join(names) + " (found " + std::to_string(given) + ").");
}

void ConfigReader::fail_value(const std::string &key, const std::string &message) const {
  fail_at(node_[key] ? node_[key] : node_, key, message);
}

std::string ConfigReader::join_names(const std::vector<std::string> &names) { return join(names); }

std::string ConfigReader::suggest(const std::string &word, const std::vector<std::string> &names) {
  return did_you_mean(word, names);
}

template <class T> bool ConfigReader::read_scalar(const std::string &key, T &out) {
  mark_known(key);
  const YAML::Node value = node_[key];
  if (!value || value.IsNull())
    return false;
  if (!value.IsScalar())
    fail_at(value, key, "must be a single value, not a list or mapping.");
  try {
    out = value.as<T>();
  } catch (const YAML::Exception &) {
    fail_at(value, key, "= '" + value.Scalar() + "' is not a valid value of this key's type.");
  }
  return true;
}

void ConfigReader::number(const std::string &key, double &value, const Range &range, const std::string &) {
  if (!read_scalar(key, value))
    return;
  if (!std::isfinite(value) || !range.contains(value)) {
    std::ostringstream message;
    message << "= " << node_[key].Scalar() << " is out of range: allowed " << range.describe() << " "
            << range.unit << ".";
    fail_value(key, message.str());
  }
}

void ConfigReader::integer(const std::string &key, int &value, const Range &range, const std::string &) {
  if (!read_scalar(key, value))
    return;
  if (!range.contains(value))
    fail_value(key, "= " + node_[key].Scalar() + " is out of range: allowed " + range.describe() + ".");
}

template <class T>
void ConfigReader::read_optional(const std::string &key, std::optional<T> &value, const Range &range,
                                 const std::string &doc,
                                 void (ConfigReader::*read)(const std::string &, T &, const Range &,
                                                            const std::string &)) {
  mark_known(key);
  if (!node_[key] || node_[key].IsNull())
    return;
  T read_value{};
  (this->*read)(key, read_value, range, doc);
  value = read_value;
}

void ConfigReader::optional_number(const std::string &key, std::optional<double> &value, const Range &range,
                                   const std::string &doc) {
  read_optional(key, value, range, doc, &ConfigReader::number);
}

void ConfigReader::optional_integer(const std::string &key, std::optional<int> &value, const Range &range,
                                    const std::string &doc) {
  read_optional(key, value, range, doc, &ConfigReader::integer);
}

void ConfigReader::flag(const std::string &key, bool &value, const std::string &) {
  read_scalar(key, value);
}

void ConfigReader::text(const std::string &key, std::string &value, const std::string &) {
  read_scalar(key, value);
}

namespace {
std::vector<double> read_numbers(const YAML::Node &node, std::size_t expected) {
  if (!node.IsSequence() || node.size() != expected)
    throw std::invalid_argument("size");
  std::vector<double> out;
  for (const auto &item : node)
    out.push_back(item.as<double>());
  return out;
}
} // namespace

void ConfigReader::vec3(const std::string &key, Vec3 &value, const std::string &unit, const std::string &) {
  mark_known(key);
  if (!node_[key])
    return;
  try {
    const auto v = read_numbers(node_[key], 3);
    value = Vec3(v[0], v[1], v[2]);
  } catch (const std::exception &) {
    fail_value(key, "must be a list of three numbers [x, y, z] in " + unit + ".");
  }
  if (!value.allFinite())
    fail_value(key, "must hold finite numbers.");
}

void ConfigReader::vec2(const std::string &key, Eigen::Vector2d &value, const Range &range, const std::string &) {
  mark_known(key);
  if (!node_[key])
    return;
  try {
    const auto v = read_numbers(node_[key], 2);
    value = Eigen::Vector2d(v[0], v[1]);
  } catch (const std::exception &) {
    fail_value(key, "must be a list of two numbers [a, b] in " + range.unit + ".");
  }
  if (!range.contains(value[0]) || !range.contains(value[1]))
    fail_value(key, "is out of range: each entry must be " + range.describe() + " " + range.unit + ".");
}

void ConfigReader::int2(const std::string &key, Eigen::Vector2i &value, const Range &range, const std::string &) {
  mark_known(key);
  if (!node_[key])
    return;
  try {
    const auto v = read_numbers(node_[key], 2);
    if (v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
      throw std::invalid_argument("integer");
    value = Eigen::Vector2i(static_cast<int>(v[0]), static_cast<int>(v[1]));
  } catch (const std::exception &) {
    fail_value(key, "must be a list of two integers [n1, n2].");
  }
  if (!range.contains(value[0]) || !range.contains(value[1]))
    fail_value(key, "is out of range: each entry must be " + range.describe() + ".");
}

void ConfigReader::integer_list(const std::string &key, std::vector<int> &value, const Range &range,
                                const std::string &) {
  mark_known(key);
  const YAML::Node seq = node_[key];
  if (!seq || seq.IsNull())
    return;
  std::vector<int> read;
  try {
    if (!seq.IsSequence())
      throw std::invalid_argument("not a list");
    for (const auto &item : seq)
      read.push_back(item.as<int>());
  } catch (const std::exception &) {
    fail_value(key, "must be a list of integers, e.g. [3, 7].");
  }
  for (const int entry : read)
    if (!range.contains(entry))
      fail_value(key, "is out of range: each entry must be " + range.describe() + ".");
  value = read;
}

void ConfigReader::existing_file(const std::string &key, std::filesystem::path &value, const std::string &) {
  std::string text_value;
  if (!read_scalar(key, text_value))
    return;
  std::filesystem::path path(text_value);
  if (path.is_relative())
    path = file_.parent_path() / path;
  if (!std::filesystem::is_regular_file(path))
    fail_value(key, "= '" + text_value + "': file not found (looked for " + path.string() + ").");
  value = path;
}

ConfigReader ConfigReader::list_item(const std::string &key, std::size_t index) const {
  return ConfigReader(node_[key][index], file_, path_of(key) + "[" + std::to_string(index) + "]");
}

ConfigReader ConfigReader::child_reader(const std::string &key) {
  ConfigReader child(node_[key], file_, path_of(key));
  child.require_mapping();
  return child;
}

void ConfigReader::finish() const {
  if (!node_.IsMap())
    return;
  std::vector<std::string> valid(known_.begin(), known_.end());
  for (const auto &entry : node_) {
    const std::string key = entry.first.Scalar();
    if (known_.count(key))
      continue;
    throw ConfigError(location(entry.first) + ": unknown key '" + path_of(key) + "'." +
                      did_you_mean(key, valid) + " Valid keys here: " + join(valid) + ".");
  }
}

} // namespace fsi::common
