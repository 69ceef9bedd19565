#pragma once
// User errors in a case (bad key, bad value, missing file). Always on; the message names the
// file, the line, the key, what was found and what is allowed. Programs exit with
// common::exit_code_bad_input (ExitCodes.hpp).

#include "UserError.hpp"

#include <string>

namespace fsi::common {

class ConfigError : public UserError {
public:
  explicit ConfigError(const std::string &message) : UserError(message) {}
};

} // namespace fsi::common
