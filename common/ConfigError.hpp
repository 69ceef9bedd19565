#pragma once
// User errors in a case (bad key, bad value, missing file). Always on; the message names the
// file, the line, the key, what was found and what is allowed. Programs exit with code 2.

#include <stdexcept>
#include <string>

namespace fsi::common {

class ConfigError : public std::runtime_error {
public:
  explicit ConfigError(const std::string &message) : std::runtime_error(message) {}
};

/// Exit code of every executable for invalid input (case file, command line, geometry).
inline constexpr int exit_code_bad_input = 2;
/// Exit code when a run stops because the simulation diverged or a peer failed.
inline constexpr int exit_code_run_failed = 1;

} // namespace fsi::common
