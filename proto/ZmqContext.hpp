#pragma once
// The one ZeroMQ context of a process. Every channel makes its socket here, so inproc
// endpoints connect across channels (they need a common context) and the process runs one set
// of I/O threads. Creating it also keeps freed megabyte blocks mapped in this process (glibc
// mallopt, see ZmqContext.cpp): the array frames of every step reuse them without page faults.

#include <zmq.hpp>

namespace fsi::proto {

class ZmqContext {
public:
  /// The process-wide context, created on first use and never destroyed (see ZmqContext.cpp).
  static zmq::context_t &shared();

  /// Delivers what is still queued (up to each socket's linger) and ends the context. Call it
  /// once, at the end of main, after every channel is gone: without it, the last messages of a
  /// process (the coupler's Shutdown, a refusal, an error report) may die with it.
  static void deliver_pending_and_close() noexcept;
};

/// Calls ZmqContext::deliver_pending_and_close() when main's scope ends: declare it first in
/// main, so that it outlives every channel.
class ZmqContextCloser {
public:
  ZmqContextCloser() = default;
  ~ZmqContextCloser() { ZmqContext::deliver_pending_and_close(); }
  ZmqContextCloser(const ZmqContextCloser &) = delete;
  ZmqContextCloser &operator=(const ZmqContextCloser &) = delete;
};

} // namespace fsi::proto
