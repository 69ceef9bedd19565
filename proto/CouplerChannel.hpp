#pragma once
// The coupler's end of the transport: one ROUTER socket bound to an endpoint, to which every
// participant connects. Messages are Envelopes; peers are named by their routing id
// ("fluid:main"), which each participant sets when it connects. Use a channel from one thread at
// a time (ZeroMQ sockets are not thread-safe); several channels may live in one process.

#include "ChannelOptions.hpp"
#include "Endpoint.hpp"
#include "Incoming.hpp"
#include "Message.hpp"
#include "Protocol.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fsi::proto {

class Socket;
class ZapHandler;

class CouplerChannel {
public:
  /// Binds to endpoint. Throws TransportError when the endpoint is taken or unusable, or is a
  /// tcp endpoint other machines can reach without options.curve or options.insecure_remote.
  /// With options.curve, only the admitted participants' messages are received: a message
  /// whose connection did not authenticate as the role its routing id names is dropped.
  explicit CouplerChannel(const Endpoint &endpoint, const ChannelOptions &options = {});
  ~CouplerChannel();
  CouplerChannel(CouplerChannel &&) noexcept;
  CouplerChannel &operator=(CouplerChannel &&) noexcept;

  /// Messages dropped because their sender was not authenticated as its role (CURVE).
  long dropped_unauthenticated() const { return dropped_; }

  /// Where participants connect: the bound endpoint, a tcp port 0 replaced by the chosen port.
  const Endpoint &endpoint() const { return endpoint_; }

  /// Queues the message for the participant with this routing id; its array frames go with it
  /// (moved, not copied: the message keeps only its header). Throws TransportError when no
  /// such participant is connected, or its queue stays full for options.send_timeout.
  void send(const std::string &peer, Message &message);
  /// As above, for an Envelope that names no array frames.
  void send(const std::string &peer, const Envelope &envelope);

  /// As send(), but never waits and never throws: false when the peer is unknown or its queue
  /// is full (a stranger that does not read must not stall the run).
  bool try_send(const std::string &peer, const Envelope &envelope) noexcept;

  /// The next message, or nullopt after timeout (negative: wait without limit) or when a
  /// signal interrupts the wait. Bad bytes never throw: they come back as a malformed Incoming.
  std::optional<Incoming> receive(std::chrono::milliseconds timeout);

  /// As receive(), but parses into incoming, reusing its Envelope's memory when the body type
  /// repeats. False after the timeout, with incoming unchanged.
  bool receive_into(Incoming &incoming, std::chrono::milliseconds timeout);

private:
  void send_frames(const std::string &peer, std::vector<zmq::message_t> &frames, const Envelope &envelope);

  bool admitted(const std::vector<zmq::message_t> &frames);

  std::unique_ptr<ZapHandler> zap_; // before socket_: outlives it
  std::unique_ptr<Socket> socket_;
  Endpoint endpoint_;
  bool authenticate_ = false;
  long dropped_ = 0;
};

} // namespace fsi::proto
