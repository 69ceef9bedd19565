#pragma once
// The code version every results file records: "<project version>-<git describe>" of the
// build (common/CMakeLists.txt regenerates its one source file at each build, when it changes,
// so that a new commit relinks instead of recompiling everything).

namespace fsi::common {

const char *code_version();

} // namespace fsi::common
