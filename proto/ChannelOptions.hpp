#pragma once
// Socket settings shared by the coupler and participant channels. The defaults suit a coupled
// run on one machine; a case file may change them (and must, to allow remote participants).

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace fsi::proto {

/// CURVE encryption and authentication (ZeroMQ's CurveZMQ; keys as 40 Z85 characters).
struct CurveSettings {
  /// This side's key pair.
  std::string public_key;
  std::string secret_key;
  /// A participant: the coupler's public key (the only server it will talk to).
  std::string server_public_key;
  /// The coupler: the participants' public keys it admits, by name ("structure", "fluid"). A
  /// message counts only if its connection authenticated with one of them and the name is the
  /// role of the routing id it came with: anything else is dropped.
  std::map<std::string, std::string> admitted;
};

struct ChannelOptions {
  /// Messages queued per peer and direction before send() waits (ZeroMQ high-water marks).
  /// Bounded so that a stuck peer shows up as an error instead of growing memory.
  int queue_limit_messages = 100;
  /// How long closing the socket may wait to deliver messages still queued (the coupler's
  /// last Shutdown, a refusal, a participant's error report). 0 would drop them.
  std::chrono::milliseconds linger{2000};
  /// How long send() waits for room in a full queue before it throws.
  std::chrono::milliseconds send_timeout{10000};
  /// Larger incoming message parts are dropped and their connection closed (ZMQ_MAXMSGSIZE).
  /// Runs set it from their structures' size (message_limit_bytes()).
  std::int64_t max_message_bytes = std::int64_t{1} << 30;
  /// Encrypt and authenticate every connection; without it nothing on the wire is secret and
  /// anyone who reaches the endpoint may join.
  std::optional<CurveSettings> curve;
  /// Binding a tcp endpoint that is not loopback without CURVE lets anyone who reaches it in:
  /// it must be asked for explicitly.
  bool insecure_remote = false;
  /// TCP keepalive: first probe after this idle time, then every interval, dead after probes.
  int tcp_keepalive_idle_s = 30;
  int tcp_keepalive_interval_s = 5;
  int tcp_keepalive_probes = 6;

  /// The largest message part a run with this many structure points needs (its arrays of 3
  /// doubles a point, twice over, plus 1 MiB for the Envelope), for max_message_bytes.
  static std::int64_t message_limit_bytes(std::int64_t structure_points);

  /// Throws TransportError naming the first option out of range.
  void validate() const;
};

} // namespace fsi::proto
