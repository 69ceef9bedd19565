#pragma once
// Errors of the coupling transport. Always on (user errors and failures of a peer, never
// programmer errors); each message is one sentence naming the endpoint or peer, what happened
// and what to do. The two classes are tiny and always caught together, so they share a file.

#include "common/UserError.hpp"

#include <string>

namespace fsi::proto {

/// An endpoint that cannot be parsed, bound or connected, a peer that is gone or stuck.
class TransportError : public common::UserError {
public:
  explicit TransportError(const std::string &message) : common::UserError(message) {}
};

/// A message that is not a valid Envelope of this protocol version, or whose arrays have the
/// wrong size. The channel stays usable: the next message is read normally.
class MalformedMessageError : public TransportError {
public:
  explicit MalformedMessageError(const std::string &message) : TransportError(message) {}
};

} // namespace fsi::proto
