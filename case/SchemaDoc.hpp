#pragma once
// The case-file reference (Markdown) generated from the configuration declarations: the
// top-level keys, then one table per structure model. `fsi-structure --schema` prints it and
// a test checks that docs/case-reference.md holds exactly this text.

#include <string>

namespace fsi::case_config {

std::string case_schema_markdown();

} // namespace fsi::case_config
