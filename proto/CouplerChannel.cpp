#include "CouplerChannel.hpp"

#include "EnvelopeCodec.hpp"
#include "Socket.hpp"
#include "TransportError.hpp"
#include "ZapHandler.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

namespace fsi::proto {

namespace {

// A DEALER's message arrives at the ROUTER as [routing id][Envelope][array frames...].
constexpr std::size_t header_frame = 1;

// The role a routing id claims: "structure" of "structure:main/heartbeat".
std::string role_of(const std::string &routing_id) { return routing_id.substr(0, routing_id.find(':')); }

} // namespace

CouplerChannel::CouplerChannel(const Endpoint &endpoint, const ChannelOptions &options)
    : endpoint_(endpoint), authenticate_(options.curve.has_value()) {
  endpoint.check_bindable(options.curve.has_value() || options.insecure_remote);
  socket_ = std::make_unique<Socket>(zmq::socket_type::router, options, "coupler");
  socket_->set_router_mandatory();
  if (options.curve) {
    // Fault hook of the reliability tests (S3): no handler, so that failing closed is shown.
    if (std::getenv("FSI_FAULT_NO_ZAP_HANDLER"))
      spdlog::warn("fault injection: the CURVE authentication handler is not started");
    else
      zap_ = std::make_unique<ZapHandler>(options.curve->admitted);
    socket_->make_curve_server(*options.curve, "fsi");
  }
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

bool CouplerChannel::try_send(const std::string &peer, const Envelope &envelope) noexcept {
  try {
    std::vector<zmq::message_t> frames;
    frames.emplace_back(peer.data(), peer.size());
    EnvelopeCodec::encode(envelope, frames);
    return socket_->send_frames(frames, false) == Socket::SendStatus::sent;
  } catch (...) {
    return false;
  }
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

bool CouplerChannel::admitted(const std::vector<zmq::message_t> &frames) {
  if (!authenticate_)
    return true;
  // Every message of an authenticated connection carries the name the handler gave its key.
  const std::string peer(static_cast<const char *>(frames.front().data()), frames.front().size());
  const char *user = frames.size() > header_frame ? zmq_msg_gets(frames[header_frame].handle(), "User-Id") : nullptr;
  if (user && *user && role_of(peer) == user)
    return true;
  if (++dropped_ <= 10)
    spdlog::warn("coupler dropped a message from '{}': {}", printable(peer),
                 user && *user ? "its connection authenticated as '" + std::string(user) + "', not as that role"
                               : std::string("its connection is not authenticated (no CURVE identity)"));
  else if (dropped_ == 100 || dropped_ == 1000 || dropped_ == 10000 || dropped_ == 100000 || dropped_ == 1000000)
    spdlog::warn("coupler dropped {} unauthenticated messages so far", dropped_);
  return false;
}

bool CouplerChannel::receive_into(Incoming &incoming, std::chrono::milliseconds timeout) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + timeout;
  std::vector<zmq::message_t> frames;
  do {
    const auto left = timeout.count() < 0 ? timeout
                                          : std::max(std::chrono::milliseconds(0),
                                                     std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
    if (!socket_->wait_readable(left))
      return false;
    frames = socket_->receive_frames();
    if (frames.empty())
      return false;
  } while (!admitted(frames));
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
