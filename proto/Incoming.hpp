#pragma once
// One message received by the coupler: who sent it (the participant's routing id) and either
// the message (Envelope and array frames) or why the bytes are not one.

#include "MalformedMessage.hpp"
#include "Message.hpp"
#include "Protocol.hpp"

#include <string>
#include <variant>

namespace fsi::proto {

class Incoming {
public:
  /// An empty Envelope from no peer, to be filled by CouplerChannel::receive_into.
  Incoming() = default;
  Incoming(std::string peer, Message message);
  Incoming(std::string peer, MalformedMessage malformed);

  /// Routing id of the sender ("fluid:main"); pass it to CouplerChannel::send to answer.
  const std::string &peer() const { return peer_; }

  bool is_malformed() const { return std::holds_alternative<MalformedMessage>(content_); }
  /// The message, or its Envelope; throw std::logic_error if the message is malformed.
  const Message &message() const;
  Message &message();
  const Envelope &envelope() const { return message().envelope(); }
  Envelope &envelope() { return message().envelope(); }
  /// Why the message is unusable; throws std::logic_error if it is a valid Envelope.
  const MalformedMessage &malformed() const;

private:
  friend class CouplerChannel;
  /// The message to parse into, keeping the one held (and its Envelope's memory) if any.
  Message &message_to_fill();

  std::string peer_;
  std::variant<Message, MalformedMessage> content_;
};

} // namespace fsi::proto
