#pragma once
// Message <-> the frames of one ZeroMQ message: the serialised Envelope (the header), then the
// array frames its ArrayFrame fields name, which are moved, never copied. Decoding never throws
// on bad bytes: it says why they are not a message of this protocol version.

#include "MalformedMessage.hpp"
#include "Message.hpp"
#include "Protocol.hpp"

#include <zmq.hpp>

#include <optional>
#include <vector>

namespace fsi::proto {

class EnvelopeCodec {
public:
  /// Appends the header frame and moves the message's array frames after it (the message keeps
  /// its header and holds no frames afterwards). Throws TransportError when the header's
  /// ArrayFrame fields do not name the frames one to one (a bug of the sender).
  static void encode(Message &message, std::vector<zmq::message_t> &frames);
  /// Appends the header frame of an Envelope that names no array frames.
  static void encode(const Envelope &envelope, std::vector<zmq::message_t> &frames);

  /// Parses frames[first] as the header and moves the frames after it into message as its
  /// arrays; nullopt when it is a usable message, else why not (message then unspecified).
  /// When the message already holds a body of the same type, its memory is reused.
  static std::optional<MalformedMessage> decode_into(std::vector<zmq::message_t> &frames, std::size_t first,
                                                     Message &message);

private:
  static zmq::message_t encode_header(const Envelope &envelope);
  static void clear_keeping_storage(Envelope &envelope);
  static std::optional<MalformedMessage> check(const Envelope &envelope, std::size_t n_bytes);
  /// Why the header's ArrayFrame fields do not name the frames one to one; nullopt if they do.
  static std::optional<std::string> array_frames_mismatch(const Envelope &envelope,
                                                          const std::vector<std::unique_ptr<zmq::message_t>> &frames);
};

} // namespace fsi::proto
