// Faults that need raw ZeroMQ and Protobuf: a real fsi-coupler process (and, for a full run,
// real fsi-structure --coupled and fsi-prescribed-flow processes) on tcp loopback, with a raw
// DEALER socket sending what no participant would: a Hello of another protocol version,
// random bytes, frames that are not Envelopes.

#include "ChildProcess.hpp"
#include "proto/Protocol.hpp"

#include <gtest/gtest.h>
#include <zmq_addon.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using fsi::proto::Envelope;

// A short coupled scene (cases/sheet-in-uniform-flow, 1 s = 20000 steps of a few 0.1 ms), with
// liveness limits small enough for a test.
const char *const case_yaml = R"(run:
  end_time_s: 1.0
  time_step_s: 5.0e-5
  output_interval_s: 0.05
  progress_interval_s: 0.1
gravity_m_per_s2: [0, 0, 0]
structures:
  - name: sheet
    model: membrane
    size_m: [0.05, 0.05]
    n_points: [11, 11]
    material:
      mass_per_area_kg_per_m2: 0.08
      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
    edges: {s1_min: free, s1_max: free, s2_min: free, s2_max: free}
fluid:
  prescribed:
    uniform: {velocity_m_per_s: [0.2, 0.0, 0.1]}
coupling:
  law: penalty
  stiffness_n_per_m_per_measure: 3.2e4
  heartbeat_interval_s: 0.1
  timeout_s: 1.0
  handshake_timeout_s: 10.0
)";

using fsi::testing::read_text;
using Child = fsi::testing::ChildProcess;

class ProtocolFaults : public ::testing::Test {
protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "fsi-protocol-faults-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    fs::create_directories(dir_ / "case");
    std::ofstream(dir_ / "case" / "case.yaml") << case_yaml;
  }
  void TearDown() override {
    if (!std::getenv("FSI_KEEP_TEST_DIRS"))
      fs::remove_all(dir_);
  }

  /// Starts fsi-coupler and returns its endpoint (from <out>/coupler.endpoint).
  std::string start_coupler() {
    coupler_ = std::make_unique<Child>(
        std::vector<std::string>{FSI_COUPLER_EXE, (dir_ / "case").string(), "-o", out().string()},
        dir_ / "coupler.console");
    const auto deadline = Clock::now() + 20s;
    while (Clock::now() < deadline) {
      std::string endpoint = read_text(out() / "coupler.endpoint");
      if (!endpoint.empty() && endpoint.back() == '\n')
        return endpoint.substr(0, endpoint.size() - 1);
      if (coupler_->wait(0ms))
        break;
      std::this_thread::sleep_for(10ms);
    }
    ADD_FAILURE() << "no coupler.endpoint: " << coupler_->output();
    return {};
  }

  void start_participants(const std::string &endpoint) {
    structure_ = std::make_unique<Child>(std::vector<std::string>{FSI_STRUCTURE_EXE, (dir_ / "case").string(),
                                                                  "--coupled", "--endpoint", endpoint, "-o",
                                                                  out().string()},
                                         dir_ / "structure.console");
    fluid_ = std::make_unique<Child>(std::vector<std::string>{FSI_FLUID_EXE, (dir_ / "case").string(), "--endpoint",
                                                              endpoint, "-o", out().string()},
                                     dir_ / "fluid.console");
  }

  /// Waits until the coupler has logged a progress line ("step N/M"): the run is under way.
  bool wait_for_progress() {
    const auto deadline = Clock::now() + 20s;
    while (Clock::now() < deadline) {
      if (coupler_->output().find("step ") != std::string::npos &&
          coupler_->output().find("/20000") != std::string::npos)
        return true;
      if (coupler_->wait(0ms))
        return false;
      std::this_thread::sleep_for(10ms);
    }
    return false;
  }

  zmq::socket_t raw_dealer(const std::string &routing_id, const std::string &endpoint) {
    zmq::socket_t socket(context_, zmq::socket_type::dealer);
    socket.set(zmq::sockopt::linger, 0);
    socket.set(zmq::sockopt::routing_id, routing_id);
    socket.connect(endpoint);
    return socket;
  }

  /// The next Envelope on a raw socket within timeout, or nullopt.
  static std::optional<Envelope> receive(zmq::socket_t &socket, std::chrono::milliseconds timeout) {
    zmq::pollitem_t item{socket.handle(), 0, ZMQ_POLLIN, 0};
    if (zmq::poll(&item, 1, timeout) <= 0)
      return std::nullopt;
    zmq::message_t frame;
    if (!socket.recv(frame))
      return std::nullopt;
    Envelope envelope;
    if (!envelope.ParseFromArray(frame.data(), static_cast<int>(frame.size())))
      return std::nullopt;
    return envelope;
  }

  /// The next ErrorReport on a raw socket (heartbeats skipped), or nullopt.
  static std::optional<std::string> receive_error(zmq::socket_t &socket, std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (Clock::now() < deadline) {
      auto envelope = receive(socket, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
      if (envelope && envelope->has_error())
        return envelope->error().message();
    }
    return std::nullopt;
  }

  static Envelope hello(std::uint32_t envelope_version, std::uint32_t hello_version) {
    Envelope envelope = fsi::proto::make_envelope(fsi::proto::v2::ROLE_STRUCTURE, 0);
    envelope.set_protocol_version(envelope_version);
    auto *h = envelope.mutable_hello();
    h->set_role(fsi::proto::v2::ROLE_STRUCTURE);
    h->set_participant_name("main");
    h->set_protocol_version(hello_version);
    h->set_case_fingerprint("0000000000000000");
    return envelope;
  }

  fs::path out() const { return dir_ / "out"; }

  void expect_refused(const Envelope &hello, const std::string &coupler_says,
                      const std::vector<std::string> &error_says);

  fs::path dir_;
  zmq::context_t context_;
  std::unique_ptr<Child> coupler_, structure_, fluid_;
};

