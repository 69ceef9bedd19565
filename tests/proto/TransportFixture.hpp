#pragma once
// The transport contract runs over every kind of endpoint: each test gets a coupler bound to a
// fresh endpoint of its kind (tcp loopback on a free port, ipc in a temporary folder, inproc
// with a unique name) and makes participants that connect to it.

#include "proto/CouplerChannel.hpp"
#include "proto/ParticipantChannel.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>

namespace fsi::proto::test {

class TransportFixture : public ::testing::TestWithParam<Endpoint::Transport> {
protected:
  /// Generous: only a broken transport waits this long.
  static constexpr std::chrono::milliseconds patience{5000};

  void SetUp() override;
  void TearDown() override;

  CouplerChannel &coupler() { return *coupler_; }
  ParticipantChannel make_participant(Role role, const std::string &name);

  /// The next message at the coupler; fails the test if none arrives in time.
  Incoming receive_at_coupler();
  /// The next message at a participant; fails the test if none arrives in time.
  Message receive_at(ParticipantChannel &participant);

private:
  Endpoint fresh_endpoint();

  std::filesystem::path temp_dir_;
  std::unique_ptr<CouplerChannel> coupler_;
};

/// "tcp", "ipc", "inproc": names the instantiations of the contract suite.
std::string transport_name(const ::testing::TestParamInfo<Endpoint::Transport> &info);

} // namespace fsi::proto::test
