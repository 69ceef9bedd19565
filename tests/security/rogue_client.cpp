// fsi-rogue-client: a process that is not part of a run and tries to get into it, for the
// security tests (test_security.py, S2, S4 and S5 of docs/security.md). It connects to the
// coupler's endpoint as one of these rogues, sends what it says, waits, and prints how many
// messages it got back ("replies N") and whether its connection was accepted. Exit 0 whatever
// the coupler did: the test judges the coupler's results, not the rogue's.
//
//   fsi-rogue-client ENDPOINT MODE KEYS_DIR [--seconds S] [--bytes B] [--messages N]
// MODE:
//   plaintext         no CURVE, claiming to be structure:main
//   unknown-key       CURVE with a key pair of its own (right server key)
//   wrong-server-key  CURVE with the fluid's own key pair but a server key that is not the coupler's
//   stolen-role       CURVE with the fluid's key pair, claiming to be structure:main
//   oversized         CURVE with the fluid's key pair as fluid:rogue, one message part of B bytes
//   flood             CURVE with the fluid's key pair as fluid:flood, N Hellos without ever reading

#include "proto/CurveKeyFolder.hpp"
#include "proto/EnvelopeCodec.hpp"
#include "proto/Protocol.hpp"
#include "proto/ZmqContext.hpp"

#include <CLI/CLI.hpp>
#include <zmq.hpp>
#include <zmq_addon.hpp>

#include <chrono>
#include <cstring>
#include <iostream>
#include <iterator>
#include <thread>

namespace {

using namespace fsi::proto;

std::vector<zmq::message_t> hello_frames(const std::string &claimed_name) {
  Envelope hello = make_envelope(v2::ROLE_STRUCTURE, 0);
  hello.mutable_hello()->set_role(v2::ROLE_STRUCTURE);
  hello.mutable_hello()->set_participant_name(claimed_name);
  hello.mutable_hello()->set_protocol_version(current_protocol_version);
  std::vector<zmq::message_t> frames;
  EnvelopeCodec::encode(hello, frames);
  return frames;
}

void send(zmq::socket_t &socket, std::vector<zmq::message_t> frames) {
  for (std::size_t i = 0; i < frames.size(); ++i)
    socket.send(frames[i], (i + 1 < frames.size() ? zmq::send_flags::sndmore : zmq::send_flags::none) |
                               zmq::send_flags::dontwait);
}

} // namespace

int main(int argc, char **argv) {
  const ZmqContextCloser closer;
  CLI::App app{"fsi-rogue-client: tries to get into a run (security tests)"};
  std::string endpoint, mode, keys_dir;
  double seconds = 2.0;
  long bytes = 0, messages = 100000;
  app.add_option("endpoint", endpoint)->required();
  app.add_option("mode", mode)->required()->check(
      CLI::IsMember({"plaintext", "unknown-key", "wrong-server-key", "stolen-role", "oversized", "flood"}));
  app.add_option("keys_dir", keys_dir)->required();
  app.add_option("--seconds", seconds, "How long to wait for replies");
  app.add_option("--bytes", bytes, "oversized: the size of the message part");
  app.add_option("--messages", messages, "flood: how many");
  CLI11_PARSE(app, argc, argv);

  const CurveKeyFolder keys(keys_dir);
  zmq::socket_t socket(ZmqContext::shared(), zmq::socket_type::dealer);
  socket.set(zmq::sockopt::linger, 0);
  socket.set(zmq::sockopt::sndhwm, 1000000);
  std::string routing_id = "structure:main";
  if (mode != "plaintext") {
    const CurveKeyPair own = mode == "unknown-key" ? CurveKeyPair::generate() : keys.read_pair("fluid");
    const std::string server = mode == "wrong-server-key" ? CurveKeyPair::generate().public_key : keys.read_public("coupler");
    socket.set(zmq::sockopt::curve_serverkey, server);
    socket.set(zmq::sockopt::curve_publickey, own.public_key);
    socket.set(zmq::sockopt::curve_secretkey, own.secret_key);
    if (mode == "oversized")
      routing_id = "fluid:rogue";
    if (mode == "flood")
      routing_id = "fluid:flood";
  }
  socket.set(zmq::sockopt::routing_id, routing_id);
  zmq::socket_t monitor_socket(ZmqContext::shared(), zmq::socket_type::pair);
  zmq_socket_monitor(socket.handle(), "inproc://rogue-monitor", ZMQ_EVENT_HANDSHAKE_SUCCEEDED | ZMQ_EVENT_DISCONNECTED);
  monitor_socket.connect("inproc://rogue-monitor");
  socket.connect(endpoint);

  if (mode == "oversized") {
    std::vector<zmq::message_t> frames;
    frames.emplace_back(static_cast<std::size_t>(bytes));
    std::memset(frames.back().data(), 0x5a, frames.back().size());
    send(socket, std::move(frames));
  } else if (mode == "flood") {
    for (long i = 0; i < messages; ++i)
      send(socket, hello_frames("flood"));
  } else {
    send(socket, hello_frames("main"));
  }

  long replies = 0, disconnected = 0;
  bool accepted = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    zmq::pollitem_t items[] = {{monitor_socket.handle(), 0, ZMQ_POLLIN, 0}, {socket.handle(), 0, ZMQ_POLLIN, 0}};
    zmq::poll(items, 2, std::chrono::milliseconds(50));
    if (items[0].revents & ZMQ_POLLIN) {
      std::vector<zmq::message_t> event; // [event id (16 bit) + value (32 bit)][endpoint]
      (void)zmq::recv_multipart(monitor_socket, std::back_inserter(event));
      std::uint16_t id = 0;
      std::memcpy(&id, event.front().data(), sizeof(id));
      if (id == ZMQ_EVENT_HANDSHAKE_SUCCEEDED)
        accepted = true;
      else
        ++disconnected;
    }
    if ((items[1].revents & ZMQ_POLLIN) && mode != "flood") { // a flooder never reads
      std::vector<zmq::message_t> reply;
      if (zmq::recv_multipart(socket, std::back_inserter(reply), zmq::recv_flags::dontwait))
        ++replies;
    }
  }
  zmq_socket_monitor(socket.handle(), nullptr, 0);
  std::cout << "mode " << mode << " accepted " << (accepted ? 1 : 0) << " replies " << replies << " disconnected "
            << disconnected << std::endl;
  return 0;
}
