#pragma once
// The one explicit registry of coupling laws (penalty, two_point_sets, feedback). Adding a law
// means writing its CouplingLaw, its config class, and one line in CouplingLawRegistry::builtin().

#include "CouplingLawConfig.hpp"
#include "common/Registry.hpp"

namespace fsi::coupler {

class CouplingLawRegistry : public common::ConfigRegistry<CouplingLawConfig> {
public:
  CouplingLawRegistry() : ConfigRegistry("coupling law", "laws") {}
  /// The laws this build knows, registered explicitly.
  static const CouplingLawRegistry &builtin();
};

using CouplingLawEntry = common::ConfigEntry<CouplingLawConfig>;

} // namespace fsi::coupler
