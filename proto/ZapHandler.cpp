#include "ZapHandler.hpp"

#include "TransportError.hpp"
#include "ZmqContext.hpp"

#include <spdlog/spdlog.h>
#include <zmq_addon.hpp>

#include <array>
#include <cerrno>
#include <iterator>
#include <memory>
#include <vector>

namespace fsi::proto {

namespace {

constexpr const char *zap_endpoint = "inproc://zeromq.zap.01";
constexpr long refusals_logged_in_full = 10;

std::string text_of(const zmq::message_t &frame) { return std::string(static_cast<const char *>(frame.data()), frame.size()); }

std::string z85_of(const zmq::message_t &frame) {
  if (frame.size() != 32)
    return "";
  std::array<char, 41> text{};
  zmq_z85_encode(text.data(), static_cast<const std::uint8_t *>(frame.data()), 32);
  return text.data();
}

} // namespace

ZapHandler::ZapHandler(const std::map<std::string, std::string> &admitted) {
  for (const auto &[name, key] : admitted)
    name_of_key_[key] = name;
  auto socket = std::make_unique<zmq::socket_t>(ZmqContext::shared(), zmq::socket_type::rep);
  socket->set(zmq::sockopt::linger, 0);
  try {
    socket->bind(zap_endpoint);
  } catch (const zmq::error_t &error) {
    throw TransportError(std::string("cannot start the CURVE authentication handler (") + error.what() +
                         "): one coupler with CURVE per process");
  }
  thread_ = std::thread([this, s = socket.release()] {
    std::unique_ptr<zmq::socket_t> owned(s);
    serve(owned.get());
  });
}

ZapHandler::~ZapHandler() {
  stop_ = true;
  if (thread_.joinable())
    thread_.join();
}

void ZapHandler::serve(void *raw) {
  auto &socket = *static_cast<zmq::socket_t *>(raw);
  try {
    while (!stop_) {
      zmq::pollitem_t item{socket.handle(), 0, ZMQ_POLLIN, 0};
      std::vector<zmq::message_t> request;
      try {
        if (zmq::poll(&item, 1, std::chrono::milliseconds(100)) == 0)
          continue;
        if (!zmq::recv_multipart(socket, std::back_inserter(request), zmq::recv_flags::dontwait))
          continue;
      } catch (const zmq::error_t &error) {
        if (error.num() == EINTR) // a signal landed in this thread (a stop request): not the end
          continue;               // (libzmq's ZAP requests are whole messages, queued together)
        throw;
      }
      // [version, request id, domain, address, routing id, mechanism, credentials...]
      const bool well_formed = request.size() >= 6 && text_of(request[0]) == "1.0";
      const std::string mechanism = well_formed ? text_of(request[5]) : "";
      const std::string key = well_formed && mechanism == "CURVE" && request.size() >= 7 ? z85_of(request[6]) : "";
      const auto admitted = name_of_key_.find(key);
      const bool ok = !key.empty() && admitted != name_of_key_.end();
      if (!ok) {
        const long n = ++refused_;
        const std::string address = request.size() > 3 ? text_of(request[3]) : "?";
        if (n <= refusals_logged_in_full)
          spdlog::warn("refused a connection from {}: {}", address,
                       mechanism != "CURVE" ? "it did not use CURVE (mechanism '" + mechanism + "')"
                                            : "its CURVE key " + key + " is not an admitted participant's");
        else if (n == 100 || n == 1000 || n == 10000 || n == 100000 || n == 1000000)
          spdlog::warn("{} connections refused so far", n);
      }
      std::array<std::string, 6> reply{"1.0", request.size() > 1 ? text_of(request[1]) : "", ok ? "200" : "400",
                                       ok ? "OK" : "not admitted", ok ? admitted->second : "", ""};
      for (std::size_t i = 0; i < reply.size(); ++i)
        socket.send(zmq::buffer(reply[i]), i + 1 < reply.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
    }
  } catch (const std::exception &e) {
    // The channel fails closed without us: every message then lacks a User-Id and is dropped.
    spdlog::error("the CURVE authentication handler stopped ({}): no participant can join from now on", e.what());
  }
  try {
    socket.unbind(zap_endpoint); // at once, so that a later handler of this process may bind it
  } catch (const zmq::error_t &) {
  }
}

} // namespace fsi::proto
