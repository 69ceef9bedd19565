#pragma once
// The one explicit registry of structure models. Adding a model means writing its config
// class (keys + build) and adding one line to ModelRegistry::builtin().

#include "ModelConfig.hpp"

#include <functional>
#include <vector>

namespace fsi::structure {

struct ModelEntry {
  std::string name;
  std::string summary;
  std::function<std::unique_ptr<ModelConfig>()> make_config;
};

class ModelRegistry {
public:
  /// The models this build knows, registered explicitly (no static self-registration).
  static const ModelRegistry &builtin();

  void add(ModelEntry entry);
  /// Default configuration of model `name`; throws ConfigError listing the valid names.
  std::unique_ptr<ModelConfig> make_config(const std::string &name) const;
  std::vector<std::string> names() const;
  const std::vector<ModelEntry> &entries() const { return entries_; }

private:
  std::vector<ModelEntry> entries_;
};

} // namespace fsi::structure
