#pragma once
// A participant's side of a coupled run, above the transport: the handshake (Hello/Welcome),
// a background heartbeat, waiting for the coupler's next request with a liveness timeout,
// and error reports. Participant runs the one loop over it that both our participants use:
//
//   ParticipantSession session(settings);
//   session.handshake(structures);
//   while (true) {
//     Message &request = session.next_request();    // throws CouplerLost, RunStopped
//     if (request.envelope().has_shutdown()) break; // end of run (success)
//     ... compute, then session.send(reply) ...
//   }

#include "SessionErrors.hpp"
#include "SessionSettings.hpp"
#include "proto/Message.hpp"
#include "proto/ParticipantChannel.hpp"
#include "proto/Protocol.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace fsi::participant {

class ParticipantSession {
public:
  explicit ParticipantSession(SessionSettings settings);
  ~ParticipantSession();
  ParticipantSession(const ParticipantSession &) = delete;
  ParticipantSession &operator=(const ParticipantSession &) = delete;

  /// Sends Hello (with the structures, for the structure participant) and waits for Welcome.
  /// Throws CouplerLost when the coupler refuses (version, case) or does not answer in time.
  /// Starts the heartbeat.
  const proto::v2::Welcome &handshake(const std::vector<proto::v2::StructureTopology> &structures = {});
  const proto::v2::Welcome &welcome() const { return welcome_; }

  /// The next request of the coupler (heartbeats are absorbed). A Shutdown with success is
  /// returned (the end of the run); a failed Shutdown or an ErrorReport throws RunStopped.
  /// Throws CouplerLost after welcome.timeout_s without any message from the coupler,
  /// Interrupted when the coupler ends the run because of a stop signal (Shutdown.interrupted),
  /// or on a stop signal of this process before Welcome or stop_grace after it.
  proto::Message &next_request();

  /// Sends a reply (stamped with this participant's role); its array frames go with it.
  void send(proto::Message &message);
  /// Tells the coupler this participant failed at `step` (best effort: never throws).
  void report_error(const std::string &message, std::uint64_t step) noexcept;

  proto::Role role() const { return settings_.role; }
  const std::string &routing_id() const { return channel_.routing_id(); }

private:
  proto::Message &wait_for_message(std::chrono::milliseconds timeout, const char *waiting_for);
  void start_heartbeat(std::chrono::milliseconds interval);
  void stop_heartbeat();
  void heartbeat_loop(std::chrono::milliseconds interval);
  /// A stop signal of this process while waiting (see SessionSettings::stop_signal).
  void on_stop_signal(int signal);

  SessionSettings settings_;
  proto::ParticipantChannel channel_;
  proto::v2::Welcome welcome_;
  proto::Message incoming_;
  std::thread heartbeat_;
  std::mutex heartbeat_mutex_;
  std::condition_variable heartbeat_wakeup_;
  bool heartbeat_stop_ = false;
  /// The stop signal this process received, reported with every heartbeat from then on.
  std::atomic<int> reported_signal_{0};
  std::chrono::steady_clock::time_point signal_seen_{};
};

} // namespace fsi::participant
