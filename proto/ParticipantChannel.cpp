#include "ParticipantChannel.hpp"

#include "EnvelopeCodec.hpp"
#include "Socket.hpp"
#include "TransportError.hpp"

#include <utility>
#include <vector>

namespace fsi::proto {

namespace {

MalformedMessageError malformed_error(const std::string &routing_id, const Endpoint &coupler,
                                      const std::string &reason) {
  return MalformedMessageError("participant " + printable(routing_id) +
                               " received a malformed message from the coupler at " +
                               coupler.str() + ": " + reason);
}

void parse_frames(std::vector<zmq::message_t> &frames, Message &message, const std::string &routing_id,
                  const Endpoint &coupler) {
  if (auto malformed = EnvelopeCodec::decode_into(frames, 0, message)) {
    throw malformed_error(routing_id, coupler, malformed->reason);
  }
}

} // namespace

ParticipantChannel::ParticipantChannel(const Endpoint &coupler, Role role,
                                       const std::string &participant_name,
                                       const ChannelOptions &options)
    : coupler_(coupler), routing_id_(proto::routing_id(role, participant_name)) {
  coupler.check_connectable();
  socket_ = std::make_unique<Socket>(zmq::socket_type::dealer, options,
                                     "participant " + printable(routing_id_));
  socket_->set_routing_id(routing_id_);
  if (options.curve)
    socket_->make_curve_client(*options.curve);
  socket_->connect(coupler);
}

ParticipantChannel::~ParticipantChannel() = default;
ParticipantChannel::ParticipantChannel(ParticipantChannel &&) noexcept = default;
ParticipantChannel &ParticipantChannel::operator=(ParticipantChannel &&) noexcept = default;

void ParticipantChannel::send(Message &message) {
  std::vector<zmq::message_t> frames;
  EnvelopeCodec::encode(message, frames);
  send_frames(frames, message.envelope());
}

void ParticipantChannel::send(const Envelope &envelope) {
  std::vector<zmq::message_t> frames;
  EnvelopeCodec::encode(envelope, frames);
  send_frames(frames, envelope);
}

void ParticipantChannel::send_frames(std::vector<zmq::message_t> &frames, const Envelope &envelope) {
  if (socket_->send_frames(frames) != Socket::SendStatus::sent) {
    throw TransportError("participant " + printable(routing_id_) + " cannot send " +
                         std::string(body_name(envelope)) + " to the coupler at " + coupler_.str() +
                         ": the queue stayed full for the send timeout; is the coupler running?");
  }
}

std::optional<Message> ParticipantChannel::receive(std::chrono::milliseconds timeout) {
  Message message;
  if (!receive_into(message, timeout)) {
    return std::nullopt;
  }
  return message;
}

bool ParticipantChannel::receive_into(Message &message, std::chrono::milliseconds timeout) {
  if (!socket_->wait_readable(timeout)) {
    return false;
  }
  auto frames = socket_->receive_frames();
  if (frames.empty()) {
    return false;
  }
  parse_frames(frames, message, routing_id_, coupler_);
  return true;
}

} // namespace fsi::proto
