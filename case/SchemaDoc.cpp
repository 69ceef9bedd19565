#include "SchemaDoc.hpp"

#include "CaseConfig.hpp"
#include "coupler/CouplingLawRegistry.hpp"

#include <sstream>

namespace fsi::case_config {

std::string case_schema_markdown() {
  std::ostringstream out;
  out << "#### Top level of `case.yaml`\n\n";
  common::ConfigDocWriter::header(out);
  CaseConfig defaults;
  common::ConfigDocWriter top(out);
  defaults.visit(top);
  // One table per entry of a family chosen by a key: `section` with `key: name`.
  const auto tables = [&out](const auto &registry, const std::string &section, const std::string &key,
                             const std::string &prefix) {
    for (const auto &entry : registry.entries()) {
      out << "\n#### `" << section << "` with `" << key << ": " << entry.name << "`: " << entry.summary << "\n\n";
      common::ConfigDocWriter::header(out);
      auto config = entry.make_config();
      common::ConfigDocWriter writer(out, prefix);
      config->visit(writer);
    }
  };
  tables(structure::ModelRegistry::builtin(), "structures[]", "model", "structures[].");
  tables(coupler::CouplingLawRegistry::builtin(), "coupling", "law", "coupling.");
  return out.str();
}

} // namespace fsi::case_config
