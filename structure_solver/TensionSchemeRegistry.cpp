#include "TensionSchemeRegistry.hpp"

#include "FrozenTension.hpp"
#include "LinearizedTension.hpp"
#include "StabilizedTension.hpp"

namespace fsi::structure {

const TensionSchemeRegistry &TensionSchemeRegistry::builtin() {
  static const TensionSchemeRegistry registry = [] {
    TensionSchemeRegistry r;
    r.add({"frozen", "tension coefficients at X^n: the paper's semi-implicit Eq. (4)", false,
           [](const StepSettings &s) { return std::make_unique<FrozenTension>(s); }});
    r.add({"stabilized", "an isotropic bound of the stretching stiffness beyond Delta s / (1.5 c) taken implicitly",
           true, [](const StepSettings &s) { return std::make_unique<StabilizedTension>(s); }});
    r.add({"linearized", "the change of the tension linearised about X^n, implicit (3n x 3n)", true,
           [](const StepSettings &s) { return std::make_unique<LinearizedTension>(s); }});
    return r;
  }();
  return registry;
}

std::vector<std::pair<std::string, std::string>> TensionSchemeRegistry::choices() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto &e : entries())
    out.emplace_back(e.name, e.name);
  return out;
}

} // namespace fsi::structure
