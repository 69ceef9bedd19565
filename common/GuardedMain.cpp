#include "GuardedMain.hpp"

#include "ExitCodes.hpp"
#include "UserError.hpp"

#include <spdlog/spdlog.h>

#include <exception>

namespace fsi::common {

int guarded_main(const std::string &what, const std::function<int()> &work) {
  try {
    return work();
  } catch (const UserError &e) {
    spdlog::error("{}", e.what());
    return exit_code_bad_input;
  } catch (const std::exception &e) {
    spdlog::error("{} failed: {}", what, e.what());
    return exit_code_run_failed;
  }
}

} // namespace fsi::common
