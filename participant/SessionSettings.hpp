#pragma once
// Where a participant finds the coupler and how it waits for it (ParticipantSession).

#include "proto/ChannelOptions.hpp"
#include "proto/Endpoint.hpp"
#include "proto/Protocol.hpp"

#include <atomic>
#include <chrono>
#include <string>

namespace fsi::participant {

struct SessionSettings {
  proto::Endpoint coupler = proto::Endpoint::parse("tcp://127.0.0.1:5560");
  proto::Role role = proto::v2::ROLE_STRUCTURE;
  std::string name = "main";
  std::string case_fingerprint;
  proto::ChannelOptions options;
  std::chrono::milliseconds handshake_timeout{120000};
  /// Set by the process's signal handler; checked while waiting. Before Welcome a signal stops
  /// the participant at once; after it, the participant tells the coupler (Heartbeat.stop_signal)
  /// and keeps answering, so that the run ends at a step boundary with a checkpoint, unless the
  /// coupler has not ended it `stop_grace` after the signal.
  const std::atomic<int> *stop_signal = nullptr;
  std::chrono::milliseconds stop_grace{60000};
};

} // namespace fsi::participant
