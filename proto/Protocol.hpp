#pragma once
// The coupling protocol (fsi_coupling.proto, package fsi.proto.v2) as the rest of the code
// sees it: the generated messages, the protocol version this build speaks, and small helpers
// to stamp envelopes and name roles, bodies and peers.

#include "proto/fsi_coupling.pb.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace fsi::proto {

using Envelope = v2::Envelope;
using Role = v2::Role;

/// Version of fsi_coupling.proto this build speaks; Envelope.protocol_version must equal it.
inline constexpr std::uint32_t current_protocol_version = 2;

/// An empty Envelope stamped with the protocol version, the sender's role and the step.
Envelope make_envelope(Role sender, std::uint64_t step);

/// "coupler", "fluid", "structure" or "unspecified".
std::string_view role_name(Role role);

/// Name of the body field that is set ("hello", "fluid_advance", ...), "none" when unset.
std::string_view body_name(const Envelope &envelope);

/// Routing id of a participant on the coupler's socket, "<role>:<name>" (e.g. "fluid:main").
/// Throws TransportError for the coupler role, an unspecified role or an unusable name.
std::string routing_id(Role role, std::string_view participant_name);

/// Suffix of the name under which a participant's heartbeat thread connects its own socket
/// ("structure:main/heartbeat"); the coupler credits its heartbeats to "structure:main".
inline constexpr std::string_view heartbeat_suffix = "/heartbeat";

/// The participant a routing id belongs to: the id itself, or without heartbeat_suffix.
std::string participant_of(std::string_view routing_id);

/// A routing id or other raw bytes made safe for a log line (non-printable bytes as \xNN).
std::string printable(std::string_view bytes);

} // namespace fsi::proto
