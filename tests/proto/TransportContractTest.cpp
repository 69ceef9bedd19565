// The transport contract: every test runs over tcp (loopback), ipc and inproc.

#include "SampleEnvelopes.hpp"
#include "TransportFixture.hpp"

#include "proto/Message.hpp"
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
  auto participant = make_participant(v2::ROLE_STRUCTURE, "flag");
  auto sent = sample_messages();
  const auto expected = sample_messages();
  for (std::size_t i = 0; i < sent.size(); ++i) {
    SCOPED_TRACE(std::string(body_name(expected[i].envelope())));
    participant.send(sent[i]);
    EXPECT_EQ(sent[i].array_frame_count(), 0U); // the frames went with the message
    const Incoming incoming = receive_at_coupler();
    ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
    EXPECT_EQ(incoming.peer(), "structure:flag");
    EXPECT_TRUE(same_bytes(incoming.message(), expected[i]));
  }
}

TEST_P(TransportContract, EveryBodyTypeReachesTheParticipantWithExactValues) {
  auto participant = make_participant(v2::ROLE_FLUID, "main");
  participant.send(sample_messages().front());
  const std::string peer = receive_at_coupler().peer();
  auto sent = sample_messages();
  const auto expected = sample_messages();
  for (std::size_t i = 0; i < sent.size(); ++i) {
    SCOPED_TRACE(std::string(body_name(expected[i].envelope())));
    coupler().send(peer, sent[i]);
    EXPECT_TRUE(same_bytes(receive_at(participant), expected[i]));
  }
}

