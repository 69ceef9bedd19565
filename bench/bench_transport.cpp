// bench_transport: time of one coupling round trip over TCP loopback, coupler -> participant ->
// coupler, each way carrying N points of two N x 3 arrays (FluidAdvance: positions + force
// densities; AdvanceReply: positions + velocities), for N = 10^2 .. 10^5. Side by side, in the
// same iteration, a raw ZeroMQ round trip of the same number of bytes without Protobuf.
// Both paths start and end in PointArrays, so both pay the copies any transport needs (arrays
// into a message, message into arrays); the protocol path adds the Envelope header frame (its
// arrays travel as frames of their own, protocol version 2).
// reuse:1 keeps the Messages from step to step (receive_into, headers refilled in place), as a
// coupler does; reuse:0 builds and receives fresh ones, the simplest code.
// Participant and raw echo run in threads of this process (one ZeroMQ context, one I/O thread
// shared by both ends: a little pessimistic next to separate processes).
// Time column: the Envelope round trip. Counters: envelope_us, raw_us, ratio (target: <= 3),
// MB_per_trip (both directions).
// BM_CurveCost: the same Envelope round trip over a plaintext pair of channels and over a pair
// with CURVE (encrypted and authenticated, as coupling.security: curve), alternating within
// each iteration. Counters: plain_us, curve_us, curve_ratio.

#include "proto/CouplerChannel.hpp"
#include "proto/CurveKeyFolder.hpp"
#include "proto/Message.hpp"
#include "proto/ParticipantChannel.hpp"
#include "proto/ZmqContext.hpp"

#include <benchmark/benchmark.h>
#include <zmq_addon.hpp>

#include <chrono>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <thread>

namespace {

using namespace fsi;
using namespace fsi::proto;
using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds patience{10000};

/// The two N x 3 arrays of one message.
struct StepArrays {
  explicit StepArrays(Eigen::Index n_points)
      : first(PointArray::Random(n_points, 3)), second(PointArray::Random(n_points, 3)) {}
  PointArray first;
  PointArray second;
};

/// Participant: answers every FluidAdvance with an AdvanceReply of the arrays, until Shutdown.
class EnvelopeEcho {
public:
  EnvelopeEcho(const Endpoint &coupler, Eigen::Index n_points, bool reuse, const ChannelOptions &options)
      : channel_(coupler, v2::ROLE_FLUID, "bench", options), arrays_(n_points), n_points_(n_points),
        reuse_(reuse) {}

  void run() {
    Envelope hello = make_envelope(v2::ROLE_FLUID, 0);
    hello.mutable_hello()->set_participant_name("bench");
    channel_.send(hello);
    for (receive(); !request_.envelope().has_shutdown(); receive()) {
      // Two arrays each way: the request reuses the AdvanceReply layout (the transport does
      // not look at meanings).
      const auto &body = request_.envelope().advance_reply();
      arrays_.first = request_.points(body.position_m(), n_points_, "position_m");
      arrays_.second = request_.points(body.velocity_m_per_s(), n_points_, "velocity");
      channel_.send(reply(request_.envelope().step()));
    }
  }

private:
  void receive() {
    if (!reuse_) {
      request_ = Message();
    }
    if (!channel_.receive_into(request_, patience)) {
      throw std::runtime_error("bench participant: nothing from the coupler for 10 s");
    }
  }

  Message &reply(std::uint64_t step) {
    if (!reuse_) {
      reply_ = Message();
    }
    Envelope &header = reply_.envelope();
    header.set_protocol_version(current_protocol_version);
    header.set_sender_role(v2::ROLE_FLUID);
    header.set_step(step);
    reply_.add_points(*header.mutable_advance_reply()->mutable_position_m(), arrays_.first);
    reply_.add_points(*header.mutable_advance_reply()->mutable_velocity_m_per_s(), arrays_.second);
    return reply_;
  }

