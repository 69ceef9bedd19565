// The transport contract: every test runs over tcp (loopback), ipc and inproc.

#include "SampleEnvelopes.hpp"
#include "TransportFixture.hpp"

#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"
#include "proto/ZmqContext.hpp"

#include <zmq_addon.hpp>

#include <cstring>
#include <map>
#include <random>
#include <set>

namespace fsi::proto::test {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using Kind = MalformedMessage::Kind;

class TransportContract : public TransportFixture {};

/// A plain ZeroMQ socket on the shared context, for sending what a channel never would.
zmq::socket_t raw_socket(zmq::socket_type type) {
  zmq::socket_t socket(ZmqContext::shared(), type);
  socket.set(zmq::sockopt::linger, 0);
  return socket;
}

PointArray random_points(Eigen::Index n_points, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> value(-10.0, 10.0);
  PointArray points(n_points, 3);
  for (Eigen::Index i = 0; i < points.size(); ++i) {
    points.data()[i] = value(generator);
  }
  return points;
}

bool identical(const PointsView &a, const PointArray &b) {
  return a.rows() == b.rows() && std::memcmp(a.data(), b.data(), sizeof(double) * b.size()) == 0;
}

TEST_P(TransportContract, EveryBodyTypeReachesTheCouplerWithExactValues) {
  auto participant = make_participant(v1::ROLE_STRUCTURE, "flag");
  for (const Envelope &sent : sample_envelopes()) {
    SCOPED_TRACE(std::string(body_name(sent)));
    participant.send(sent);
    const Incoming incoming = receive_at_coupler();
    ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
    EXPECT_EQ(incoming.peer(), "structure:flag");
    EXPECT_TRUE(same_bytes(incoming.envelope(), sent));
  }
}

TEST_P(TransportContract, EveryBodyTypeReachesTheParticipantWithExactValues) {
  auto participant = make_participant(v1::ROLE_FLUID, "main");
  participant.send(sample_envelopes().front());
  const std::string peer = receive_at_coupler().peer();
  for (const Envelope &sent : sample_envelopes()) {
    SCOPED_TRACE(std::string(body_name(sent)));
    coupler().send(peer, sent);
    EXPECT_TRUE(same_bytes(receive_at(participant), sent));
  }
}

TEST_P(TransportContract, SamplesCoverEveryBodyType) {
  std::set<int> sampled;
  for (const Envelope &envelope : sample_envelopes()) {
    sampled.insert(envelope.body_case());
  }
  const auto *body = Envelope::descriptor()->FindOneofByName("body");
  ASSERT_NE(body, nullptr);
  for (int i = 0; i < body->field_count(); ++i) {
    EXPECT_EQ(sampled.count(body->field(i)->number()), 1U) << body->field(i)->name();
  }
}

TEST_P(TransportContract, HundredThousandPointArraysArriveIntact) {
  constexpr Eigen::Index n_points = 100000;
  const PointArray positions_m = random_points(n_points, 1);
  const PointArray velocities_m_per_s = random_points(n_points, 2);
  auto participant = make_participant(v1::ROLE_STRUCTURE, "flag");

  Envelope reply = make_envelope(v1::ROLE_STRUCTURE, 3);
  write_points(positions_m, *reply.mutable_advance_reply()->mutable_position_m());
  write_points(velocities_m_per_s, *reply.mutable_advance_reply()->mutable_velocity_m_per_s());
  participant.send(reply);
  const Incoming incoming = receive_at_coupler();
  ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
  const auto &received = incoming.envelope().advance_reply();
  EXPECT_TRUE(identical(view_points(received.position_m(), n_points, "position_m"), positions_m));
  EXPECT_TRUE(identical(view_points(received.velocity_m_per_s(), n_points, "velocity_m_per_s"),
                        velocities_m_per_s));

  Envelope advance = make_envelope(v1::ROLE_COUPLER, 3);
  write_points(velocities_m_per_s,
               *advance.mutable_structure_advance()->mutable_load_density_n_per_measure());
  coupler().send(incoming.peer(), advance);
  const Envelope back = receive_at(participant);
  EXPECT_TRUE(identical(view_points(back.structure_advance().load_density_n_per_measure(), "load"),
                        velocities_m_per_s));
  Envelope request = make_envelope(v1::ROLE_COUPLER, 4);
  write_points(positions_m, *request.mutable_interpolate_request()->mutable_position_m());
  coupler().send(incoming.peer(), request);
  const Envelope back_request = receive_at(participant);
  EXPECT_TRUE(identical(view_points(back_request.interpolate_request().position_m(), "position_m"), positions_m));
}

TEST_P(TransportContract, ReceivingIntoAnEnvelopeReusesItsArraysAndLeavesNothingStale) {
  constexpr Eigen::Index n_points = 1000;
  auto participant = make_participant(v1::ROLE_STRUCTURE, "flag");
  Envelope step_one = make_envelope(v1::ROLE_STRUCTURE, 1);
  step_one.mutable_advance_reply()->set_time_s(0.5);
  step_one.mutable_advance_reply()->set_solve_wall_s(0.25);
  write_points(random_points(n_points, 3), *step_one.mutable_advance_reply()->mutable_position_m());
  Envelope step_two = make_envelope(v1::ROLE_STRUCTURE, 0); // defaults: not on the wire
  write_points(random_points(n_points, 4), *step_two.mutable_advance_reply()->mutable_position_m());

  Incoming incoming;
  participant.send(step_one);
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  ASSERT_TRUE(same_bytes(incoming.envelope(), step_one));
  const double *storage = incoming.envelope().advance_reply().position_m().data();
  participant.send(step_two);
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  EXPECT_TRUE(same_bytes(incoming.envelope(), step_two)); // no stale step, time or wall time
  EXPECT_EQ(incoming.envelope().advance_reply().position_m().data(), storage);

  participant.send(sample_envelopes().front()); // another body type
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  EXPECT_TRUE(same_bytes(incoming.envelope(), sample_envelopes().front()));

  Envelope at_participant;
  for (const Envelope &sent : {step_one, step_two, sample_envelopes().back()}) {
    coupler().send(incoming.peer(), sent);
    ASSERT_TRUE(participant.receive_into(at_participant, patience));
    EXPECT_TRUE(same_bytes(at_participant, sent)) << body_name(sent);
  }
  EXPECT_FALSE(participant.receive_into(at_participant, 10ms));
  EXPECT_TRUE(same_bytes(at_participant, sample_envelopes().back()));
}

TEST_P(TransportContract, ReceivingIntoAnIncomingRecoversAfterAMalformedMessage) {
  auto raw = raw_socket(zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "raw:mixed");
  raw.connect(coupler().endpoint().str());
  Incoming incoming;
  raw.send(zmq::str_buffer("\xff garbage"));
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  EXPECT_TRUE(incoming.is_malformed());
  raw.send(zmq::buffer(sample_envelopes().back().SerializeAsString()));
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
  EXPECT_EQ(incoming.peer(), "raw:mixed");
  EXPECT_TRUE(same_bytes(incoming.envelope(), sample_envelopes().back()));
}

TEST_P(TransportContract, TwoParticipantsKeepTheirIdentities) {
  auto fluid = make_participant(v1::ROLE_FLUID, "main");
  auto structure = make_participant(v1::ROLE_STRUCTURE, "main");
  Envelope hello = make_envelope(v1::ROLE_FLUID, 0);
  hello.mutable_hello()->set_participant_name("fluid side");
  fluid.send(hello);
  hello.mutable_hello()->set_participant_name("structure side");
  structure.send(hello);

  std::map<std::string, std::string> name_of_peer;
  for (int i = 0; i < 2; ++i) {
    const Incoming incoming = receive_at_coupler();
    name_of_peer[incoming.peer()] = incoming.envelope().hello().participant_name();
  }
  EXPECT_EQ(name_of_peer["fluid:main"], "fluid side");
  EXPECT_EQ(name_of_peer["structure:main"], "structure side");

  for (const auto &[peer, name] : name_of_peer) {
    Envelope answer = make_envelope(v1::ROLE_COUPLER, 1);
    answer.mutable_shutdown()->set_reason("for " + name);
    coupler().send(peer, answer);
  }
  EXPECT_EQ(receive_at(fluid).shutdown().reason(), "for fluid side");
  EXPECT_EQ(receive_at(structure).shutdown().reason(), "for structure side");
}

TEST_P(TransportContract, CouplerReceiveReturnsNothingWithinTheTimeout) {
  const auto start = Clock::now();
  EXPECT_FALSE(coupler().receive(200ms).has_value());
  const auto elapsed = Clock::now() - start;
  EXPECT_GE(elapsed, 190ms);
  EXPECT_LE(elapsed, 300ms);
}

TEST_P(TransportContract, ParticipantReceiveReturnsNothingWithinTheTimeout) {
  auto participant = make_participant(v1::ROLE_FLUID, "main");
  const auto start = Clock::now();
  EXPECT_FALSE(participant.receive(200ms).has_value());
  const auto elapsed = Clock::now() - start;
  EXPECT_GE(elapsed, 190ms);
  EXPECT_LE(elapsed, 300ms);
}

TEST_P(TransportContract, GarbageGivesAMalformedIncomingAndTheChannelKeepsWorking) {
  auto raw = raw_socket(zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "raw:garbage");
  raw.connect(coupler().endpoint().str());

  raw.send(zmq::str_buffer("this is not protobuf \xff\xfe"));
  Incoming incoming = receive_at_coupler();
  EXPECT_EQ(incoming.peer(), "raw:garbage");
  ASSERT_TRUE(incoming.is_malformed());
  EXPECT_EQ(incoming.malformed().kind, Kind::not_an_envelope);

  raw.send(zmq::str_buffer(""));
  EXPECT_EQ(receive_at_coupler().malformed().kind, Kind::not_an_envelope);

  const std::string good = sample_envelopes().front().SerializeAsString();
  raw.send(zmq::buffer(good), zmq::send_flags::sndmore);
  raw.send(zmq::buffer(good));
  incoming = receive_at_coupler();
  ASSERT_TRUE(incoming.is_malformed());
  EXPECT_EQ(incoming.malformed().kind, Kind::wrong_framing) << incoming.malformed().reason;

  auto participant = make_participant(v1::ROLE_FLUID, "main");
  participant.send(sample_envelopes().back());
  incoming = receive_at_coupler();
  ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
  EXPECT_TRUE(same_bytes(incoming.envelope(), sample_envelopes().back()));
}

TEST_P(TransportContract, RandomBytesNeverCrashTheCoupler) {
  auto raw = raw_socket(zmq::socket_type::dealer);
  raw.connect(coupler().endpoint().str());
  std::mt19937 generator(7);
  std::uniform_int_distribution<int> byte(0, 255), length(1, 64);
  constexpr int n_messages = 50;
  for (int i = 0; i < n_messages; ++i) {
    std::string bytes(static_cast<std::size_t>(length(generator)), '\0');
    for (char &c : bytes) {
      c = static_cast<char>(byte(generator));
    }
    raw.send(zmq::buffer(bytes));
  }
  for (int i = 0; i < n_messages; ++i) {
    EXPECT_TRUE(receive_at_coupler().is_malformed());
  }
}

TEST_P(TransportContract, WrongProtocolVersionIsReportedAsSuch) {
  auto participant = make_participant(v1::ROLE_FLUID, "old");
  Envelope envelope = sample_envelopes().front();
  envelope.set_protocol_version(current_protocol_version + 1);
  participant.send(envelope);
  const Incoming incoming = receive_at_coupler();
  EXPECT_EQ(incoming.peer(), "fluid:old");
  ASSERT_TRUE(incoming.is_malformed());
  EXPECT_EQ(incoming.malformed().kind, Kind::wrong_protocol_version);
  EXPECT_NE(incoming.malformed().reason.find("protocol_version 2"), std::string::npos)
      << incoming.malformed().reason;

  envelope.set_protocol_version(0);
  participant.send(envelope);
  EXPECT_EQ(receive_at_coupler().malformed().kind, Kind::wrong_protocol_version);
}

TEST_P(TransportContract, EnvelopeWithoutBodyIsMalformed) {
  auto participant = make_participant(v1::ROLE_FLUID, "main");
  participant.send(make_envelope(v1::ROLE_FLUID, 4));
  EXPECT_EQ(receive_at_coupler().malformed().kind, Kind::missing_body);
}

TEST_P(TransportContract, ParticipantThrowsOnMalformedInputAndKeepsWorking) {
  auto router = raw_socket(zmq::socket_type::router);
  const std::string endpoint = coupler().endpoint().str() + "-raw";
  const bool tcp = GetParam() == Endpoint::Transport::tcp;
  router.bind(tcp ? "tcp://127.0.0.1:0" : endpoint);
  const auto bound = Endpoint::parse(router.get(zmq::sockopt::last_endpoint));
  ParticipantChannel participant(bound, v1::ROLE_FLUID, "main");
  participant.send(sample_envelopes().front());
  std::vector<zmq::message_t> frames;
  ASSERT_TRUE(zmq::recv_multipart(router, std::back_inserter(frames)));
  const std::string peer = frames.front().to_string();

  router.send(zmq::buffer(peer), zmq::send_flags::sndmore);
  router.send(zmq::str_buffer("garbage \xff"));
  EXPECT_THROW(participant.receive(patience), MalformedMessageError);

  Envelope newer = sample_envelopes().back();
  newer.set_protocol_version(current_protocol_version + 1);
  router.send(zmq::buffer(peer), zmq::send_flags::sndmore);
  router.send(zmq::buffer(newer.SerializeAsString()));
  try {
    participant.receive(patience);
    ADD_FAILURE() << "a wrong protocol version was accepted";
  } catch (const MalformedMessageError &error) {
    EXPECT_NE(std::string(error.what()).find("protocol_version 2"), std::string::npos)
        << error.what();
  }

  router.send(zmq::buffer(peer), zmq::send_flags::sndmore);
  router.send(zmq::buffer(sample_envelopes().back().SerializeAsString()));
  EXPECT_TRUE(same_bytes(receive_at(participant), sample_envelopes().back()));
}

TEST_P(TransportContract, SendingToAnUnknownPeerNamesIt) {
  try {
    coupler().send("fluid:nobody", sample_envelopes().back());
    FAIL() << "sending to an unknown peer did not throw";
  } catch (const TransportError &error) {
    EXPECT_NE(std::string(error.what()).find("fluid:nobody"), std::string::npos) << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(AllTransports, TransportContract,
                         ::testing::Values(Endpoint::Transport::tcp, Endpoint::Transport::ipc,
                                           Endpoint::Transport::inproc),
                         transport_name);

} // namespace
} // namespace fsi::proto::test