void send(zmq::socket_t &socket, const Envelope &envelope) {
  socket.send(zmq::buffer(envelope.SerializeAsString()), zmq::send_flags::none);
}

// c. A structure participant of another protocol version is refused: ErrorReport naming the
// version, coupler exit 2 with a clear message. Three ways to be of another version: a version-1
// participant (the Envelope says 1), a newer one (3), and Hello.protocol_version 3 inside a
// current Envelope.
/// Sends `hello` to a fresh coupler, checks that it exits 2 saying `coupler_says` and that the
/// participant got an ErrorReport containing each of `error_says`.
void ProtocolFaults::expect_refused(const Envelope &hello, const std::string &coupler_says,
                                    const std::vector<std::string> &error_says) {
  const std::string endpoint = start_coupler();
  ASSERT_FALSE(endpoint.empty());
  auto raw = raw_dealer("structure:main", endpoint);
  send(raw, hello);
  const auto error = receive_error(raw, 5s);
  const auto code = coupler_->wait(10s);
  ASSERT_TRUE(code) << "the coupler still runs: " << coupler_->output();
  EXPECT_EQ(*code, 2) << coupler_->output();
  EXPECT_NE(coupler_->output().find(coupler_says), std::string::npos) << coupler_->output();
  ASSERT_TRUE(error) << "no ErrorReport reached the refused participant (lost when the coupler exited?)";
  for (const auto &text : error_says)
    EXPECT_NE(error->find(text), std::string::npos) << *error;
}

TEST_F(ProtocolFaults, AParticipantOfVersion1IsRefused) {
  ASSERT_NO_FATAL_FAILURE(
      expect_refused(hello(1, 1), "protocol_version 1 but this side speaks version 2", {"version", "1"}));
  EXPECT_NE(coupler_->output().find("structure:main"), std::string::npos) << coupler_->output();
}

TEST_F(ProtocolFaults, EnvelopeOfVersion3IsRefused) {
  expect_refused(hello(3, 3), "protocol_version 3", {"version", "3"});
}

TEST_F(ProtocolFaults, HelloOfVersion3IsRefused) {
  expect_refused(hello(2, 3), "speaks protocol version 3, this coupler version 2", {"protocol version 3"});
}

