#pragma once
// The one explicit registry of structure models, as the configuration offers them. Adding a
// model means writing its config class (its keys) and its StructureModel, then one line here
// (ModelRegistry::builtin()) and one in the solver's ModelFactory::builtin(), which builds it
// under the same name (a test checks the two agree).

#include "ModelConfig.hpp"
#include "common/Registry.hpp"

namespace fsi::structure {

class ModelRegistry : public common::ConfigRegistry<ModelConfig> {
public:
  ModelRegistry() : ConfigRegistry("structure model", "models") {}
  /// The models this build knows, registered explicitly.
  static const ModelRegistry &builtin();
};

using ModelEntry = common::ConfigEntry<ModelConfig>;

} // namespace fsi::structure
