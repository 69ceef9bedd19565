#include "EnvelopeCodec.hpp"

#include "TransportError.hpp"

#include <google/protobuf/io/zero_copy_stream_impl_lite.h>
#include <google/protobuf/stubs/logging.h>
#include <spdlog/spdlog.h>

#include <climits>
#include <cstdint>
#include <string>

namespace fsi::proto {

// Array frames hold the doubles as they are in memory; the protocol says little-endian.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "protocol version 2 sends little-endian doubles");

namespace {

using Kind = MalformedMessage::Kind;

/// Protobuf's own log lines (for one, "String field ... contains invalid UTF-8 data when parsing
/// a protocol buffer") went to stderr beside spdlog, once for every such message, past the rate
/// limit of the coupler's reports of malformed messages. The codec reports each message that
/// does not parse itself, so Protobuf's lines go to spdlog's debug level (fatal ones: critical).
void protobuf_log_to_spdlog(google::protobuf::LogLevel level, const char *file, int line, const std::string &text) {
  if (level >= google::protobuf::LOGLEVEL_FATAL)
    spdlog::critical("protobuf ({}:{}): {}", file, line, text);
  else
    spdlog::debug("protobuf ({}:{}): {}", file, line, text);
}
[[maybe_unused]] const bool protobuf_logs_routed = (google::protobuf::SetLogHandler(&protobuf_log_to_spdlog), true);

bool has_unknown_fields(const Envelope &envelope) {
  return !envelope.GetReflection()->GetUnknownFields(envelope).empty();
}

std::string bytes_text(std::size_t n_bytes) { return std::to_string(n_bytes) + " bytes"; }

MalformedMessage malformed(Kind kind, std::string reason) { return {kind, std::move(reason)}; }

const google::protobuf::OneofDescriptor *body_oneof() {
  static const auto *const oneof = Envelope::descriptor()->FindOneofByName("body");
  return oneof;
}

/// protocol_version of a header that does not parse, if it starts as every Envelope does (field
/// 1, a varint): a peer of another version sends array fields this version cannot parse.
std::optional<std::uint64_t> leading_protocol_version(const zmq::message_t &frame) {
  const auto *bytes = static_cast<const std::uint8_t *>(frame.data());
  if (frame.size() < 2 || bytes[0] != 0x08) {
    return std::nullopt;
  }
  std::uint64_t value = 0;
  for (std::size_t i = 1; i < frame.size() && i <= 10; ++i) {
    value |= static_cast<std::uint64_t>(bytes[i] & 0x7f) << (7 * (i - 1));
    if ((bytes[i] & 0x80) == 0) {
      return value;
    }
  }
  return std::nullopt;
}

MalformedMessage wrong_version(std::uint64_t version) {
  const auto found = version == 0 ? std::string("no protocol_version") : "protocol_version " + std::to_string(version);
  return malformed(Kind::wrong_protocol_version, "the Envelope carries " + found + " but this side speaks version " +
                                                     std::to_string(current_protocol_version) +
                                                     "; build both sides from the same fsi_coupling.proto");
}

/// A frame whose bytes a double* may point into: the socket may hand out small frames at any
/// offset of its receive buffer.
void align_for_doubles(zmq::message_t &frame) {
  if (reinterpret_cast<std::uintptr_t>(frame.data()) % alignof(double) == 0) {
    return;
  }
  zmq::message_t aligned(frame.data(), frame.size());
  frame.move(aligned);
}

} // namespace

zmq::message_t EnvelopeCodec::encode_header(const Envelope &envelope) {
  const std::size_t n_bytes = envelope.ByteSizeLong();
  if (n_bytes > static_cast<std::size_t>(INT_MAX)) {
    throw TransportError("an Envelope with a " + std::string(body_name(envelope)) + " body has " +
                         bytes_text(n_bytes) + ", more than Protobuf's 2 GiB limit; split it");
  }
  zmq::message_t frame(n_bytes);
  envelope.SerializeWithCachedSizesToArray(static_cast<std::uint8_t *>(frame.data()));
  return frame;
}

void EnvelopeCodec::encode(Message &message, std::vector<zmq::message_t> &frames) {
  if (auto mismatch = array_frames_mismatch(message.envelope_, message.frames_)) {
    throw TransportError("cannot send a " + std::string(body_name(message.envelope_)) + ": " + *mismatch);
  }
  frames.push_back(encode_header(message.envelope_));
  for (auto &frame : message.frames_) {
    frames.push_back(std::move(*frame));
  }
  message.frames_.clear();
  message.owners_.clear();
}

void EnvelopeCodec::encode(const Envelope &envelope, std::vector<zmq::message_t> &frames) {
  if (auto mismatch = array_frames_mismatch(envelope, {})) {
    throw TransportError("cannot send a " + std::string(body_name(envelope)) + ": " + *mismatch);
  }
  frames.push_back(encode_header(envelope));
}

std::optional<MalformedMessage> EnvelopeCodec::decode_into(std::vector<zmq::message_t> &frames, std::size_t first,
                                                           Message &message) {
  const zmq::message_t &header = frames.at(first);
  const std::size_t n_bytes = header.size();
  if (n_bytes == 0) {
    return malformed(Kind::not_an_envelope, "an empty message is not an Envelope");
  }
  if (n_bytes > static_cast<std::size_t>(INT_MAX)) {
    return malformed(Kind::not_an_envelope, bytes_text(n_bytes) + " exceed Protobuf's limit");
  }
  Envelope &envelope = message.envelope_;
  clear_keeping_storage(envelope);
  const int size = static_cast<int>(n_bytes);
  google::protobuf::io::ArrayInputStream input(header.data(), size);
  if (!envelope.MergeFromBoundedZeroCopyStream(&input, size)) {
    const auto version = leading_protocol_version(header);
    if (version && *version != current_protocol_version) {
      return wrong_version(*version);
    }
    return malformed(Kind::not_an_envelope, bytes_text(n_bytes) + " that do not parse as an fsi.proto.v2.Envelope");
  }
  if (auto problem = check(envelope, n_bytes)) {
    return problem;
  }
  message.frames_.clear();
  message.owners_.clear();
  for (std::size_t i = first + 1; i < frames.size(); ++i) {
    message.frames_.push_back(std::make_unique<zmq::message_t>(std::move(frames[i])));
    align_for_doubles(*message.frames_.back());
  }
  if (auto mismatch = array_frames_mismatch(envelope, message.frames_)) {
    return malformed(Kind::wrong_framing, *mismatch);
  }
  return std::nullopt;
}

void EnvelopeCodec::clear_keeping_storage(Envelope &envelope) {
  // Clear() would delete the body message; clearing the body's contents keeps it, and merging a
  // body of the same type then refills it in place.
  static const auto *const descriptor = Envelope::descriptor();
  const auto *reflection = envelope.GetReflection();
  const auto *body = reflection->GetOneofFieldDescriptor(envelope, body_oneof());
  if (body != nullptr) {
    reflection->MutableMessage(&envelope, body)->Clear();
  }
  for (int i = 0; i < descriptor->field_count(); ++i) {
    if (descriptor->field(i)->real_containing_oneof() == nullptr) {
      reflection->ClearField(&envelope, descriptor->field(i));
    }
  }
  reflection->MutableUnknownFields(&envelope)->Clear();
}

std::optional<MalformedMessage> EnvelopeCodec::check(const Envelope &envelope, std::size_t n_bytes) {
  const auto version = envelope.protocol_version();
  if (version == 0 && has_unknown_fields(envelope)) {
    return malformed(Kind::not_an_envelope, bytes_text(n_bytes) + " that are not an fsi.proto.v2.Envelope");
  }
  if (version != current_protocol_version) {
    return wrong_version(version);
  }
  if (has_unknown_fields(envelope)) {
    return malformed(Kind::not_an_envelope, "the Envelope has fields that protocol version " +
                                                std::to_string(version) + " does not define");
  }
  if (envelope.body_case() == Envelope::BODY_NOT_SET) {
    return malformed(Kind::missing_body, "the Envelope has no body");
  }
  return std::nullopt;
}

std::optional<std::string> EnvelopeCodec::array_frames_mismatch(const Envelope &envelope,
                                                                const std::vector<std::unique_ptr<zmq::message_t>> &frames) {
  // The arrays are fields of the body (one level down): look at each ArrayFrame field set.
  std::vector<bool> named(frames.size(), false);
  const auto *reflection = envelope.GetReflection();
  const auto *body_field = reflection->GetOneofFieldDescriptor(envelope, body_oneof());
  if (body_field != nullptr && body_field->message_type() != nullptr) {
    const auto &body = reflection->GetMessage(envelope, body_field);
    const auto *fields = body.GetDescriptor();
    const auto *body_reflection = body.GetReflection();
    for (int i = 0; i < fields->field_count(); ++i) {
      const auto *field = fields->field(i);
      if (field->message_type() != ArrayFrame::descriptor() || !body_reflection->HasField(body, field)) {
        continue;
      }
      const auto &ref = static_cast<const ArrayFrame &>(body_reflection->GetMessage(body, field));
      const std::string name = fields->name() + "." + field->name();
      if (ref.frame() == 0) {
        if (ref.n_values() != 0) {
          return name + " has " + std::to_string(ref.n_values()) + " values but names no frame";
        }
        continue;
      }
      if (ref.frame() > frames.size()) {
        return name + " names array frame " + std::to_string(ref.frame()) + " but the message has " +
               std::to_string(frames.size()) + " array frame(s)";
      }
      const std::size_t index = ref.frame() - 1;
      if (named[index]) {
        return name + " names array frame " + std::to_string(ref.frame()) + ", which another field names too";
      }
      named[index] = true;
      const std::size_t n_bytes = frames[index]->size();
      if (ref.n_values() > n_bytes / sizeof(double) || n_bytes != sizeof(double) * ref.n_values()) {
        return name + " says " + std::to_string(ref.n_values()) + " doubles but its frame " +
               std::to_string(ref.frame()) + " holds " + bytes_text(n_bytes);
      }
    }
  }
  for (std::size_t i = 0; i < named.size(); ++i) {
    if (!named[i]) {
      return "array frame " + std::to_string(i + 1) + " of " + std::to_string(frames.size()) +
             " is named by no field of the " + std::string(body_name(envelope));
    }
  }
  return std::nullopt;
}

} // namespace fsi::proto
