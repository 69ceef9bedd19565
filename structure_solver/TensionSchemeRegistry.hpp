#pragma once
// The one explicit registry of tension schemes (solver.tension), the ways the tension enters the
// step of Eq. (4): their names, as the configuration offers them. Each is built by the solver's
// StepSystemFactory under the same name. Adding a scheme means writing its StepSystem and adding
// one line here and one line to StepSystemFactory::builtin() (a test checks the two agree).

#include "common/Registry.hpp"

#include <string>
#include <utility>
#include <vector>

namespace fsi::structure {

struct TensionSchemeEntry {
  std::string name;
  std::string summary;
  bool paper_time_scheme_only = false; ///< not combined with time_scheme: energy_conserving
};

class TensionSchemeRegistry : public common::Registry<TensionSchemeEntry> {
public:
  TensionSchemeRegistry() : Registry("tension scheme", "schemes") {}
  /// The schemes this build knows, registered explicitly.
  static const TensionSchemeRegistry &builtin();

  /// (name, name) pairs, in registration order, for a configuration choice.
  std::vector<std::pair<std::string, std::string>> choices() const;
};

} // namespace fsi::structure
