#pragma once
// The one ZeroMQ context of a process. Every channel makes its socket here, so inproc
// endpoints connect across channels (they need a common context) and the process runs one set
// of I/O threads.

#include <zmq.hpp>

namespace fsi::proto {

class ZmqContext {
public:
  /// The process-wide context, created on first use and never destroyed (see ZmqContext.cpp).
  static zmq::context_t &shared();
};

} // namespace fsi::proto
