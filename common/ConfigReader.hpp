#pragma once
// Fills a typed configuration struct from a YAML mapping. Configuration structs declare their
// keys once, in a `template <class V> void visit(V&)` member; the same declaration drives this
// reader, the ConfigEmitter (effective configuration echo) and the ConfigDocWriter (reference
// tables). Unknown keys are errors with a spelling suggestion; every message names the file,
// the line and the full key path.

#include "ConfigError.hpp"
#include "Range.hpp"
#include "Types.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fsi::common {

class ConfigReader {
public:
  /// `file` is used in messages and to resolve relative paths; `key_path` prefixes key names.
  ConfigReader(YAML::Node node, std::filesystem::path file, std::string key_path = "");

  static ConfigReader from_file(const std::filesystem::path &file);
  /// As from_file, with the overlay file (a preset) merged in first: mappings merge key by
  /// key, lists of mappings of the same length item by item, anything else is replaced.
  static ConfigReader from_file_with_overlay(const std::filesystem::path &file, const std::filesystem::path &overlay);
  /// This reader's mapping with each assignment "a.b.c=VALUE" merged over it as a preset would
  /// be (VALUE read as YAML: 0.0076, word, [1, 2, 3]; the key path through mappings only). Throws
  /// ConfigError naming a malformed assignment. The keys are then checked as any other.
  ConfigReader with_assignments(const std::vector<std::string> &assignments) const;

  void number(const std::string &key, double &value, const Range &range, const std::string &doc);
  void integer(const std::string &key, int &value, const Range &range, const std::string &doc);
  /// A number that may be absent (or null): empty then, else read and checked as `number`.
  void optional_number(const std::string &key, std::optional<double> &value, const Range &range,
                       const std::string &doc);
  /// An integer that may be absent (or null): empty then, else read and checked as `integer`.
  void optional_integer(const std::string &key, std::optional<int> &value, const Range &range,
                        const std::string &doc);
  void flag(const std::string &key, bool &value, const std::string &doc);
  void text(const std::string &key, std::string &value, const std::string &doc);
  void vec3(const std::string &key, Vec3 &value, const std::string &unit, const std::string &doc);
  void vec2(const std::string &key, Eigen::Vector2d &value, const Range &range, const std::string &doc);
  void int2(const std::string &key, Eigen::Vector2i &value, const Range &range, const std::string &doc);
  /// A list of integers of any length (e.g. grid indices [i1, i2]); each entry within `range`.
  void integer_list(const std::string &key, std::vector<int> &value, const Range &range, const std::string &doc);
  /// A file path, resolved against the case file's folder; it must exist when given.
  void existing_file(const std::string &key, std::filesystem::path &value, const std::string &doc);

  template <class Enum>
  void choice(const std::string &key, Enum &value,
              const std::vector<std::pair<std::string, Enum>> &names, const std::string &doc) {
    std::string name;
    if (!read_scalar(key, name))
      return;
    for (const auto &[candidate, enumerator] : names)
      if (candidate == name) {
        value = enumerator;
        return;
      }
    std::vector<std::string> valid;
    for (const auto &entry : names)
      valid.push_back(entry.first);
    fail_value(key, "'" + name + "' is not one of: " + join_names(valid) + "." + suggest(name, valid));
    (void)doc;
  }

  template <class Sub> void section(const std::string &key, Sub &sub, const std::string &doc) {
    (void)doc;
    mark_known(key);
    if (!node_[key])
      return;
    ConfigReader child = child_reader(key);
    sub.visit(child);
    child.finish();
  }

  template <class Sub>
  void optional_section(const std::string &key, std::optional<Sub> &sub, const std::string &doc) {
    (void)doc;
    mark_known(key);
    if (!node_[key] || node_[key].IsNull())
      return;
    sub.emplace();
    ConfigReader child = child_reader(key);
    sub->visit(child);
    child.finish();
  }

  template <class Sub> void list(const std::string &key, std::vector<Sub> &items, const std::string &doc) {
    (void)doc;
    mark_known(key);
    const YAML::Node seq = node_[key];
    if (!seq)
      return;
    if (!seq.IsSequence())
      fail_at(seq, key, "must be a list (YAML '- ' items).");
    items.clear();
    for (std::size_t i = 0; i < seq.size(); ++i) {
      ConfigReader child = list_item(key, i);
      child.require_mapping();
      items.emplace_back();
      items.back().visit(child);
      child.finish();
    }
  }

  /// Reports unknown keys of this mapping. Call after all keys were declared.
  void finish() const;

  /// A user error about this mapping as a whole (e.g. a combination of keys).
  [[noreturn]] void fail(const std::string &message) const;
  /// A user error about one key of this mapping.
  [[noreturn]] void fail_value(const std::string &key, const std::string &message) const;
  /// The sections of one choice (a surface kind, a motion, a flow): refuses a mapping holding
  /// none or several of them, "must hold exactly one of: a, b, c (found n)."
  void require_exactly_one(std::initializer_list<std::pair<const char *, bool>> sections) const;

  bool has(const std::string &key) const { return static_cast<bool>(node_[key]); }
  /// A reader of item `index` of the list `key` (its messages name `key[index]` and its line).
  ConfigReader list_item(const std::string &key, std::size_t index) const;
  const YAML::Node &node() const { return node_; }
  const std::filesystem::path &file() const { return file_; }
  std::string path_of(const std::string &key) const { return path_.empty() ? key : path_ + "." + key; }
  void require_mapping() const;

private:
  template <class T> bool read_scalar(const std::string &key, T &out);
  /// optional_number and optional_integer: empty when absent or null, else read by `read`.
  template <class T>
  void read_optional(const std::string &key, std::optional<T> &value, const Range &range, const std::string &doc,
                     void (ConfigReader::*read)(const std::string &, T &, const Range &, const std::string &));
  ConfigReader child_reader(const std::string &key);
  void mark_known(const std::string &key) { known_.insert(key); }
  std::string location(const YAML::Node &node) const;
  [[noreturn]] void fail_at(const YAML::Node &node, const std::string &key, const std::string &message) const;
  static std::string join_names(const std::vector<std::string> &names);
  static std::string suggest(const std::string &word, const std::vector<std::string> &names);

  YAML::Node node_;
  std::filesystem::path file_;
  std::string path_;
  std::set<std::string> known_;
};

} // namespace fsi::common
