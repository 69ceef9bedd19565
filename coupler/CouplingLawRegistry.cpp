#include "CouplingLawRegistry.hpp"

#include "PenaltyLawConfig.hpp"
#include "common/DidYouMean.hpp"

namespace fsi::coupler {

const CouplingLawRegistry &CouplingLawRegistry::builtin() {
  static const CouplingLawRegistry registry = [] {
    CouplingLawRegistry r;
    r.add({"penalty", "Eq. (5): F_fsi = -K_fsi (X_ib^{n+1} - 2 X^n + X^{n-1})",
           [] { return std::make_unique<PenaltyLawConfig>(); }});
    return r;
  }();
  return registry;
}

void CouplingLawRegistry::add(CouplingLawEntry entry) { entries_.push_back(std::move(entry)); }

std::vector<std::string> CouplingLawRegistry::names() const {
  std::vector<std::string> out;
  for (const auto &e : entries_)
    out.push_back(e.name);
  return out;
}

std::unique_ptr<CouplingLawConfig> CouplingLawRegistry::make_config(const std::string &name) const {
  for (const auto &e : entries_)
    if (e.name == name)
      return e.make_config();
  throw common::ConfigError("unknown coupling law '" + name + "'." + common::did_you_mean(name, names()) +
                            " Valid laws: " + common::join(names()) + ".");
}

} // namespace fsi::coupler
