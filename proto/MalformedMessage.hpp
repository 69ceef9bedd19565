#pragma once
// Why bytes received from a peer are not a usable Envelope. The coupler answers such a message
// with an ErrorReport instead of crashing; a participant throws MalformedMessageError.

#include <string>
#include <string_view>

namespace fsi::proto {

struct MalformedMessage {
  enum class Kind {
    wrong_framing,          // not exactly one payload frame
    not_an_envelope,        // empty, unparsable, or fields this protocol version does not have
    wrong_protocol_version, // Envelope.protocol_version missing or not current_protocol_version
    missing_body,           // an Envelope without a body
  };

  Kind kind;
  /// One sentence: what arrived and what was expected.
  std::string reason;
};

inline std::string_view kind_name(MalformedMessage::Kind kind) {
  switch (kind) {
  case MalformedMessage::Kind::wrong_framing:
    return "wrong framing";
  case MalformedMessage::Kind::not_an_envelope:
    return "not an envelope";
  case MalformedMessage::Kind::wrong_protocol_version:
    return "wrong protocol version";
  case MalformedMessage::Kind::missing_body:
    return "missing body";
  }
  return "unknown";
}

} // namespace fsi::proto
