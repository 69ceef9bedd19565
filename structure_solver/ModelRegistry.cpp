#include "ModelRegistry.hpp"

#include "FilamentConfig.hpp"
#include "MembraneConfig.hpp"
#include "common/DidYouMean.hpp"

namespace fsi::structure {

const ModelRegistry &ModelRegistry::builtin() {
  static const ModelRegistry registry = [] {
    ModelRegistry r;
    r.add({"membrane", "2D sheet in 3D: stretching, shearing, bending, twisting (Eqs. 3-4)",
           [] { return std::make_unique<MembraneConfig>(); }});
    r.add({"filament", "1D filament in 3D: stretching and bending (Eqs. 3-4 with one coordinate)",
           [] { return std::make_unique<FilamentConfig>(); }});
    return r;
  }();
  return registry;
}

void ModelRegistry::add(ModelEntry entry) { entries_.push_back(std::move(entry)); }

std::vector<std::string> ModelRegistry::names() const {
  std::vector<std::string> out;
  for (const auto &e : entries_)
    out.push_back(e.name);
  return out;
}

std::unique_ptr<ModelConfig> ModelRegistry::make_config(const std::string &name) const {
  for (const auto &e : entries_)
    if (e.name == name)
      return e.make_config();
  throw common::ConfigError("unknown structure model '" + name + "'." + common::did_you_mean(name, names()) +
                            " Valid models: " + common::join(names()) + ".");
}

} // namespace fsi::structure
