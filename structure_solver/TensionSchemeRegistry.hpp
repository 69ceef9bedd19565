#pragma once
// The one explicit registry of tension schemes (solver.tension), the ways the tension enters the
// step of Eq. (4). Adding a scheme means writing its StepSystem and adding one line to
// TensionSchemeRegistry::builtin().

#include "StepSettings.hpp"
#include "StepSystem.hpp"
#include "common/Registry.hpp"

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

class TensionSchemeRegistry : public common::Registry<TensionSchemeEntry> {
public:
  TensionSchemeRegistry() : Registry("tension scheme", "schemes") {}
  /// The schemes this build knows, registered explicitly.
  static const TensionSchemeRegistry &builtin();

  /// The step system of scheme `name`; throws ConfigError listing the valid names.
  std::unique_ptr<StepSystem> make(const std::string &name, const StepSettings &settings) const {
    return entry(name).make(settings);
  }
  /// (name, name) pairs, in registration order, for a configuration choice.
  std::vector<std::pair<std::string, std::string>> choices() const;
};

} // namespace fsi::structure
