#pragma once
// A participant's end of the transport: one DEALER socket connected to the coupler, with the
// routing id "<role>:<name>" so the coupler can tell participants apart. Connecting does not
// wait for the coupler: messages queue until it is there. Use a channel from one thread at a
// time (ZeroMQ sockets are not thread-safe).

#include "ChannelOptions.hpp"
#include "Endpoint.hpp"
#include "Protocol.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace fsi::proto {

class Socket;

class ParticipantChannel {
public:
  /// Throws TransportError for an endpoint that can only be bound (tcp port 0, host *), a
  /// role other than fluid or structure, or an unusable name.
  ParticipantChannel(const Endpoint &coupler, Role role, const std::string &participant_name,
                     const ChannelOptions &options = {});
  ~ParticipantChannel();
  ParticipantChannel(ParticipantChannel &&) noexcept;
  ParticipantChannel &operator=(ParticipantChannel &&) noexcept;

  /// The id the coupler sees as Incoming::peer(), e.g. "fluid:main".
  const std::string &routing_id() const { return routing_id_; }
  const Endpoint &coupler_endpoint() const { return coupler_; }

  /// Queues envelope for the coupler; throws TransportError when the queue stays full for
  /// options.send_timeout (the coupler is gone or stuck).
  void send(const Envelope &envelope);

  /// The next Envelope from the coupler, or nullopt after timeout (negative: wait without
  /// limit) or when a signal interrupts the wait. Throws MalformedMessageError for anything
  /// that is not a valid Envelope of this protocol version; the channel stays usable.
  std::optional<Envelope> receive(std::chrono::milliseconds timeout);

  /// As receive(), but parses into envelope, reusing the memory of its arrays when the body
  /// type repeats (worth it from about 10^4 points). False after the timeout, with envelope
  /// unchanged; unspecified after MalformedMessageError.
  bool receive_into(Envelope &envelope, std::chrono::milliseconds timeout);

private:
  std::unique_ptr<Socket> socket_;
  Endpoint coupler_;
  std::string routing_id_;
};

} // namespace fsi::proto
