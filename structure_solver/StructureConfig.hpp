#pragma once
// One entry of the case's `structures` list: a name, a model from the registry and that
// model's own keys at the same level.

#include "ModelRegistry.hpp"
#include "common/DidYouMean.hpp"

namespace fsi::structure {

struct StructureConfig {
  std::string name = "sheet";
  std::string model = "membrane";
  std::unique_ptr<ModelConfig> parameters;

  template <class V> void visit(V &v) {
    v.text("name", name, "Unique name; the HDF5 group /structures/<name>.");
    v.text("model", model, "Structure model: " + common::join(ModelRegistry::builtin().names()) + ".");
    if constexpr (std::is_same_v<V, common::ConfigDocWriter>)
      return; // each model's keys are documented in their own table
    else {
      if constexpr (std::is_same_v<V, common::ConfigReader>) {
        try {
          parameters = ModelRegistry::builtin().make_config(model);
        } catch (const common::ConfigError &e) {
          v.fail_value("model", std::string("= ") + e.what());
        }
      }
      if (parameters)
        parameters->visit(v);
    }
  }
};

} // namespace fsi::structure
