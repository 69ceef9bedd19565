#pragma once
// Socket settings shared by the coupler and participant channels. The defaults suit a coupled
// run on one machine; a case file may change them (and must, to allow remote participants).

#include <chrono>
#include <cstdint>

namespace fsi::proto {

struct ChannelOptions {
  /// Messages queued per peer and direction before send() waits (ZeroMQ high-water marks).
  /// Bounded so that a stuck peer shows up as an error instead of growing memory.
  int queue_limit_messages = 100;
  /// How long closing the socket may wait to deliver messages still queued (the coupler's
  /// last Shutdown, a refusal, a participant's error report). 0 would drop them.
  std::chrono::milliseconds linger{2000};
  /// How long send() waits for room in a full queue before it throws.
  std::chrono::milliseconds send_timeout{10000};
  /// Larger incoming messages are dropped and their connection closed (ZMQ_MAXMSGSIZE).
  std::int64_t max_message_bytes = std::int64_t{1} << 30;
  /// Binding a tcp endpoint that is not loopback lets other machines in: ask for it explicitly.
  bool allow_remote = false;
  /// TCP keepalive: first probe after this idle time, then every interval, dead after probes.
  int tcp_keepalive_idle_s = 30;
  int tcp_keepalive_interval_s = 5;
  int tcp_keepalive_probes = 6;

  /// Throws TransportError naming the first option out of range.
  void validate() const;
};

} // namespace fsi::proto
