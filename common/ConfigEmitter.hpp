#pragma once
// Writes the effective configuration (every key, defaults included) as YAML: echoed in the
// log at start and saved with the results. Same visitor interface as ConfigReader.

#include "Range.hpp"
#include "Types.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fsi::common {

class ConfigEmitter {
public:
  explicit ConfigEmitter(YAML::Emitter &out) : out_(out) {}

  void number(const std::string &key, const double &value, const Range &, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void integer(const std::string &key, const int &value, const Range &, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void optional_number(const std::string &key, const std::optional<double> &value, const Range &range,
                       const std::string &doc) {
    if (value)
      number(key, *value, range, doc);
  }
  void optional_integer(const std::string &key, const std::optional<int> &value, const Range &range,
                        const std::string &doc) {
    if (value)
      integer(key, *value, range, doc);
  }
  void flag(const std::string &key, const bool &value, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void text(const std::string &key, const std::string &value, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void vec3(const std::string &key, const Vec3 &v, const std::string &, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << v[0] << v[1] << v[2]
         << YAML::EndSeq;
  }
  void vec2(const std::string &key, const Eigen::Vector2d &v, const Range &, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << v[0] << v[1] << YAML::EndSeq;
  }
  void int2(const std::string &key, const Eigen::Vector2i &v, const Range &, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << v[0] << v[1] << YAML::EndSeq;
  }
  void integer_list(const std::string &key, const std::vector<int> &v, const Range &, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const int entry : v)
      out_ << entry;
    out_ << YAML::EndSeq;
  }
  void existing_file(const std::string &key, const std::filesystem::path &value, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << value.string();
  }
  template <class Enum>
  void choice(const std::string &key, const Enum &value,
              const std::vector<std::pair<std::string, Enum>> &names, const std::string &) {
    for (const auto &[name, enumerator] : names)
      if (enumerator == value) { // the first name is canonical; later ones are aliases
        out_ << YAML::Key << key << YAML::Value << name;
        return;
      }
  }
  template <class Sub> void section(const std::string &key, Sub &sub, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    sub.visit(*this);
    out_ << YAML::EndMap;
  }
  template <class Sub>
  void optional_section(const std::string &key, std::optional<Sub> &sub, const std::string &doc) {
    if (sub)
      section(key, *sub, doc);
  }
  template <class Sub> void list(const std::string &key, std::vector<Sub> &items, const std::string &) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginSeq;
    for (auto &item : items) {
      out_ << YAML::BeginMap;
      item.visit(*this);
      out_ << YAML::EndMap;
    }
    out_ << YAML::EndSeq;
  }

private:
  YAML::Emitter &out_;
};

/// The effective configuration of `config` as YAML text.
template <class Config> std::string to_yaml(Config &config) {
  YAML::Emitter out;
  out.SetDoublePrecision(10);
  out << YAML::BeginMap;
  ConfigEmitter emitter(out);
  config.visit(emitter);
  out << YAML::EndMap;
  return out.c_str();
}

} // namespace fsi::common
