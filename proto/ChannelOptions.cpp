#include "ChannelOptions.hpp"

#include "TransportError.hpp"

#include <string>

namespace fsi::proto {

namespace {

void require_positive(long long value, const char *name) {
  if (value <= 0) {
    throw TransportError(std::string("channel option ") + name + " is " + std::to_string(value) +
                         "; it must be positive");
  }
}

} // namespace

std::int64_t ChannelOptions::message_limit_bytes(std::int64_t structure_points) {
  return (std::int64_t{1} << 20) + 2 * 3 * static_cast<std::int64_t>(sizeof(double)) * structure_points;
}

void ChannelOptions::validate() const {
  require_positive(queue_limit_messages, "queue_limit_messages");
  require_positive(send_timeout.count(), "send_timeout");
  require_positive(max_message_bytes, "max_message_bytes");
  require_positive(tcp_keepalive_idle_s, "tcp_keepalive_idle_s");
  require_positive(tcp_keepalive_interval_s, "tcp_keepalive_interval_s");
  require_positive(tcp_keepalive_probes, "tcp_keepalive_probes");
  if (curve) {
    for (const auto *key : {&curve->public_key, &curve->secret_key})
      if (key->size() != 40)
        throw TransportError("channel option curve: a key must be 40 Z85 characters, this one has " +
                             std::to_string(key->size()));
  }
}

} // namespace fsi::proto
