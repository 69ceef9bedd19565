// Fuzz target: the coupler's message handling behind its socket. Each input is one message
// (frames as in FuzzFrames.hpp) sent by one of a few peers (the first byte picks it: the joined
// structure and fluid, a heartbeat socket, strangers) to a real CouplerChannel over inproc;
// the coupler's ParticipantTable takes it as during a run: it absorbs heartbeats, answers and
// ignores strangers and malformed messages, stops on a participant's error report, or hands a
// message on. Nothing may crash, hang or throw anything but the coupler's own run-stopping
// errors.

#include "FuzzFrames.hpp"
#include "coupler/CouplingErrors.hpp"
#include "coupler/ParticipantTable.hpp"
#include "proto/CouplerChannel.hpp"
#include "proto/ZmqContext.hpp"

#include <zmq_addon.hpp>

#include <array>
#include <chrono>
#include <memory>

namespace {

using namespace fsi;
using namespace std::chrono_literals;

const std::array<const char *, 6> peers = {"structure:main", "fluid:main", "structure:main/heartbeat",
                                           "fluid:other",    "stranger",   "\xff\x00\x01"};

struct Harness {
  proto::CouplerChannel channel{proto::Endpoint::parse("inproc://fsi-fuzz-coupler")};
  // Liveness limits beyond any fuzzing session: no heartbeat is sent, no one declared dead.
  coupler::ParticipantTable table{channel, coupler::Liveness{1000000s, 2000000s, 2000000s}, nullptr};
  std::vector<std::unique_ptr<zmq::socket_t>> dealers;

  Harness() {
    table.add("structure:main");
    table.add("fluid:main");
    table.close_admission();
    for (const char *id : peers) {
      auto socket = std::make_unique<zmq::socket_t>(proto::ZmqContext::shared(), zmq::socket_type::dealer);
      socket->set(zmq::sockopt::linger, 0);
      socket->set(zmq::sockopt::routing_id, zmq::buffer(std::string(id, id == peers[5] ? 3 : std::strlen(id))));
      socket->connect("inproc://fsi-fuzz-coupler");
      dealers.push_back(std::move(socket));
    }
  }

  // libFuzzer's timer interrupts the process every few seconds (SIGALRM): a ZeroMQ call it lands
  // in fails with EINTR, which cppzmq throws, and is repeated here. (Uncaught, it ended a CI run's
  // fuzzing with an abort once: a fault of this harness, not of the coupler's socket layer,
  // which repeats or reports EINTR itself.)
  template <class Call> static auto retry_interrupted(Call call) {
    while (true) {
      try {
        return call();
      } catch (const zmq::error_t &error) {
        if (error.num() != EINTR)
          throw;
      }
    }
  }

  void drain() {
    for (auto &dealer : dealers) {
      zmq::message_t part;
      while (retry_interrupted([&] { return dealer->recv(part, zmq::recv_flags::dontwait); }))
        ;
    }
  }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  static Harness harness;
  if (size < 1)
    return 0;
  auto &dealer = *harness.dealers[data[0] % peers.size()];
  auto frames = fsi::fuzz::split_frames(data + 1, size - 1);
  if (frames.empty())
    frames.emplace_back();
  for (std::size_t i = 0; i < frames.size(); ++i)
    Harness::retry_interrupted([&] {
      return dealer.send(frames[i], i + 1 < frames.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
    });
  try {
    auto &incoming = harness.table.next(std::chrono::steady_clock::now() + 3ms, "structure:main", "fuzz", 7);
    if (!incoming.is_malformed())
      (void)proto::body_name(incoming.envelope());
  } catch (const coupler::ParticipantFailed &) {
    // a participant's error report, or nothing handed on before the deadline: both are the
    // coupler's normal ways to stop or go on waiting
  } catch (const coupler::HandshakeRefused &) {
  }
  harness.drain();
  return 0;
}