TEST_P(TransportContract, SamplesCoverEveryBodyType) {
  std::set<int> sampled;
  for (const Message &message : sample_messages()) {
    sampled.insert(message.envelope().body_case());
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
  auto participant = make_participant(v2::ROLE_STRUCTURE, "flag");

  Message reply = make_envelope(v2::ROLE_STRUCTURE, 3);
  reply.add_points(*reply.envelope().mutable_advance_reply()->mutable_position_m(), positions_m);
  reply.add_points(*reply.envelope().mutable_advance_reply()->mutable_velocity_m_per_s(), velocities_m_per_s);
  participant.send(reply);
  const Incoming incoming = receive_at_coupler();
  ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
  EXPECT_LT(incoming.envelope().ByteSizeLong(), 100U); // the arrays are not in the header
  const auto &received = incoming.envelope().advance_reply();
  EXPECT_TRUE(identical(incoming.message().points(received.position_m(), n_points, "position_m"), positions_m));
  EXPECT_TRUE(identical(incoming.message().points(received.velocity_m_per_s(), n_points, "velocity_m_per_s"),
                        velocities_m_per_s));

  Message advance = make_envelope(v2::ROLE_COUPLER, 3);
  advance.add_points(*advance.envelope().mutable_structure_advance()->mutable_load_density_n_per_measure(),
                     velocities_m_per_s);
  coupler().send(incoming.peer(), advance);
  const Message back = receive_at(participant);
  EXPECT_TRUE(identical(back.points(back.envelope().structure_advance().load_density_n_per_measure(), "load"),
                        velocities_m_per_s));
  Message request = make_envelope(v2::ROLE_COUPLER, 4);
  request.add_points(*request.envelope().mutable_interpolate_request()->mutable_position_m(), positions_m);
  coupler().send(incoming.peer(), request);
  const Message back_request = receive_at(participant);
  EXPECT_TRUE(identical(back_request.points(back_request.envelope().interpolate_request().position_m(), "position_m"),
                        positions_m));
}

Message advance_reply_of(Eigen::Index n_points, unsigned seed, std::uint64_t step, double time_s) {
  Message message = make_envelope(v2::ROLE_STRUCTURE, step);
  auto *body = message.envelope().mutable_advance_reply();
  if (time_s != 0.0) {
    body->set_time_s(time_s);
    body->set_solve_wall_s(0.25);
  }
  message.add_points(*body->mutable_position_m(), random_points(n_points, seed));
  return message;
}

TEST_P(TransportContract, ReceivingIntoAMessageLeavesNothingStale) {
  constexpr Eigen::Index n_points = 1000;
  auto participant = make_participant(v2::ROLE_STRUCTURE, "flag");
  auto step_one = [] { return advance_reply_of(n_points, 3, 1, 0.5); };
  auto step_two = [] { return advance_reply_of(n_points, 4, 0, 0.0); }; // defaults: not on the wire

  Incoming incoming;
  Message sent = step_one();
  participant.send(sent);
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  ASSERT_TRUE(same_bytes(incoming.message(), step_one()));
  sent = step_two();
  participant.send(sent);
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  EXPECT_TRUE(same_bytes(incoming.message(), step_two())); // no stale step, time or wall time

  participant.send(sample_messages().front()); // another body type, without arrays
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  EXPECT_TRUE(same_bytes(incoming.message(), sample_messages().front()));
  EXPECT_EQ(incoming.message().array_frame_count(), 0U);

  Message at_participant;
  std::vector<Message> expected;
  expected.push_back(step_one());
  expected.push_back(step_two());
  expected.push_back(std::move(sample_messages().back()));
  for (const Message &want : expected) {
    Message copy = want.envelope();
    if (want.envelope().has_advance_reply()) {
      const auto &ref = want.envelope().advance_reply().position_m();
      copy.add_points(*copy.envelope().mutable_advance_reply()->mutable_position_m(), want.points(ref, "position_m"));
    }
    coupler().send(incoming.peer(), copy);
    ASSERT_TRUE(participant.receive_into(at_participant, patience));
    EXPECT_TRUE(same_bytes(at_participant, want)) << body_name(want.envelope());
  }
  EXPECT_FALSE(participant.receive_into(at_participant, 10ms));
  EXPECT_TRUE(same_bytes(at_participant, expected.back()));
}

TEST_P(TransportContract, AddingToAFieldAgainReplacesItsFrame) {
  auto participant = make_participant(v2::ROLE_STRUCTURE, "flag");
  Message message = make_envelope(v2::ROLE_STRUCTURE, 1);
  auto *body = message.envelope().mutable_advance_reply();
  message.add_points(*body->mutable_position_m(), random_points(5, 1));
  message.add_points(*body->mutable_velocity_m_per_s(), random_points(7, 2));
  message.add_points(*body->mutable_position_m(), random_points(3, 3));
  EXPECT_EQ(message.array_frame_count(), 2U);
  participant.send(message);
  const Incoming incoming = receive_at_coupler();
  ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
  const auto &received = incoming.envelope().advance_reply();
  EXPECT_TRUE(identical(incoming.message().points(received.position_m(), 3, "position_m"), random_points(3, 3)));
  EXPECT_TRUE(identical(incoming.message().points(received.velocity_m_per_s(), 7, "velocity"), random_points(7, 2)));
  EXPECT_THROW(incoming.message().points(received.position_m(), 4, "position_m"), MalformedMessageError);
}

TEST_P(TransportContract, AHeaderNamingAFrameItDoesNotCarryIsRefusedBeforeItIsSent) {
  auto participant = make_participant(v2::ROLE_STRUCTURE, "flag");
  Message message = make_envelope(v2::ROLE_STRUCTURE, 1);
  message.envelope().mutable_advance_reply()->mutable_position_m()->set_frame(1);
  message.envelope().mutable_advance_reply()->mutable_position_m()->set_n_values(3);
  try {
    participant.send(message);
    FAIL() << "a header naming a missing frame was sent";
  } catch (const TransportError &error) {
    EXPECT_NE(std::string(error.what()).find("AdvanceReply.position_m names array frame 1"), std::string::npos)
        << error.what();
  }
}

TEST_P(TransportContract, ArrayFramesThatDoNotMatchTheHeaderAreWrongFraming) {
  auto raw = raw_socket(zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "raw:frames");
  raw.connect(coupler().endpoint().str());
  Envelope header = make_envelope(v2::ROLE_STRUCTURE, 2);
  header.mutable_advance_reply()->mutable_position_m()->set_frame(1);
  header.mutable_advance_reply()->mutable_position_m()->set_n_values(6);
  const std::string bytes = header.SerializeAsString();
  const std::vector<double> two_points(6, 1.5), one_point(3, 1.5);
  const struct {
    std::vector<std::vector<double>> frames;
    const char *reason;
  } cases[] = {
      {{}, "AdvanceReply.position_m names array frame 1 but the message has 0 array frame(s)"},
      {{one_point}, "AdvanceReply.position_m says 6 doubles but its frame 1 holds 24 bytes"},
      {{two_points, one_point}, "array frame 2 of 2 is named by no field of the advance_reply"},
  };
  for (const auto &c : cases) {
    raw.send(zmq::buffer(bytes), c.frames.empty() ? zmq::send_flags::none : zmq::send_flags::sndmore);
    for (std::size_t i = 0; i < c.frames.size(); ++i) {
      raw.send(zmq::buffer(c.frames[i]), i + 1 < c.frames.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
    }
    const Incoming incoming = receive_at_coupler();
    ASSERT_TRUE(incoming.is_malformed()) << c.reason;
    EXPECT_EQ(incoming.malformed().kind, Kind::wrong_framing);
    EXPECT_NE(incoming.malformed().reason.find(c.reason), std::string::npos) << incoming.malformed().reason;
  }
  raw.send(zmq::buffer(bytes), zmq::send_flags::sndmore);
  raw.send(zmq::buffer(two_points));
  const Incoming good = receive_at_coupler();
  ASSERT_FALSE(good.is_malformed()) << good.malformed().reason;
  EXPECT_EQ(good.message().points(good.envelope().advance_reply().position_m(), 2, "position_m")(1, 2), 1.5);
}

TEST_P(TransportContract, AVersionOnePeerIsToldItsVersion) {
  // What a protocol version 1 structure sent: one frame, its positions as packed doubles in the
  // Envelope (protocol_version 1, role 3, step 5, advance_reply { position_m: 1 point }).
  std::string v1 = {0x08, 0x01, 0x10, 0x03, 0x18, 0x05, static_cast<char>(0x82), 0x01, 26, 0x12, 24};
  const double point[3] = {0.25, -1.0, 3.0};
  v1.append(reinterpret_cast<const char *>(point), sizeof(point));
  auto raw = raw_socket(zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "structure:old");
  raw.connect(coupler().endpoint().str());
  raw.send(zmq::buffer(v1));
  const Incoming incoming = receive_at_coupler();
  ASSERT_TRUE(incoming.is_malformed());
  EXPECT_EQ(incoming.malformed().kind, Kind::wrong_protocol_version) << incoming.malformed().reason;
  EXPECT_NE(incoming.malformed().reason.find("protocol_version 1 but this side speaks version 2"), std::string::npos)
      << incoming.malformed().reason;
}

TEST_P(TransportContract, ReceivingIntoAnIncomingRecoversAfterAMalformedMessage) {
  auto raw = raw_socket(zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "raw:mixed");
  raw.connect(coupler().endpoint().str());
  Incoming incoming;
  raw.send(zmq::str_buffer("\xff garbage"));
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  EXPECT_TRUE(incoming.is_malformed());
  raw.send(zmq::buffer(sample_messages().back().envelope().SerializeAsString()));
  ASSERT_TRUE(coupler().receive_into(incoming, patience));
  ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
  EXPECT_EQ(incoming.peer(), "raw:mixed");
  EXPECT_TRUE(same_bytes(incoming.message(), sample_messages().back()));
}

TEST_P(TransportContract, TwoParticipantsKeepTheirIdentities) {
  auto fluid = make_participant(v2::ROLE_FLUID, "main");
  auto structure = make_participant(v2::ROLE_STRUCTURE, "main");
  Envelope hello = make_envelope(v2::ROLE_FLUID, 0);
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
    Envelope answer = make_envelope(v2::ROLE_COUPLER, 1);
    answer.mutable_shutdown()->set_reason("for " + name);
    coupler().send(peer, answer);
  }
  EXPECT_EQ(receive_at(fluid).envelope().shutdown().reason(), "for fluid side");
  EXPECT_EQ(receive_at(structure).envelope().shutdown().reason(), "for structure side");
}

TEST_P(TransportContract, CouplerReceiveReturnsNothingWithinTheTimeout) {
  const auto start = Clock::now();
  EXPECT_FALSE(coupler().receive(200ms).has_value());
  const auto elapsed = Clock::now() - start;
  EXPECT_GE(elapsed, 190ms);
  EXPECT_LE(elapsed, 300ms);
}

TEST_P(TransportContract, ParticipantReceiveReturnsNothingWithinTheTimeout) {
  auto participant = make_participant(v2::ROLE_FLUID, "main");
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

  const std::string good = sample_messages().front().envelope().SerializeAsString();
  raw.send(zmq::buffer(good), zmq::send_flags::sndmore);
  raw.send(zmq::buffer(good));
  incoming = receive_at_coupler();
  ASSERT_TRUE(incoming.is_malformed());
  EXPECT_EQ(incoming.malformed().kind, Kind::wrong_framing) << incoming.malformed().reason;

  auto participant = make_participant(v2::ROLE_FLUID, "main");
  participant.send(sample_messages().back());
  incoming = receive_at_coupler();
  ASSERT_FALSE(incoming.is_malformed()) << incoming.malformed().reason;
  EXPECT_TRUE(same_bytes(incoming.message(), sample_messages().back()));
}

TEST_P(TransportContract, InvalidUtf8InAStringIsMalformedAndProtobufPrintsNothingOfItsOwn) {
  // Protobuf refuses a string field that is not UTF-8 and logs a line of its own for it; that
  // line goes to spdlog's debug level (EnvelopeCodec), not to stderr, once per bad message.
  auto raw = raw_socket(zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "raw:utf8");
  raw.connect(coupler().endpoint().str());
  Envelope envelope = make_envelope(v2::ROLE_FLUID, 3);
  envelope.mutable_error()->set_message("@@@@");
  std::string bytes = envelope.SerializeAsString();
  bytes.replace(bytes.find("@@@@"), 4, "\xff\xfe\xff\xfe");
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  raw.send(zmq::buffer(bytes));
  Incoming incoming = receive_at_coupler();
  const std::string printed = testing::internal::GetCapturedStderr() + testing::internal::GetCapturedStdout();
  ASSERT_TRUE(incoming.is_malformed());
  EXPECT_EQ(incoming.malformed().kind, Kind::not_an_envelope) << incoming.malformed().reason;
  EXPECT_EQ(printed.find("UTF-8"), std::string::npos) << printed;
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
  auto participant = make_participant(v2::ROLE_FLUID, "old");
  Envelope envelope = sample_messages().front().envelope();
  envelope.set_protocol_version(current_protocol_version + 1);
  participant.send(envelope);
  const Incoming incoming = receive_at_coupler();
  EXPECT_EQ(incoming.peer(), "fluid:old");
  ASSERT_TRUE(incoming.is_malformed());
  EXPECT_EQ(incoming.malformed().kind, Kind::wrong_protocol_version);
  EXPECT_NE(incoming.malformed().reason.find("protocol_version 3"), std::string::npos)
      << incoming.malformed().reason;

  envelope.set_protocol_version(0);
  participant.send(envelope);
  EXPECT_EQ(receive_at_coupler().malformed().kind, Kind::wrong_protocol_version);
}

TEST_P(TransportContract, EnvelopeWithoutBodyIsMalformed) {
  auto participant = make_participant(v2::ROLE_FLUID, "main");
  participant.send(make_envelope(v2::ROLE_FLUID, 4));
  EXPECT_EQ(receive_at_coupler().malformed().kind, Kind::missing_body);
}

TEST_P(TransportContract, ParticipantThrowsOnMalformedInputAndKeepsWorking) {
  auto router = raw_socket(zmq::socket_type::router);
  const std::string endpoint = coupler().endpoint().str() + "-raw";
  const bool tcp = GetParam() == Endpoint::Transport::tcp;
  router.bind(tcp ? "tcp://127.0.0.1:0" : endpoint);
  const auto bound = Endpoint::parse(router.get(zmq::sockopt::last_endpoint));
  ParticipantChannel participant(bound, v2::ROLE_FLUID, "main");
  participant.send(sample_messages().front());
  std::vector<zmq::message_t> frames;
  ASSERT_TRUE(zmq::recv_multipart(router, std::back_inserter(frames)));
  const std::string peer = frames.front().to_string();

  router.send(zmq::buffer(peer), zmq::send_flags::sndmore);
  router.send(zmq::str_buffer("garbage \xff"));
  EXPECT_THROW(participant.receive(patience), MalformedMessageError);

  Envelope newer = sample_messages().back().envelope();
  newer.set_protocol_version(current_protocol_version + 1);
  router.send(zmq::buffer(peer), zmq::send_flags::sndmore);
  router.send(zmq::buffer(newer.SerializeAsString()));
  try {
    participant.receive(patience);
    ADD_FAILURE() << "a wrong protocol version was accepted";
  } catch (const MalformedMessageError &error) {
    EXPECT_NE(std::string(error.what()).find("protocol_version 3"), std::string::npos)
        << error.what();
  }

  router.send(zmq::buffer(peer), zmq::send_flags::sndmore);
  router.send(zmq::buffer(sample_messages().back().envelope().SerializeAsString()));
  EXPECT_TRUE(same_bytes(receive_at(participant), sample_messages().back()));
}

TEST_P(TransportContract, SendingToAnUnknownPeerNamesIt) {
  try {
    coupler().send("fluid:nobody", sample_messages().back());
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