  ParticipantChannel channel_;
  StepArrays arrays_;
  Eigen::Index n_points_;
  bool reuse_;
  Message request_;
  Message reply_;
};

void copy_into(const StepArrays &arrays, zmq::message_t &message) {
  auto *bytes = static_cast<char *>(message.data());
  std::memcpy(bytes, arrays.first.data(), sizeof(double) * arrays.first.size());
  std::memcpy(bytes + sizeof(double) * arrays.first.size(), arrays.second.data(),
              sizeof(double) * arrays.second.size());
}

void copy_from(const zmq::message_t &message, StepArrays &arrays) {
  const auto *bytes = static_cast<const char *>(message.data());
  std::memcpy(arrays.first.data(), bytes, sizeof(double) * arrays.first.size());
  std::memcpy(arrays.second.data(), bytes + sizeof(double) * arrays.first.size(),
              sizeof(double) * arrays.second.size());
}

zmq::socket_t raw_socket(zmq::socket_type type) {
  zmq::socket_t socket(ZmqContext::shared(), type);
  socket.set(zmq::sockopt::linger, 0);
  return socket;
}

/// Raw participant: copies each message into arrays and the arrays back into an answer of the
/// same size, until an empty message.
void run_raw_echo(const std::string &endpoint, Eigen::Index n_points) {
  auto socket = raw_socket(zmq::socket_type::dealer);
  socket.connect(endpoint);
  socket.send(zmq::str_buffer("hello"));
  StepArrays arrays(n_points);
  zmq::message_t request;
  while (socket.recv(request) && request.size() > 0) {
    copy_from(request, arrays);
    zmq::message_t reply(request.size());
    copy_into(arrays, reply);
    socket.send(reply, zmq::send_flags::none);
  }
}

/// Coupler side of both round trips, with the participants in their threads.
class RoundTrips {
public:
  RoundTrips(Eigen::Index n_points, bool reuse, const ChannelOptions &coupler_options = {},
             const ChannelOptions &participant_options = {})
      : n_points_(n_points), reuse_(reuse), out_(n_points), in_(n_points),
        coupler_(Endpoint::parse("tcp://127.0.0.1:0"), coupler_options),
        router_(raw_socket(zmq::socket_type::router)),
        echo_(std::make_unique<EnvelopeEcho>(coupler_.endpoint(), n_points, reuse, participant_options)) {
    router_.bind("tcp://127.0.0.1:0");
    envelope_echo_ = std::thread([this] { echo_->run(); });
    raw_echo_ = std::thread(run_raw_echo, router_.get(zmq::sockopt::last_endpoint), n_points);
    receive_envelope();
    envelope_peer_ = incoming_.peer();
    raw_peer_ = receive_raw().front().to_string();
    // The same bytes as the message: its header and its two arrays.
    raw_bytes_ = fill_advance(0).envelope().ByteSizeLong() + 2 * sizeof(double) * out_.first.size();
  }

  ~RoundTrips() {
    Envelope shutdown = make_envelope(v2::ROLE_COUPLER, 0);
    shutdown.mutable_shutdown()->set_success(true);
    coupler_.send(envelope_peer_, shutdown);
    send_raw(zmq::message_t());
    envelope_echo_.join();
    raw_echo_.join();
  }

  void envelope_round_trip(std::uint64_t step) {
    coupler_.send(envelope_peer_, fill_advance(step));
    receive_envelope();
    const auto &reply = incoming_.envelope().advance_reply();
    in_.first = incoming_.message().points(reply.position_m(), n_points_, "position_m");
    in_.second = incoming_.message().points(reply.velocity_m_per_s(), n_points_, "velocity_m_per_s");
  }

  void raw_round_trip() {
    zmq::message_t request(raw_bytes_);
    copy_into(out_, request);
    send_raw(std::move(request));
    copy_from(receive_raw().back(), in_);
  }

  bool arrays_came_back() const { return in_.first == out_.first && in_.second == out_.second; }
  std::size_t bytes_per_message() const { return raw_bytes_; }

private:
  Message &fill_advance(std::uint64_t step) {
    if (!reuse_) {
      advance_ = Message();
    }
    Envelope &header = advance_.envelope();
    header.set_protocol_version(current_protocol_version);
    header.set_sender_role(v2::ROLE_COUPLER);
    header.set_step(step);
    auto *body = header.mutable_advance_reply();
    advance_.add_points(*body->mutable_position_m(), out_.first);
    advance_.add_points(*body->mutable_velocity_m_per_s(), out_.second);
    return advance_;
  }

