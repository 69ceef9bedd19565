#include "ModelRegistry.hpp"

#include "FilamentConfig.hpp"
#include "MembraneConfig.hpp"

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

} // namespace fsi::structure
