#include "TensionSchemeRegistry.hpp"

#include "FrozenTension.hpp"
#include "LinearizedTension.hpp"
#include "StabilizedTension.hpp"
#include "common/ConfigError.hpp"
#include "common/DidYouMean.hpp"

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

void TensionSchemeRegistry::add(TensionSchemeEntry entry) { entries_.push_back(std::move(entry)); }

std::vector<std::string> TensionSchemeRegistry::names() const {
  std::vector<std::string> out;
  for (const auto &e : entries_)
    out.push_back(e.name);
  return out;
}

std::vector<std::pair<std::string, std::string>> TensionSchemeRegistry::choices() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto &e : entries_)
    out.emplace_back(e.name, e.name);
  return out;
}

const TensionSchemeEntry &TensionSchemeRegistry::entry(const std::string &name) const {
  for (const auto &e : entries_)
    if (e.name == name)
      return e;
  throw common::ConfigError("unknown tension scheme '" + name + "'." + common::did_you_mean(name, names()) +
                            " Valid schemes: " + common::join(names()) + ".");
}

std::unique_ptr<StepSystem> TensionSchemeRegistry::make(const std::string &name, const StepSettings &settings) const {
  return entry(name).make(settings);
}

} // namespace fsi::structure
