#include "TensionSchemeRegistry.hpp"

namespace fsi::structure {

const TensionSchemeRegistry &TensionSchemeRegistry::builtin() {
  static const TensionSchemeRegistry registry = [] {
    TensionSchemeRegistry r;
    r.add({"frozen", "tension coefficients at X^n: the paper's semi-implicit Eq. (4)", false});
    r.add({"stabilized", "an isotropic bound of the stretching stiffness beyond Delta s / (1.5 c) taken implicitly",
           true});
    r.add({"linearized", "the change of the tension linearised about X^n, implicit (3n x 3n)", true});
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
