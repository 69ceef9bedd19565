#include "CouplerChannel.hpp"

#include "EnvelopeCodec.hpp"
#include "Socket.hpp"
#include "TransportError.hpp"

#include <utility>
#include <vector>

namespace fsi::proto {

namespace {

// A DEALER's message arrives at the ROUTER as [routing id][Envelope][array frames...].
constexpr std::size_t header_frame = 1;

} // namespace

CouplerChannel::CouplerChannel(const Endpoint &endpoint, const ChannelOptions &options)
    : endpoint_(endpoint) {
  endpoint.check_bindable(options.allow_remote);
  socket_ = std::make_unique<Socket>(zmq::socket_type::router, options, "coupler");
  socket_->set_router_mandatory();
  endpoint_ = socket_->bind(endpoint);
}

CouplerChannel::~CouplerChannel() = default;
CouplerChannel::CouplerChannel(CouplerChannel &&) noexcept = default;
CouplerChannel &CouplerChannel::operator=(CouplerChannel &&) noexcept = default;

void CouplerChannel::send(const std::string &peer, Message &message) {
  std::vector<zmq::message_t> frames;
  frames.emplace_back(peer.data(), peer.size());
  EnvelopeCodec::encode(message, frames);
  send_frames(peer, frames, message.envelope());
}

void CouplerChannel::send(const std::string &peer, const Envelope &envelope) {
  std::vector<zmq::message_t> frames;
  frames.emplace_back(peer.data(), peer.size());
  EnvelopeCodec::encode(envelope, frames);
  send_frames(peer, frames, envelope);
}

void CouplerChannel::send_frames(const std::string &peer, std::vector<zmq::message_t> &frames,
                                 const Envelope &envelope) {
  switch (socket_->send_frames(frames)) {
  case Socket::SendStatus::sent:
    return;
  case Socket::SendStatus::unknown_peer:
    throw TransportError("coupler at " + endpoint_.str() + " cannot send " +
                         std::string(body_name(envelope)) + " to '" + printable(peer) +
                         "': no participant with that routing id is connected (it may have "
                         "exited; see its log)");
  case Socket::SendStatus::queue_full:
    throw TransportError("coupler at " + endpoint_.str() + " cannot send " +
                         std::string(body_name(envelope)) + " to '" + printable(peer) +
                         "': its queue stayed full for the send timeout, so it is stuck or too "
                         "slow; check that participant");
  }
}

std::optional<Incoming> CouplerChannel::receive(std::chrono::milliseconds timeout) {
  Incoming incoming;
  if (!receive_into(incoming, timeout)) {
    return std::nullopt;
  }
  return incoming;
}

bool CouplerChannel::receive_into(Incoming &incoming, std::chrono::milliseconds timeout) {
  if (!socket_->wait_readable(timeout)) {
    return false;
  }
  auto frames = socket_->receive_frames();
  if (frames.empty()) {
    return false;
  }
  incoming.peer_.assign(static_cast<const char *>(frames.front().data()), frames.front().size());
  auto malformed = frames.size() <= header_frame
                       ? MalformedMessage{MalformedMessage::Kind::wrong_framing, "the message has no Envelope frame"}
                       : EnvelopeCodec::decode_into(frames, header_frame, incoming.message_to_fill());
  if (malformed) {
    incoming.content_ = std::move(*malformed);
  }
  return true;
}

} // namespace fsi::proto
