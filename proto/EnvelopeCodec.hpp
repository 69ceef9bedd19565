#pragma once
// Envelope <-> one ZeroMQ frame. Encoding serialises straight into the frame's buffer; decoding
// never throws on bad bytes: it says why they are not an Envelope of this protocol version.

#include "MalformedMessage.hpp"
#include "Protocol.hpp"

#include <zmq.hpp>

#include <optional>

namespace fsi::proto {

class EnvelopeCodec {
public:
  /// The serialised Envelope in a frame of exactly its size (one copy of the arrays).
  static zmq::message_t encode(const Envelope &envelope);

  /// Parses a payload frame into envelope; nullopt when it is a usable Envelope, else why not
  /// (envelope is then unspecified). When envelope already holds a body of the same type, its
  /// arrays' memory is reused (ParseFromArray would free and allocate it again).
  static std::optional<MalformedMessage> decode_into(const zmq::message_t &frame,
                                                     Envelope &envelope);

private:
  static void clear_keeping_storage(Envelope &envelope);
  static std::optional<MalformedMessage> check(const Envelope &envelope, std::size_t n_bytes);
};

} // namespace fsi::proto
