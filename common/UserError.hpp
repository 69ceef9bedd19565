#pragma once
// The base of every error a user can fix (a bad case file, a missing or open STL mesh, an
// endpoint that cannot be used): always on, one actionable message, exit code
// exit_code_bad_input. Programmer errors are assertions and std::logic_error instead.

#include <stdexcept>
#include <string>

namespace fsi::common {

class UserError : public std::runtime_error {
public:
  explicit UserError(const std::string &message) : std::runtime_error(message) {}
};

} // namespace fsi::common