  void receive_envelope() {
    if (!reuse_) {
      incoming_ = Incoming();
    }
    if (!coupler_.receive_into(incoming_, patience) || incoming_.is_malformed()) {
      throw std::runtime_error("bench coupler: no valid answer from the participant");
    }
  }

  void send_raw(zmq::message_t payload) {
    router_.send(zmq::buffer(raw_peer_), zmq::send_flags::sndmore);
    router_.send(payload, zmq::send_flags::none);
  }

  std::vector<zmq::message_t> receive_raw() {
    std::vector<zmq::message_t> frames;
    if (!zmq::recv_multipart(router_, std::back_inserter(frames))) {
      throw std::runtime_error("bench coupler: no raw answer");
    }
    return frames;
  }

  Eigen::Index n_points_;
  bool reuse_;
  StepArrays out_;
  StepArrays in_;
  CouplerChannel coupler_;
  zmq::socket_t router_;
  std::unique_ptr<EnvelopeEcho> echo_;
  std::thread envelope_echo_;
  std::thread raw_echo_;
  Message advance_;
  Incoming incoming_;
  std::string envelope_peer_;
  std::string raw_peer_;
  std::size_t raw_bytes_ = 0;
};

double seconds_of(const std::function<void()> &work) {
  const auto start = Clock::now();
  work();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void BM_RoundTrip(benchmark::State &state) {
  RoundTrips trips(state.range(0), state.range(1) != 0);
  double envelope_s = 0.0, raw_s = 0.0;
  std::uint64_t step = 0;
  for (auto _ : state) {
    const double envelope_trip_s = seconds_of([&] { trips.envelope_round_trip(++step); });
    raw_s += seconds_of([&] { trips.raw_round_trip(); });
    envelope_s += envelope_trip_s;
    state.SetIterationTime(envelope_trip_s);
  }
  if (!trips.arrays_came_back()) {
    state.SkipWithError("the arrays did not come back intact");
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["envelope_us"] = 1e6 * envelope_s / n;
  state.counters["raw_us"] = 1e6 * raw_s / n;
  state.counters["ratio"] = envelope_s / raw_s;
  state.counters["MB_per_trip"] = 2e-6 * static_cast<double>(trips.bytes_per_message());
}

void BM_CurveCost(benchmark::State &state) {
  const CurveKeyPair server = CurveKeyPair::generate(), client = CurveKeyPair::generate();
  ChannelOptions coupler_options, participant_options;
  coupler_options.curve = CurveSettings{server.public_key, server.secret_key, "", {{"fluid", client.public_key}}};
  participant_options.curve = CurveSettings{client.public_key, client.secret_key, server.public_key, {}};
  RoundTrips plain(state.range(0), true);
  RoundTrips curve(state.range(0), true, coupler_options, participant_options);
  double plain_s = 0.0, curve_s = 0.0;
  std::uint64_t step = 0;
  for (auto _ : state) {
    ++step;
    const double curve_trip_s = seconds_of([&] { curve.envelope_round_trip(step); });
    plain_s += seconds_of([&] { plain.envelope_round_trip(step); });
    curve_s += curve_trip_s;
    state.SetIterationTime(curve_trip_s);
  }
  if (!plain.arrays_came_back() || !curve.arrays_came_back())
    state.SkipWithError("the arrays did not come back intact");
  const double n = static_cast<double>(state.iterations());
  state.counters["plain_us"] = 1e6 * plain_s / n;
  state.counters["curve_us"] = 1e6 * curve_s / n;
  state.counters["curve_ratio"] = curve_s / plain_s;
  state.counters["MB_per_trip"] = 2e-6 * static_cast<double>(curve.bytes_per_message());
}

BENCHMARK(BM_CurveCost)->ArgName("points")->Arg(100)->Arg(10000)->Arg(100000)->UseManualTime()->Unit(benchmark::kMicrosecond);

BENCHMARK(BM_RoundTrip)
    ->ArgNames({"points", "reuse"})
    ->ArgsProduct({{100, 1000, 10000, 100000}, {1, 0}})
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
