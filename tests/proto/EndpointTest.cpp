// Endpoint parsing, the loopback rule, and the channel checks that use them.

#include "proto/Endpoint.hpp"
#include "proto/CouplerChannel.hpp"
#include "proto/ParticipantChannel.hpp"
#include "proto/TransportError.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fsi::proto::test {
namespace {

/// The message of the TransportError thrown by f, or "" if none was thrown.
template <typename F> std::string error_of(F &&f) {
  try {
    f();
  } catch (const TransportError &error) {
    return error.what();
  }
  return "";
}

bool contains(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}

TEST(Endpoint, ParsesTcpWithIpv4HostNameAndIpv6) {
  const auto ipv4 = Endpoint::parse("tcp://127.0.0.1:5555");
  EXPECT_EQ(ipv4.transport(), Endpoint::Transport::tcp);
  EXPECT_EQ(ipv4.host(), "127.0.0.1");
  EXPECT_EQ(ipv4.port(), 5555);
  EXPECT_EQ(ipv4.str(), "tcp://127.0.0.1:5555");

  const auto ipv6 = Endpoint::parse("tcp://[::1]:80");
  EXPECT_TRUE(ipv6.is_ipv6());
  EXPECT_EQ(ipv6.host(), "::1");
  EXPECT_EQ(ipv6.str(), "tcp://[::1]:80");

  EXPECT_EQ(Endpoint::parse("tcp://coupler-node.cluster:65535").port(), 65535);
  EXPECT_EQ(Endpoint::parse("tcp://localhost:*").port(), 0);
  EXPECT_EQ(Endpoint::parse("tcp://*:0").host(), "*");
}

TEST(Endpoint, ParsesIpcAndInproc) {
  const auto ipc = Endpoint::parse("ipc:///tmp/fsi/coupler.sock");
  EXPECT_EQ(ipc.transport(), Endpoint::Transport::ipc);
  EXPECT_EQ(ipc.address(), "/tmp/fsi/coupler.sock");
  EXPECT_EQ(ipc.str(), "ipc:///tmp/fsi/coupler.sock");

  const auto inproc = Endpoint::parse("inproc://coupler");
  EXPECT_EQ(inproc.transport(), Endpoint::Transport::inproc);
  EXPECT_EQ(inproc.address(), "coupler");
}

TEST(Endpoint, LoopbackMeansOnlyThisMachineCanConnect) {
  for (const char *text :
       {"tcp://127.0.0.1:1", "tcp://127.8.9.10:1", "tcp://localhost:1", "tcp://LocalHost:1",
        "tcp://[::1]:1", "tcp://[::ffff:127.0.0.1]:1", "ipc:///tmp/x", "inproc://x"}) {
    EXPECT_TRUE(Endpoint::parse(text).is_loopback()) << text;
  }
  for (const char *text :
       {"tcp://0.0.0.0:1", "tcp://*:1", "tcp://10.0.0.1:1", "tcp://128.0.0.1:1", "tcp://[::]:1",
        "tcp://[fe80::1]:1", "tcp://example.org:1", "tcp://localhost.example.org:1"}) {
    EXPECT_FALSE(Endpoint::parse(text).is_loopback()) << text;
  }
}

TEST(Endpoint, ErrorsNameTheEndpointAndTheAllowedForms) {
  const std::pair<const char *, const char *> cases[] = {
      {"", "does not start with"},
      {"udp://127.0.0.1:5", "does not start with"},
      {"tcp://127.0.0.1", "no :PORT"},
      {"tcp://:5555", "host is empty"},
      {"tcp://127.0.0.1:", "port"},
      {"tcp://127.0.0.1:65536", "0 to 65535"},
      {"tcp://127.0.0.1:55x", "0 to 65535"},
      {"tcp://127.0.0.1:5555/", "0 to 65535"},
      {"tcp://::1:5555", "in brackets"},
      {"tcp://[::1:5555", "no closing ']'"},
      {"tcp://[nonsense]:5555", "not an IPv6 address"},
      {"tcp://[::1]5555", "no :PORT"},
      {"tcp://eth0;192.168.1.1:5555", "neither an address nor a host name"},
      {"ipc://", "path is empty"},
      {"inproc://", "name is empty"},
  };
  for (const auto &[text, why] : cases) {
    const std::string message = error_of([&] { Endpoint::parse(text); });
    EXPECT_TRUE(contains(message, std::string("'") + text + "'")) << text << ": " << message;
    EXPECT_TRUE(contains(message, why)) << text << ": " << message;
    EXPECT_TRUE(contains(message, "tcp://HOST:PORT")) << text << ": " << message;
  }
  const std::string long_path = "ipc:///" + std::string(120, 'x');
  EXPECT_TRUE(contains(error_of([&] { Endpoint::parse(long_path); }), "at most 107"));
}

TEST(Endpoint, NonLoopbackBindIsRefusedWithoutCurveOrInsecureRemote) {
  for (const char *text : {"tcp://0.0.0.0:0", "tcp://*:0", "tcp://192.0.2.1:0"}) {
    const std::string message = error_of([&] { CouplerChannel channel(Endpoint::parse(text)); });
    EXPECT_TRUE(contains(message, text)) << message;
    EXPECT_TRUE(contains(message, "insecure_remote") && contains(message, "security: curve")) << message;
    EXPECT_TRUE(contains(message, "127.0.0.1")) << message;
  }
}

TEST(Endpoint, NonLoopbackBindWorksWhenAllowed) {
  ChannelOptions options;
  options.insecure_remote = true;
  const CouplerChannel channel(Endpoint::parse("tcp://*:0"), options);
  EXPECT_NE(channel.endpoint().port(), 0);
}

TEST(Endpoint, LoopbackNamesBind) {
  for (const char *text : {"tcp://localhost:0", "tcp://[::1]:0", "tcp://127.0.0.1:*"}) {
    const CouplerChannel channel(Endpoint::parse(text));
    EXPECT_NE(channel.endpoint().port(), 0) << text;
    EXPECT_TRUE(channel.endpoint().is_loopback()) << channel.endpoint().str();
  }
}

TEST(Endpoint, BindingAHostNameSaysToUseTheAddress) {
  ChannelOptions options;
  options.insecure_remote = true;
  const std::string message = error_of(
      [&] { CouplerChannel channel(Endpoint::parse("tcp://coupler.invalid:0"), options); });
  EXPECT_TRUE(contains(message, "tcp://coupler.invalid:0")) << message;
  EXPECT_TRUE(contains(message, "not host names")) << message;
}

TEST(Endpoint, ATakenPortIsNamedWithARemedy) {
  const CouplerChannel first(Endpoint::parse("tcp://127.0.0.1:0"));
  const std::string taken = first.endpoint().str();
  const std::string message = error_of([&] { CouplerChannel second(Endpoint::parse(taken)); });
  EXPECT_TRUE(contains(message, taken)) << message;
  EXPECT_TRUE(contains(message, "pick another port")) << message;
}

TEST(Endpoint, ParticipantsCannotConnectToBindOnlyEndpoints) {
  EXPECT_TRUE(contains(error_of([] {
                         ParticipantChannel p(Endpoint::parse("tcp://127.0.0.1:0"), v2::ROLE_FLUID,
                                              "main");
                       }),
                       "port 0"));
  EXPECT_TRUE(contains(error_of([] {
                         ParticipantChannel p(Endpoint::parse("tcp://*:5555"), v2::ROLE_FLUID,
                                              "main");
                       }),
                       "host *"));
}

TEST(Endpoint, ParticipantsNeedAParticipantRoleAndAName) {
  const auto coupler = Endpoint::parse("inproc://nowhere");
  EXPECT_TRUE(contains(error_of([&] { ParticipantChannel p(coupler, v2::ROLE_COUPLER, "main"); }),
                       "fluid or"));
  EXPECT_TRUE(contains(error_of([&] { ParticipantChannel p(coupler, v2::ROLE_FLUID, ""); }),
                       "1 to 200 characters"));
  EXPECT_EQ(ParticipantChannel(coupler, v2::ROLE_FLUID, "main").routing_id(), "fluid:main");
}

TEST(Endpoint, OptionsOutOfRangeAreNamed) {
  ChannelOptions options;
  options.queue_limit_messages = 0;
  EXPECT_TRUE(
      contains(error_of([&] { CouplerChannel c(Endpoint::parse("inproc://options"), options); }),
               "queue_limit_messages"));
}

} // namespace
} // namespace fsi::proto::test
