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

void parse_frames(std::vector<zmq::message_t> &frames, Envelope &envelope,
                  const std::string &routing_id, const Endpoint &coupler) {
  if (frames.size() != 1) {
    throw malformed_error(routing_id, coupler,
                          "it has " + std::to_string(frames.size()) +
                              " frames; an Envelope travels in exactly one");
  }
  if (auto malformed = EnvelopeCodec::decode_into(frames.front(), envelope)) {
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
  socket_->connect(coupler);
}

ParticipantChannel::~ParticipantChannel() = default;
ParticipantChannel::ParticipantChannel(ParticipantChannel &&) noexcept = default;
ParticipantChannel &ParticipantChannel::operator=(ParticipantChannel &&) noexcept = default;

void ParticipantChannel::send(const Envelope &envelope) {
  std::vector<zmq::message_t> frames;
  frames.push_back(EnvelopeCodec::encode(envelope));
  if (socket_->send_frames(frames) != Socket::SendStatus::sent) {
    throw TransportError("participant " + printable(routing_id_) + " cannot send " +
                         std::string(body_name(envelope)) + " to the coupler at " + coupler_.str() +
                         ": the queue stayed full for the send timeout; is the coupler running?");
  }
}

std::optional<Envelope> ParticipantChannel::receive(std::chrono::milliseconds timeout) {
  Envelope envelope;
  if (!receive_into(envelope, timeout)) {
    return std::nullopt;
  }
  return envelope;
}

bool ParticipantChannel::receive_into(Envelope &envelope, std::chrono::milliseconds timeout) {
  if (!socket_->wait_readable(timeout)) {
    return false;
  }
  auto frames = socket_->receive_frames();
  if (frames.empty()) {
    return false;
  }
  parse_frames(frames, envelope, routing_id_, coupler_);
  return true;
}

} // namespace fsi::proto
