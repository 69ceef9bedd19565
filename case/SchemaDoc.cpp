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
  for (const auto &entry : structure::ModelRegistry::builtin().entries()) {
    out << "\n#### `structures[]` with `model: " << entry.name << "`: " << entry.summary << "\n\n";
    common::ConfigDocWriter::header(out);
    auto config = entry.make_config();
    common::ConfigDocWriter writer(out, "structures[].");
    config->visit(writer);
  }
  for (const auto &entry : coupler::CouplingLawRegistry::builtin().entries()) {
    out << "\n#### `coupling` with `law: " << entry.name << "`: " << entry.summary << "\n\n";
    common::ConfigDocWriter::header(out);
    auto config = entry.make_config();
    common::ConfigDocWriter writer(out, "coupling.");
    config->visit(writer);
  }
  return out.str();
}

} // namespace fsi::case_config
