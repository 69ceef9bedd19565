#pragma once
// The one catch ladder of the four executables: runs the work of a main() and turns what it
// throws into the exit codes of ExitCodes.hpp. A UserError (bad case, bad geometry, bad
// endpoint) is logged as it is and gives exit_code_bad_input; any other exception is logged as
// "<what> failed: <message>" and gives exit_code_run_failed. Otherwise the work's own code.

#include <functional>
#include <string>

namespace fsi::common {

int guarded_main(const std::string &what, const std::function<int()> &work);

} // namespace fsi::common
