#pragma once
// A participant's side of a coupled run, above the transport: the handshake (Hello/Welcome),
// a background heartbeat, waiting for the coupler's next request with a liveness timeout,
// and error reports. Fluid and structure participants (ours, or a user's own solver written
// against docs/protocol.md) follow the same loop:
//
//   ParticipantSession session(settings);
//   session.handshake(structures);
//   while (true) {
//     Message &request = session.next_request();    // throws CouplerLost, RunStopped
//     if (request.envelope().has_shutdown()) break; // end of run (success)
//     ... compute, then session.send(reply) ...
//   }

#include "ChannelOptions.hpp"
#include "Endpoint.hpp"
#include "Message.hpp"
#include "ParticipantChannel.hpp"
#include "Protocol.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fsi::proto {

/// The coupler refused the handshake, never answered it, or went silent during the run.
class CouplerLost : public std::runtime_error {
public:
  explicit CouplerLost(const std::string &message) : std::runtime_error(message) {}
};

/// The coupler stopped the run because of someone else (Shutdown with success = false, or an
/// ErrorReport); what() is its reason.
class RunStopped : public std::runtime_error {
public:
  explicit RunStopped(const std::string &message) : std::runtime_error(message) {}
};

/// A stop signal (SIGINT, SIGTERM) ended the run: the coupler ended it at a step boundary
/// (Shutdown.interrupted; `signal` 0 when this process received none), or this process
/// received one before the run started or while the coupler did not end the run within
/// SessionSettings::stop_grace.
class Interrupted : public std::runtime_error {
public:
  explicit Interrupted(int signal) : std::runtime_error("interrupted by signal " + std::to_string(signal)), signal(signal) {}
  Interrupted(int signal, const std::string &message, bool by_coupler)
      : std::runtime_error(message), signal(signal), by_coupler(by_coupler) {}
  int signal;
  /// The coupler ended the run (Shutdown.interrupted): it needs no ErrorReport.
  bool by_coupler = false;
};

struct SessionSettings {
  Endpoint coupler = Endpoint::parse("tcp://127.0.0.1:5560");
  Role role = v2::ROLE_STRUCTURE;
  std::string name = "main";
  std::string case_fingerprint;
  ChannelOptions options;
  std::chrono::milliseconds handshake_timeout{120000};
  /// Set by the process's signal handler; checked while waiting. Before Welcome a signal stops
  /// the participant at once; after it, the participant tells the coupler (Heartbeat.stop_signal)
  /// and keeps answering, so that the run ends at a step boundary with a checkpoint, unless the
  /// coupler has not ended it `stop_grace` after the signal.
  const std::atomic<int> *stop_signal = nullptr;
  std::chrono::milliseconds stop_grace{60000};
};

class ParticipantSession {
public:
  explicit ParticipantSession(SessionSettings settings);
  ~ParticipantSession();
  ParticipantSession(const ParticipantSession &) = delete;
  ParticipantSession &operator=(const ParticipantSession &) = delete;

  /// Sends Hello (with the structures, for the structure participant) and waits for Welcome.
  /// Throws CouplerLost when the coupler refuses (version, case) or does not answer in time.
  /// Starts the heartbeat.
  const v2::Welcome &handshake(const std::vector<v2::StructureTopology> &structures = {});
  const v2::Welcome &welcome() const { return welcome_; }

  /// The next request of the coupler (heartbeats are absorbed). A Shutdown with success is
  /// returned (the end of the run); a failed Shutdown or an ErrorReport throws RunStopped.
  /// Throws CouplerLost after welcome.timeout_s without any message from the coupler,
  /// Interrupted when the coupler ends the run because of a stop signal (Shutdown.interrupted),
  /// or on a stop signal of this process before Welcome or stop_grace after it.
  Message &next_request();

  /// Sends a reply (stamped with this participant's role); its array frames go with it.
  void send(Message &message);
  /// Tells the coupler this participant failed at `step` (best effort: never throws).
  void report_error(const std::string &message, std::uint64_t step) noexcept;

  Role role() const { return settings_.role; }
  const std::string &routing_id() const { return channel_.routing_id(); }

private:
  Message &wait_for_message(std::chrono::milliseconds timeout, const char *waiting_for);
  void start_heartbeat(std::chrono::milliseconds interval);
  void stop_heartbeat();
  void heartbeat_loop(std::chrono::milliseconds interval);
  /// A stop signal of this process while waiting (see SessionSettings::stop_signal).
  void on_stop_signal(int signal);

  SessionSettings settings_;
  ParticipantChannel channel_;
  v2::Welcome welcome_;
  Message incoming_;
  std::thread heartbeat_;
  std::mutex heartbeat_mutex_;
  std::condition_variable heartbeat_wakeup_;
  bool heartbeat_stop_ = false;
  /// The stop signal this process received, reported with every heartbeat from then on.
  std::atomic<int> reported_signal_{0};
  std::chrono::steady_clock::time_point signal_seen_{};
};

} // namespace fsi::proto
