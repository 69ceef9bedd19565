#pragma once
// Why a checkpoint cannot be used: the file, and what is wrong with it (truncated, a checksum
// that does not match, another case, a missing entry). A restart skips such a set and says so.

#include <stdexcept>
#include <string>

namespace fsi::checkpoint {

class CheckpointError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace fsi::checkpoint
