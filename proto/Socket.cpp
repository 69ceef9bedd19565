#include "Socket.hpp"

#include "TransportError.hpp"
#include "ZmqContext.hpp"

#include <zmq_addon.hpp>

#include <cerrno>
#include <iterator>
#include <utility>

namespace fsi::proto {

namespace {

std::string advice_for_bind_error(int error) {
  switch (error) {
  case EADDRINUSE:
    return "another process uses it; pick another port (or 0 for any free one) or stop that "
           "process";
  case EADDRNOTAVAIL:
    return "this machine has no such address; use 127.0.0.1 to stay on this machine";
  case ENODEV:
    return "ZeroMQ binds IP addresses or interface names, not host names; use the IP address";
  case EACCES:
    return "permission denied; use a port above 1023 or a writable ipc path";
  case ENOENT:
    return "the directory of the ipc path does not exist; create it or choose another path";
  default:
    return "check the endpoint in the case file";
  }
}

} // namespace

Socket::Socket(zmq::socket_type type, const ChannelOptions &options, std::string owner)
    : socket_(ZmqContext::shared(), type), owner_(std::move(owner)) {
  options.validate();
  apply(options);
}

void Socket::apply(const ChannelOptions &options) {
  socket_.set(zmq::sockopt::linger, static_cast<int>(options.linger.count()));
  socket_.set(zmq::sockopt::sndhwm, options.queue_limit_messages);
  socket_.set(zmq::sockopt::rcvhwm, options.queue_limit_messages);
  socket_.set(zmq::sockopt::sndtimeo, static_cast<int>(options.send_timeout.count()));
  socket_.set(zmq::sockopt::maxmsgsize, options.max_message_bytes);
  socket_.set(zmq::sockopt::tcp_keepalive, 1);
  socket_.set(zmq::sockopt::tcp_keepalive_idle, options.tcp_keepalive_idle_s);
  socket_.set(zmq::sockopt::tcp_keepalive_intvl, options.tcp_keepalive_interval_s);
  socket_.set(zmq::sockopt::tcp_keepalive_cnt, options.tcp_keepalive_probes);
}

void Socket::make_curve_server(const CurveSettings &curve, const std::string &zap_domain) {
  socket_.set(zmq::sockopt::curve_server, 1);
  socket_.set(zmq::sockopt::curve_secretkey, curve.secret_key);
  socket_.set(zmq::sockopt::zap_domain, zap_domain);
}

void Socket::make_curve_client(const CurveSettings &curve) {
  socket_.set(zmq::sockopt::curve_serverkey, curve.server_public_key);
  socket_.set(zmq::sockopt::curve_publickey, curve.public_key);
  socket_.set(zmq::sockopt::curve_secretkey, curve.secret_key);
}

void Socket::set_router_mandatory() { socket_.set(zmq::sockopt::router_mandatory, 1); }

void Socket::set_routing_id(const std::string &routing_id) { socket_.set(zmq::sockopt::routing_id, routing_id); }

void Socket::use_ipv6_for(const Endpoint &endpoint) { socket_.set(zmq::sockopt::ipv6, endpoint.is_ipv6() ? 1 : 0); }

Endpoint Socket::bind(const Endpoint &endpoint) {
  use_ipv6_for(endpoint);
  try {
    socket_.bind(endpoint.bind_form().str());
  } catch (const zmq::error_t &error) {
    throw TransportError(owner_ + " cannot bind " + endpoint.str() + " (" + error.what() +
                         "): " + advice_for_bind_error(error.num()));
  }
  return Endpoint::parse(socket_.get(zmq::sockopt::last_endpoint));
}

void Socket::connect(const Endpoint &endpoint) {
  use_ipv6_for(endpoint);
  try {
    socket_.connect(endpoint.str());
  } catch (const zmq::error_t &error) {
    throw TransportError(owner_ + " cannot connect to " + endpoint.str() + " (" + error.what() +
                         "); check the coupler's endpoint in the case file");
  }
}

bool Socket::wait_readable(std::chrono::milliseconds timeout) {
  zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
  try {
    zmq::poll(&item, 1, timeout.count() < 0 ? std::chrono::milliseconds(-1) : timeout);
  } catch (const zmq::error_t &error) {
    if (error.num() == EINTR) {
      return false;
    }
    throw TransportError(owner_ + " cannot wait for messages (" + error.what() + ")");
  }
  return (item.revents & ZMQ_POLLIN) != 0;
}

std::vector<zmq::message_t> Socket::receive_frames() {
  // Part by part: a signal (EINTR) between two parts of a message must not drop the parts read
  // and leave the rest to be read as a message of its own. ZeroMQ delivers a message's parts
  // together, so once the first is here the others are.
  std::vector<zmq::message_t> frames;
  while (true) {
    zmq::message_t part;
    try {
      if (!socket_.recv(part, zmq::recv_flags::dontwait)) {
        if (frames.empty())
          return {}; // nothing waiting after all
        continue;
      }
    } catch (const zmq::error_t &error) {
      if (error.num() != EINTR)
        throw TransportError(owner_ + " cannot receive (" + error.what() + ")");
      if (frames.empty())
        return {};
      continue;
    }
    const bool more = part.more();
    frames.push_back(std::move(part));
    if (!more)
      return frames;
  }
}

Socket::SendStatus Socket::send_frames(std::vector<zmq::message_t> &frames, bool wait) {
  try {
    for (std::size_t i = 0; i < frames.size(); ++i) {
      auto flags = i + 1 < frames.size() ? zmq::send_flags::sndmore : zmq::send_flags::none;
      if (!wait) // later frames of a message never block once the first is queued
        flags = flags | zmq::send_flags::dontwait;
      if (!socket_.send(frames[i], flags)) {
        return SendStatus::queue_full;
      }
    }
  } catch (const zmq::error_t &error) {
    if (error.num() == EHOSTUNREACH) {
      return SendStatus::unknown_peer;
    }
    throw TransportError(owner_ + " cannot send (" + error.what() + ")");
  }
  return SendStatus::sent;
}

} // namespace fsi::proto
