#include "Protocol.hpp"

#include "TransportError.hpp"

#include <cstdio>

namespace fsi::proto {

namespace {

// ZeroMQ allows routing ids of 1..255 bytes; the role prefix takes up to 10.
constexpr std::size_t max_participant_name_bytes = 200;

bool is_printable(char c) { return c >= 0x20 && c < 0x7f; }

} // namespace

Envelope make_envelope(Role sender, std::uint64_t step) {
  Envelope envelope;
  envelope.set_protocol_version(current_protocol_version);
  envelope.set_sender_role(sender);
  envelope.set_step(step);
  return envelope;
}

std::string_view role_name(Role role) {
  switch (role) {
  case v2::ROLE_COUPLER:
    return "coupler";
  case v2::ROLE_FLUID:
    return "fluid";
  case v2::ROLE_STRUCTURE:
    return "structure";
  default:
    return "unspecified";
  }
}

std::string_view body_name(const Envelope &envelope) {
  if (envelope.body_case() == Envelope::BODY_NOT_SET) {
    return "none";
  }
  const auto *field = Envelope::descriptor()->FindFieldByNumber(envelope.body_case());
  return field != nullptr ? std::string_view(field->name()) : std::string_view("unknown");
}

std::string routing_id(Role role, std::string_view participant_name) {
  if (role != v2::ROLE_FLUID && role != v2::ROLE_STRUCTURE) {
    throw TransportError("a participant must have the role fluid or structure, not '" +
                         std::string(role_name(role)) + "'");
  }
  if (participant_name.empty() || participant_name.size() > max_participant_name_bytes) {
    throw TransportError("participant name '" + printable(participant_name) + "' must have 1 to " +
                         std::to_string(max_participant_name_bytes) + " characters");
  }
  return std::string(role_name(role)) + ":" + std::string(participant_name);
}

std::string participant_of(std::string_view routing_id) {
  if (routing_id.size() > heartbeat_suffix.size() &&
      routing_id.substr(routing_id.size() - heartbeat_suffix.size()) == heartbeat_suffix)
    routing_id.remove_suffix(heartbeat_suffix.size());
  return std::string(routing_id);
}

std::string printable(std::string_view bytes) {
  std::string text;
  text.reserve(bytes.size());
  for (const char c : bytes) {
    if (is_printable(c)) {
      text += c;
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(c));
      text += escaped;
    }
  }
  return text;
}

} // namespace fsi::proto
