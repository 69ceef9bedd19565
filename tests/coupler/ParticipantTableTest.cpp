// Liveness over a real ZeroMQ socket (tcp loopback), in one process: the coupler's
// ParticipantTable against participants built on ParticipantSession. A participant that
// stops (its heartbeat with it) is named within the timeout; a participant that is busy but
// alive keeps its heartbeat going and is waited for; strangers' bytes are answered, not fatal.

#include "coupler/CouplingErrors.hpp"
#include "coupler/ParticipantTable.hpp"
#include "participant/ParticipantSession.hpp"

#include <gtest/gtest.h>

#include <future>
#include <thread>

namespace fsi::coupler {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr double heartbeat_s = 0.05, timeout_s = 0.5;

class LivenessTest : public ::testing::Test {
protected:
  proto::CouplerChannel channel{proto::Endpoint::parse("tcp://127.0.0.1:0")};
  ParticipantTable table{channel, Liveness{50ms, 500ms, 20s}, nullptr};

  participant::SessionSettings settings(const std::string &name) {
    participant::SessionSettings s;
    s.coupler = channel.endpoint();
    s.role = proto::v2::ROLE_STRUCTURE;
    s.name = name;
    s.handshake_timeout = 5s;
    return s;
  }

  /// Plays the coupler's side of the handshake for one participant.
  std::string accept_one() {
    auto &hello = table.next(Clock::now() + 5s, "anyone", "Hello", 0);
    EXPECT_TRUE(hello.envelope().has_hello());
    const std::string id = hello.peer();
    table.add(id);
    proto::Message welcome = proto::make_envelope(proto::v2::ROLE_COUPLER, 0);
    welcome.envelope().mutable_welcome()->set_heartbeat_interval_s(heartbeat_s);
    welcome.envelope().mutable_welcome()->set_timeout_s(timeout_s);
    table.send(id, welcome, 0);
    table.close_admission(); // the handshake is over: liveness is watched from now on
    return id;
  }
};

TEST_F(LivenessTest, AParticipantThatStopsIsNamedWithinTheTimeout) {
  auto session = std::make_unique<participant::ParticipantSession>(settings("doomed"));
  auto joined = std::async(std::launch::async, [&] { session->handshake(); });
  const std::string id = accept_one();
  joined.get();
  session.reset(); // the process "dies": no more heartbeats, no reply
  const auto start = Clock::now();
  try {
    table.next(Clock::now() + 20s, id, "AdvanceReply", 7);
    FAIL() << "no failure reported";
  } catch (const ParticipantFailed &e) {
    const double waited = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_EQ(e.participant, "structure:doomed");
    EXPECT_NE(std::string(e.what()).find("at step 7"), std::string::npos) << e.what();
    EXPECT_GT(waited, 0.8 * timeout_s);
    EXPECT_LT(waited, timeout_s + 0.5) << "liveness must be detected within the timeout (+ polling slack)";
  }
}

TEST_F(LivenessTest, AJoinedParticipantWaitingForTheOthersIsNotDeclaredDead) {
  // During the handshake a participant that has said Hello waits for Welcome without
  // heartbeats (they start with Welcome); the coupler waits for the others meanwhile.
  proto::ParticipantChannel early(channel.endpoint(), proto::v2::ROLE_STRUCTURE, "early");
  proto::Envelope hello = proto::make_envelope(proto::v2::ROLE_STRUCTURE, 0);
  hello.mutable_hello()->set_participant_name("early");
  early.send(hello);
  auto &incoming = table.next(Clock::now() + 5s, "anyone", "Hello", 0);
  table.add(incoming.peer());
  try {
    table.next(Clock::now() + 3 * std::chrono::milliseconds(static_cast<int>(timeout_s * 1000)), "fluid", "Hello", 0);
    FAIL() << "nothing should have arrived";
  } catch (const ParticipantFailed &e) {
    EXPECT_EQ(e.participant, "fluid") << "the waiting participant was declared dead: " << e.what();
  }
}

TEST_F(LivenessTest, ABusyParticipantStaysAliveThroughItsHeartbeat) {
  participant::ParticipantSession session(settings("slow"));
  auto joined = std::async(std::launch::async, [&] { session.handshake(); });
  const std::string id = accept_one();
  joined.get();
  // The participant "solves" for three times the liveness timeout, then replies.
  auto reply = std::async(std::launch::async, [&] {
    std::this_thread::sleep_for(3 * std::chrono::milliseconds(static_cast<int>(timeout_s * 1000)));
    proto::Message done = proto::make_envelope(proto::v2::ROLE_STRUCTURE, 3);
    done.envelope().mutable_advance_reply()->set_time_s(1.0);
    session.send(done);
  });
  auto &incoming = table.next(Clock::now() + 10s, id, "AdvanceReply", 3);
  EXPECT_EQ(incoming.peer(), id);
  EXPECT_TRUE(incoming.envelope().has_advance_reply());
  reply.get();
}

TEST_F(LivenessTest, MissingReplyOfALiveParticipantHitsTheStepDeadline) {
  participant::ParticipantSession session(settings("hung"));
  auto joined = std::async(std::launch::async, [&] { session.handshake(); });
  const std::string id = accept_one();
  joined.get();
  try {
    table.next(Clock::now() + 1s, id, "AdvanceReply", 4);
    FAIL() << "no failure reported";
  } catch (const ParticipantFailed &e) {
    EXPECT_EQ(e.participant, id);
    EXPECT_NE(std::string(e.what()).find("seems stuck"), std::string::npos) << e.what();
  }
}

TEST_F(LivenessTest, StrangersAreAnsweredWithAnErrorAndTheWaitGoesOn) {
  participant::ParticipantSession session(settings("main"));
  auto joined = std::async(std::launch::async, [&] { session.handshake(); });
  const std::string id = accept_one();
  joined.get();
  proto::ParticipantChannel stranger(channel.endpoint(), proto::v2::ROLE_FLUID, "stranger");
  proto::Envelope bogus = proto::make_envelope(proto::v2::ROLE_FLUID, 0);
  bogus.mutable_advance_reply()->set_time_s(1.0);
  stranger.send(bogus);
  auto reply = std::async(std::launch::async, [&] {
    std::this_thread::sleep_for(200ms);
    proto::Message done = proto::make_envelope(proto::v2::ROLE_STRUCTURE, 0);
    done.envelope().mutable_advance_reply();
    session.send(done);
  });
  auto &incoming = table.next(Clock::now() + 5s, id, "AdvanceReply", 0);
  EXPECT_EQ(incoming.peer(), id);
  const auto answer = stranger.receive(2s);
  ASSERT_TRUE(answer.has_value());
  ASSERT_TRUE(answer->envelope().has_error());
  const auto &error = answer->envelope().error();
  EXPECT_NE(error.message().find("send Hello first"), std::string::npos) << error.message();
  reply.get();
}

} // namespace
} // namespace fsi::coupler
