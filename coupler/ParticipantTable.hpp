#pragma once
// The coupler's view of its participants over one CouplerChannel: who has joined, when each
// was last heard from, and the housekeeping of every wait: heartbeats in both directions,
// liveness timeouts, error replies to malformed or unexpected messages. The coupling run
// only ever sees the messages it asked for.

#include "proto/CouplerChannel.hpp"

#include <atomic>
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fsi::coupler {

struct Liveness {
  std::chrono::milliseconds heartbeat_interval{500};
  std::chrono::milliseconds timeout{10000};      ///< silence after which a participant is dead
  std::chrono::milliseconds step_timeout{600000}; ///< longest wait for one reply
};

class ParticipantTable {
public:
  using Clock = std::chrono::steady_clock;

  ParticipantTable(proto::CouplerChannel &channel, Liveness liveness, const std::atomic<int> *stop_signal);

  /// A participant whose handshake was accepted: from now on it is heartbeated and watched.
  void add(const std::string &routing_id);
  const std::vector<std::string> &participants() const { return ids_; }
  /// The handshake is over: from now on a stranger's message of another protocol version is
  /// answered and ignored like any other malformed message, instead of refusing the run, and
  /// the participants' liveness is watched (their heartbeats start with Welcome).
  void close_admission() { admission_open_ = false; }
  bool knows(const std::string &routing_id) const { return last_seen_.count(routing_id) != 0; }

  /// Sends to a participant (stamped with the coupler's role and the step; its array frames go
  /// with it). A participant that is gone or does not read throws ParticipantFailed.
  void send(const std::string &routing_id, proto::Message &message, std::uint64_t step);

  /// The next message the run has to act on: any body but a heartbeat from a known
  /// participant, or a Hello from anyone. Answers malformed bytes and messages from strangers
  /// with an ErrorReport and keeps waiting. Throws ParticipantFailed for an ErrorReport, a
  /// participant silent for the liveness timeout, or `deadline` passing (naming
  /// `waiting_for`); HandshakeRefused for a would-be participant of another protocol version
  /// while admission is open;
  /// StopRequested on a stop signal, at once before allow_clean_stop(), else once the stop is
  /// older than its grace.
  proto::Incoming &next(Clock::time_point deadline, const std::string &waited_peer, const std::string &waiting_for,
                        std::uint64_t step);

  /// Answers `peer` with an ErrorReport (best effort).
  void answer_error(const std::string &peer, const std::string &message, std::uint64_t step) noexcept;
  /// Answers a message that is not the one awaited: "unexpected <body> for step <its step>"
  /// followed by `expectation` (what the coupler waits for), as an ErrorReport of `step`.
  void answer_unexpected(const proto::Incoming &incoming, std::uint64_t step, const std::string &expectation) noexcept;
  /// Sends Shutdown to every participant that joined (best effort: never throws);
  /// `interrupted`: ended by a stop signal, at a step boundary (Shutdown.interrupted).
  void shutdown_all(const std::string &reason, bool success, std::uint64_t step, bool interrupted = false) noexcept;

  /// From now on (the time loop) a stop signal, of the coupler or reported by a participant
  /// (Heartbeat.stop_signal), lets the waits go on for `grace`, so that the run finishes its
  /// step and checkpoints it; past that, next() throws StopRequested.
  void allow_clean_stop(std::chrono::milliseconds grace);
  /// The stop signal received by the coupler or reported by a participant (0: none).
  int stop_requested() const;
  /// Who asked to stop: "the coupler" or a participant's name.
  const std::string &stop_requested_by() const { return stop_by_; }

  /// Wall time the coupler spent blocked in next() since the last call (waiting for peers).
  double take_wait_s();

private:
  void send_heartbeats_if_due(std::uint64_t step);
  void check_liveness(std::uint64_t step) const;
  bool absorb(const proto::Incoming &incoming, std::uint64_t step);

  proto::CouplerChannel &channel_;
  Liveness liveness_;
  const std::atomic<int> *stop_signal_;
  std::vector<std::string> ids_;
  std::map<std::string, Clock::time_point> last_seen_;
  Clock::time_point last_heartbeat_sent_{};
  proto::Incoming incoming_;
  double wait_s_ = 0.0;
  bool admission_open_ = true;
  std::optional<std::chrono::milliseconds> clean_stop_grace_;
  std::optional<Clock::time_point> stop_seen_;
  int participant_stop_signal_ = 0;
  mutable std::string stop_by_;
  /// Messages ignored (malformed, or from processes outside the run): logged in full up to
  /// ignored_logged_in_full, then counted, so that a flood cannot flood the log too.
  long ignored_ = 0;
  static constexpr long ignored_logged_in_full = 10;
};

} // namespace fsi::coupler
