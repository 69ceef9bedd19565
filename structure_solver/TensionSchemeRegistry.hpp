#pragma once
// The one explicit registry of tension schemes (solver.tension), the ways the tension enters the
// step of Eq. (4). Adding a scheme means writing its StepSystem and adding one line to
// TensionSchemeRegistry::builtin().

#include "StepSettings.hpp"
#include "StepSystem.hpp"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fsi::structure {

struct TensionSchemeEntry {
  std::string name;
  std::string summary;
  bool paper_time_scheme_only = false; ///< not combined with time_scheme: energy_conserving
  std::function<std::unique_ptr<StepSystem>(const StepSettings &)> make;
};

class TensionSchemeRegistry {
public:
  /// The schemes this build knows, registered explicitly (no static self-registration).
  static const TensionSchemeRegistry &builtin();

  void add(TensionSchemeEntry entry);
  /// Entry `name`; throws ConfigError listing the valid names.
  const TensionSchemeEntry &entry(const std::string &name) const;
  /// The step system of scheme `name`; throws ConfigError listing the valid names.
  std::unique_ptr<StepSystem> make(const std::string &name, const StepSettings &settings) const;
  std::vector<std::string> names() const;
  /// (name, name) pairs, in registration order, for a configuration choice.
  std::vector<std::pair<std::string, std::string>> choices() const;
  const std::vector<TensionSchemeEntry> &entries() const { return entries_; }

private:
  std::vector<TensionSchemeEntry> entries_;
};

} // namespace fsi::structure
