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

void ChannelOptions::validate() const {
  require_positive(queue_limit_messages, "queue_limit_messages");
  require_positive(send_timeout.count(), "send_timeout");
  require_positive(max_message_bytes, "max_message_bytes");
  require_positive(tcp_keepalive_idle_s, "tcp_keepalive_idle_s");
  require_positive(tcp_keepalive_interval_s, "tcp_keepalive_interval_s");
  require_positive(tcp_keepalive_probes, "tcp_keepalive_probes");
}

} // namespace fsi::proto
