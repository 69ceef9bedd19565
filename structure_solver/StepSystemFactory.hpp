#pragma once
// The step systems of the tension schemes, by the name TensionSchemeRegistry gives each in the
// configuration: the solver's half of that registry.

#include "StepSettings.hpp"
#include "StepSystem.hpp"
#include "common/Registry.hpp"

#include <functional>
#include <memory>
#include <string>

namespace fsi::structure {

struct StepSystemEntry {
  std::string name; ///< a TensionSchemeRegistry name
  std::function<std::unique_ptr<StepSystem>(const StepSettings &)> make;
};

class StepSystemFactory : public common::Registry<StepSystemEntry> {
public:
  StepSystemFactory() : Registry("tension scheme", "schemes") {}
  /// The step system of every scheme of TensionSchemeRegistry::builtin(), registered explicitly.
  static const StepSystemFactory &builtin();

  /// The step system of scheme `name`; throws ConfigError listing the valid names.
  std::unique_ptr<StepSystem> make(const std::string &name, const StepSettings &settings) const {
    return entry(name).make(settings);
  }
};

} // namespace fsi::structure
