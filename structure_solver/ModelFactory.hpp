#pragma once
// The structure models, built from their configuration: the solver's half of ModelRegistry,
// one entry per registry name. The configuration (ModelRegistry, MembraneConfig,
// FilamentConfig) links no solver code; the scene builds each structure here.

#include "ModelConfig.hpp"
#include "StructureModel.hpp"
#include "common/Registry.hpp"

#include <functional>
#include <memory>
#include <string>

namespace fsi::structure {

/// What a model needs from the case to build itself.
struct BuildContext {
  std::string name;
  Vec3 gravity_m_per_s2 = Vec3::Zero();
  double time_step_s = 1e-4;
};

struct ModelFactoryEntry {
  std::string name; ///< a ModelRegistry name
  std::function<std::unique_ptr<StructureModel>(const ModelConfig &, const BuildContext &)> build;
};

class ModelFactory : public common::Registry<ModelFactoryEntry> {
public:
  ModelFactory() : Registry("structure model", "models") {}
  /// A builder for every model of ModelRegistry::builtin(), registered explicitly.
  static const ModelFactory &builtin();

  /// The model `name` configured by `config` (the configuration ModelRegistry made for that
  /// name); throws ConfigError listing the valid names.
  std::unique_ptr<StructureModel> build(const std::string &name, const ModelConfig &config,
                                        const BuildContext &context) const {
    return entry(name).build(config, context);
  }
};

} // namespace fsi::structure
