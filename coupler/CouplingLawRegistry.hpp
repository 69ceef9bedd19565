#pragma once
// The one explicit registry of coupling laws. Adding a law (e.g. a feedback law with integral
// and proportional terms) means writing its CouplingLaw, its config class, and one line in
// CouplingLawRegistry::builtin().

#include "CouplingLawConfig.hpp"

#include <functional>
#include <string>
#include <vector>

namespace fsi::coupler {

struct CouplingLawEntry {
  std::string name;
  std::string summary;
  std::function<std::unique_ptr<CouplingLawConfig>()> make_config;
};

class CouplingLawRegistry {
public:
  static const CouplingLawRegistry &builtin();

  void add(CouplingLawEntry entry);
  /// Default configuration of law `name`; throws ConfigError listing the valid names.
  std::unique_ptr<CouplingLawConfig> make_config(const std::string &name) const;
  std::vector<std::string> names() const;
  const std::vector<CouplingLawEntry> &entries() const { return entries_; }

private:
  std::vector<CouplingLawEntry> entries_;
};

} // namespace fsi::coupler
