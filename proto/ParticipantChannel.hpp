#pragma once
// A participant's end of the transport: one DEALER socket connected to the coupler, with the
// routing id "<role>:<name>" so the coupler can tell participants apart. Connecting does not
// wait for the coupler: messages queue until it is there. Use a channel from one thread at a
// time (ZeroMQ sockets are not thread-safe).

#include "ChannelOptions.hpp"
#include "Endpoint.hpp"
#include "Message.hpp"
#include "Protocol.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

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

  /// Queues the message for the coupler; its array frames go with it (moved, not copied: the
  /// message keeps only its header). Throws TransportError when the queue stays full for
  /// options.send_timeout (the coupler is gone or stuck).
  void send(Message &message);
  /// As above, for an Envelope that names no array frames.
  void send(const Envelope &envelope);

  /// The next message from the coupler, or nullopt after timeout (negative: wait without
  /// limit) or when a signal interrupts the wait. Throws MalformedMessageError for anything
  /// that is not a valid message of this protocol version; the channel stays usable.
  std::optional<Message> receive(std::chrono::milliseconds timeout);

  /// As receive(), but parses into message, reusing its Envelope's memory when the body type
  /// repeats. False after the timeout, with message unchanged; unspecified after
  /// MalformedMessageError.
  bool receive_into(Message &message, std::chrono::milliseconds timeout);

private:
  void send_frames(std::vector<zmq::message_t> &frames, const Envelope &envelope);

  std::unique_ptr<Socket> socket_;
  Endpoint coupler_;
  std::string routing_id_;
};

} // namespace fsi::proto
