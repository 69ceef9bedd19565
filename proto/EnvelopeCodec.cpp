#include "EnvelopeCodec.hpp"

#include "TransportError.hpp"

#include <google/protobuf/io/zero_copy_stream_impl_lite.h>

#include <climits>
#include <string>

namespace fsi::proto {

namespace {

using Kind = MalformedMessage::Kind;

bool has_unknown_fields(const Envelope &envelope) {
  return !envelope.GetReflection()->GetUnknownFields(envelope).empty();
}

std::string bytes_text(std::size_t n_bytes) { return std::to_string(n_bytes) + " bytes"; }

MalformedMessage malformed(Kind kind, std::string reason) { return {kind, std::move(reason)}; }

} // namespace

zmq::message_t EnvelopeCodec::encode(const Envelope &envelope) {
  const std::size_t n_bytes = envelope.ByteSizeLong();
  if (n_bytes > static_cast<std::size_t>(INT_MAX)) {
    throw TransportError("an Envelope with a " + std::string(body_name(envelope)) + " body has " +
                         bytes_text(n_bytes) + ", more than Protobuf's 2 GiB limit; split it");
  }
  zmq::message_t frame(n_bytes);
  envelope.SerializeWithCachedSizesToArray(static_cast<std::uint8_t *>(frame.data()));
  return frame;
}

std::optional<MalformedMessage> EnvelopeCodec::decode_into(const zmq::message_t &frame,
                                                           Envelope &envelope) {
  const std::size_t n_bytes = frame.size();
  if (n_bytes == 0) {
    return malformed(Kind::not_an_envelope, "an empty message is not an Envelope");
  }
  if (n_bytes > static_cast<std::size_t>(INT_MAX)) {
    return malformed(Kind::not_an_envelope, bytes_text(n_bytes) + " exceed Protobuf's limit");
  }
  clear_keeping_storage(envelope);
  const int size = static_cast<int>(n_bytes);
  google::protobuf::io::ArrayInputStream input(frame.data(), size);
  if (!envelope.MergeFromBoundedZeroCopyStream(&input, size)) {
    return malformed(Kind::not_an_envelope,
                     bytes_text(n_bytes) + " that do not parse as an fsi.proto.v1.Envelope");
  }
  return check(envelope, n_bytes);
}

void EnvelopeCodec::clear_keeping_storage(Envelope &envelope) {
  // Clear() would delete the body message and with it the arrays' memory; clearing the body's
  // contents keeps it, and merging a body of the same type then refills it in place.
  static const auto *const descriptor = Envelope::descriptor();
  static const auto *const body_oneof = descriptor->FindOneofByName("body");
  const auto *reflection = envelope.GetReflection();
  const auto *body = reflection->GetOneofFieldDescriptor(envelope, body_oneof);
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

std::optional<MalformedMessage> EnvelopeCodec::check(const Envelope &envelope,
                                                     std::size_t n_bytes) {
  const auto version = envelope.protocol_version();
  if (version == 0 && has_unknown_fields(envelope)) {
    return malformed(Kind::not_an_envelope,
                     bytes_text(n_bytes) + " that are not an fsi.proto.v1.Envelope");
  }
  if (version != current_protocol_version) {
    const auto found = version == 0 ? std::string("no protocol_version")
                                    : "protocol_version " + std::to_string(version);
    return malformed(Kind::wrong_protocol_version,
                     "the Envelope carries " + found + " but this side speaks version " +
                         std::to_string(current_protocol_version) +
                         "; build both sides from the same fsi_coupling.proto");
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

} // namespace fsi::proto
