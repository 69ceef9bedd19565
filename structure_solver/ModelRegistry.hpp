#pragma once
// The one explicit registry of structure models. Adding a model means writing its config
// class (keys + build) and adding one line to ModelRegistry::builtin().

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
