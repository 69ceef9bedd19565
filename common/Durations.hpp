#pragma once
// The processes' clock: a configuration's durations (s, double) as the transport's
// milliseconds (deadlines, heartbeats), and the wall time since a point (the timings of
// coupling.h5, of a participant's replies, of the fluid's step).

#include <chrono>

namespace fsi::common {

using Clock = std::chrono::steady_clock;

/// A duration of the configuration (s) as whole milliseconds (a deadline, a heartbeat).
inline std::chrono::milliseconds to_ms(double s) { return std::chrono::milliseconds(static_cast<long long>(s * 1e3)); }

/// Wall time since t, s.
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

} // namespace fsi::common
