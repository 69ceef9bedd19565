#pragma once
// One message received by the coupler: who sent it (the participant's routing id) and either
// the Envelope or why the bytes are not one.

#include "MalformedMessage.hpp"
#include "Protocol.hpp"

#include <string>
#include <variant>

namespace fsi::proto {

class Incoming {
public:
  /// An empty Envelope from no peer, to be filled by CouplerChannel::receive_into.
  Incoming() = default;
  Incoming(std::string peer, Envelope envelope);
  Incoming(std::string peer, MalformedMessage malformed);

  /// Routing id of the sender ("fluid:main"); pass it to CouplerChannel::send to answer.
  const std::string &peer() const { return peer_; }

  bool is_malformed() const { return std::holds_alternative<MalformedMessage>(content_); }
  /// The Envelope; throws std::logic_error if the message is malformed.
  const Envelope &envelope() const;
  Envelope &envelope();
  /// Why the message is unusable; throws std::logic_error if it is a valid Envelope.
  const MalformedMessage &malformed() const;

private:
  friend class CouplerChannel;
  /// The Envelope to parse into, keeping the one held (and its arrays' memory) if any.
  Envelope &envelope_to_fill();

  std::string peer_;
  std::variant<Envelope, MalformedMessage> content_;
};

} // namespace fsi::proto