// d. Garbage sent to the coupler's socket during a run is answered with ErrorReports and the
// run completes.
TEST_F(ProtocolFaults, GarbageDuringARunIsAnsweredAndTheRunCompletes) {
  const std::string endpoint = start_coupler();
  ASSERT_FALSE(endpoint.empty());
  start_participants(endpoint);
  ASSERT_TRUE(wait_for_progress()) << coupler_->output();

  // Random bytes from a peer with a random (non-zero first byte) routing id.
  std::mt19937 generator(20240501);
  std::uniform_int_distribution<int> byte(0, 255), length(1, 200);
  std::string routing_id(8, '\0');
  for (auto &c : routing_id)
    c = static_cast<char>(1 + byte(generator) % 255);
  auto random_peer = raw_dealer(routing_id, endpoint);
  int random_answered = 0;
  const int n_random = 20;
  for (int i = 0; i < n_random; ++i) {
    std::string bytes(static_cast<std::size_t>(length(generator)), '\0');
    for (auto &c : bytes)
      c = static_cast<char>(byte(generator));
    random_peer.send(zmq::buffer(bytes), zmq::send_flags::none);
    random_answered += receive_error(random_peer, 2s) ? 1 : 0;
  }
  EXPECT_EQ(random_answered, n_random);

  // Frames that are not Envelopes, from a readable routing id.
  auto garbage = raw_dealer("garbage:1", endpoint);
  garbage.send(zmq::str_buffer("this is not an Envelope \xff\xfe"), zmq::send_flags::none);
  auto answer = receive_error(garbage, 2s);
  ASSERT_TRUE(answer);
  EXPECT_NE(answer->find("could not read"), std::string::npos) << *answer;
  garbage.send(zmq::str_buffer(""), zmq::send_flags::none);
  EXPECT_TRUE(receive_error(garbage, 2s)) << "empty frame";
  const std::string good = hello(1, 1).SerializeAsString();
  garbage.send(zmq::buffer(good), zmq::send_flags::sndmore);
  garbage.send(zmq::buffer(good), zmq::send_flags::none);
  EXPECT_TRUE(receive_error(garbage, 2s)) << "two frames";
  Envelope no_body = fsi::proto::make_envelope(fsi::proto::v2::ROLE_FLUID, 3);
  send(garbage, no_body);
  EXPECT_TRUE(receive_error(garbage, 2s)) << "Envelope without a body";
  send(garbage, hello(1, 1));
  EXPECT_TRUE(receive_error(garbage, 2s)) << "Hello in the middle of a run";

  const auto code = coupler_->wait(60s);
  ASSERT_TRUE(code) << coupler_->output();
  EXPECT_EQ(*code, 0) << coupler_->output();
  EXPECT_NE(coupler_->output().find("completed: 20000 steps"), std::string::npos) << coupler_->output();
  EXPECT_NE(coupler_->output().find("ignored a malformed message"), std::string::npos);
  EXPECT_TRUE(structure_->wait(5s));
  EXPECT_TRUE(fluid_->wait(5s));
}

// docs/protocol.md: "A malformed message (... wrong version ...) is answered with an
// ErrorReport; it never stops the receiver by itself." A stray process of another build that
// names itself structure:<something> and connects to a coupler that is mid-run is not one of
// the run's participants; its message should be answered, not end the run.
TEST_F(ProtocolFaults, WrongVersionFromAStrangerDuringARunDoesNotStopIt) {
  const std::string endpoint = start_coupler();
  ASSERT_FALSE(endpoint.empty());
  start_participants(endpoint);
  ASSERT_TRUE(wait_for_progress()) << coupler_->output();
  auto stranger = raw_dealer("structure:old-build", endpoint);
  send(stranger, hello(2, 2));
  EXPECT_TRUE(receive_error(stranger, 2s));
  const auto code = coupler_->wait(60s);
  ASSERT_TRUE(code) << coupler_->output();
  EXPECT_EQ(*code, 0) << "the run was stopped by a process that is not part of it:\n" << coupler_->output();
}

} // namespace
