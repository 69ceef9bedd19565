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

class CouplerChannel {
public:
  /// Binds to endpoint. Throws TransportError when the endpoint is taken or unusable, or is a
  /// tcp endpoint other machines can reach and options.allow_remote is false.
  explicit CouplerChannel(const Endpoint &endpoint, const ChannelOptions &options = {});
  ~CouplerChannel();
  CouplerChannel(CouplerChannel &&) noexcept;
  CouplerChannel &operator=(CouplerChannel &&) noexcept;

  /// Where participants connect: the bound endpoint, a tcp port 0 replaced by the chosen port.
  const Endpoint &endpoint() const { return endpoint_; }

  /// Queues the message for the participant with this routing id; its array frames go with it
  /// (moved, not copied: the message keeps only its header). Throws TransportError when no
  /// such participant is connected, or its queue stays full for options.send_timeout.
  void send(const std::string &peer, Message &message);
  /// As above, for an Envelope that names no array frames.
  void send(const std::string &peer, const Envelope &envelope);

  /// The next message, or nullopt after timeout (negative: wait without limit) or when a
  /// signal interrupts the wait. Bad bytes never throw: they come back as a malformed Incoming.
  std::optional<Incoming> receive(std::chrono::milliseconds timeout);

  /// As receive(), but parses into incoming, reusing its Envelope's memory when the body type
  /// repeats. False after the timeout, with incoming unchanged.
  bool receive_into(Incoming &incoming, std::chrono::milliseconds timeout);

private:
  void send_frames(const std::string &peer, std::vector<zmq::message_t> &frames, const Envelope &envelope);

  std::unique_ptr<Socket> socket_;
  Endpoint endpoint_;
};

} // namespace fsi::proto
