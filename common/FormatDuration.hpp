#pragma once
// Wall-clock durations for progress lines and ETAs: "12.3 s" below two minutes, "4m05s" above.

#include <string>

namespace fsi::common {

std::string format_duration(double seconds);

} // namespace fsi::common
