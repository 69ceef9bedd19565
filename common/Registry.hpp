#pragma once
// The one explicit registry of a swappable family (structure models, coupling laws, tension
// schemes): named entries, filled by one explicit function of the family (no static
// self-registration, which static linking drops silently). An unknown name is a user error
// with a spelling hint and the valid names. Entry: a struct with a `name` member.

#include "ConfigError.hpp"
#include "DidYouMean.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fsi::common {

template <class Entry> class Registry {
public:
  /// kind: what one entry is, for messages ("structure model"); kinds: the plural ("models").
  Registry(std::string kind, std::string kinds) : kind_(std::move(kind)), kinds_(std::move(kinds)) {}

  void add(Entry entry) { entries_.push_back(std::move(entry)); }

  /// Entry `name`; throws ConfigError listing the valid names.
  const Entry &entry(const std::string &name) const {
    for (const auto &e : entries_)
      if (e.name == name)
        return e;
    throw ConfigError("unknown " + kind_ + " '" + name + "'." + did_you_mean(name, names()) + " Valid " + kinds_ +
                      ": " + join(names()) + ".");
  }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto &e : entries_)
      out.push_back(e.name);
    return out;
  }

  const std::vector<Entry> &entries() const { return entries_; }

private:
  std::string kind_, kinds_;
  std::vector<Entry> entries_;
};

/// An entry of a family chosen by a configuration section: its keys' default configuration.
template <class Config> struct ConfigEntry {
  std::string name;
  std::string summary; ///< one line for the case-file reference
  std::function<std::unique_ptr<Config>()> make_config;
};

template <class Config> class ConfigRegistry : public Registry<ConfigEntry<Config>> {
public:
  using Registry<ConfigEntry<Config>>::Registry;
  /// Default configuration of entry `name`; throws ConfigError listing the valid names.
  std::unique_ptr<Config> make_config(const std::string &name) const { return this->entry(name).make_config(); }
};

} // namespace fsi::common
