#pragma once
// A ZeroMQ socket made from the shared context with the project's options (bounded linger, bounded
// queues, send timeout, message size limit, TCP keepalive), whose errors come back as
// TransportError naming the owner and the endpoint. Used by the channels only.

#include "ChannelOptions.hpp"
#include "Endpoint.hpp"

#include <zmq.hpp>

#include <chrono>
#include <string>
#include <vector>

namespace fsi::proto {

class Socket {
public:
  enum class SendStatus { sent, queue_full, unknown_peer };

  /// owner names this side in error messages ("coupler", "participant fluid:main").
  Socket(zmq::socket_type type, const ChannelOptions &options, std::string owner);

  /// ROUTER: answer EHOSTUNREACH for unknown peers instead of dropping the message.
  void set_router_mandatory();
  /// DEALER: the id the ROUTER on the other side sees; set before connect().
  void set_routing_id(const std::string &routing_id);

  /// CURVE, set before bind/connect: the coupler's ROUTER as server (its connections are
  /// authenticated by the ZAP handler of domain zap_domain), a participant's DEALER as client
  /// of the server key.
  void make_curve_server(const CurveSettings &curve, const std::string &zap_domain);
  void make_curve_client(const CurveSettings &curve);

  /// Binds and returns the endpoint actually bound (tcp port 0 replaced by the chosen port).
  Endpoint bind(const Endpoint &endpoint);
  void connect(const Endpoint &endpoint);

  /// Waits up to timeout (negative: without limit) for a message; false on timeout or when a
  /// signal interrupts the wait.
  bool wait_readable(std::chrono::milliseconds timeout);
  /// All frames of the next message, empty if none is waiting. Never splits a message.
  std::vector<zmq::message_t> receive_frames();
  /// Sends the frames as one message, waiting up to the send timeout for queue room (or, with
  /// wait false, not at all: queue_full at once).
  SendStatus send_frames(std::vector<zmq::message_t> &frames, bool wait = true);

private:
  void apply(const ChannelOptions &options);
  void use_ipv6_for(const Endpoint &endpoint);

  zmq::socket_t socket_;
  std::string owner_;
};

} // namespace fsi::proto
