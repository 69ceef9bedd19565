#include "ParticipantTable.hpp"

#include "CouplingErrors.hpp"
#include "proto/TransportError.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace fsi::coupler {

namespace {
using std::chrono::milliseconds;

double seconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }

bool is_power_of_ten(long n) {
  while (n >= 10 && n % 10 == 0)
    n /= 10;
  return n == 1;
}

bool looks_like_participant(const std::string &peer) {
  return peer.rfind("fluid:", 0) == 0 || peer.rfind("structure:", 0) == 0;
}
} // namespace

ParticipantTable::ParticipantTable(proto::CouplerChannel &channel, Liveness liveness,
                                   const std::atomic<int> *stop_signal)
    : channel_(channel), liveness_(liveness), stop_signal_(stop_signal) {}

void ParticipantTable::add(const std::string &routing_id) {
  ids_.push_back(routing_id);
  last_seen_[routing_id] = Clock::now();
}

void ParticipantTable::send(const std::string &routing_id, proto::Message &message, std::uint64_t step) {
  proto::Envelope &envelope = message.envelope();
  envelope.set_protocol_version(proto::current_protocol_version);
  envelope.set_sender_role(proto::v2::ROLE_COUPLER);
  envelope.set_step(step);
  try {
    channel_.send(routing_id, message);
  } catch (const proto::TransportError &e) {
    throw ParticipantFailed(routing_id, "cannot send " + std::string(proto::body_name(envelope)) + " to participant " +
                                            routing_id + " at step " + std::to_string(step) + ": " + e.what());
  }
}

proto::Incoming &ParticipantTable::next(Clock::time_point deadline, const std::string &waited_peer,
                                        const std::string &waiting_for, std::uint64_t step) {
  while (true) {
    if (const int signal = stop_requested()) {
      const auto now = Clock::now();
      if (!clean_stop_grace_ || (stop_seen_ && now - *stop_seen_ > *clean_stop_grace_))
        throw StopRequested(signal);
      if (!stop_seen_) {
        stop_seen_ = now;
        spdlog::warn("signal {} at {}: the run ends at the end of this step (waiting at most {} s for it)", signal,
                     stop_requested_by(), clean_stop_grace_->count() / 1000);
      }
    }
    send_heartbeats_if_due(step);
    if (!admission_open_) // heartbeats start with Welcome, sent when everyone has joined
      check_liveness(step);
    const auto now = Clock::now();
    if (now >= deadline)
      throw ParticipantFailed(waited_peer, "no " + waiting_for + " from " + waited_peer + " at step " +
                                               std::to_string(step) + " within the time limit (coupling." +
                                               (knows(waited_peer) ? "step_timeout_s" : "handshake_timeout_s") +
                                               "); it is alive (heartbeats) but seems stuck");
    const auto slice = std::min({std::chrono::duration_cast<milliseconds>(deadline - now),
                                 liveness_.heartbeat_interval / 2, milliseconds(100)});
    const auto before = Clock::now();
    const bool received = channel_.receive_into(incoming_, std::max(slice, milliseconds(1)));
    wait_s_ += seconds(Clock::now() - before);
    if (received && !absorb(incoming_, step))
      return incoming_;
  }
}

bool ParticipantTable::absorb(const proto::Incoming &incoming, std::uint64_t step) {
  const std::string &peer = incoming.peer();
  if (incoming.is_malformed()) {
    const auto &bad = incoming.malformed();
    if (bad.kind == proto::MalformedMessage::Kind::wrong_protocol_version && looks_like_participant(peer) &&
        admission_open_ && !knows(proto::participant_of(peer))) {
      const std::string message = "refused participant " + proto::printable(peer) + ": " + bad.reason +
                                  " (this coupler speaks protocol version " +
                                  std::to_string(proto::current_protocol_version) +
                                  "); build all processes of a run from the same version";
      answer_error(peer, message, step);
      throw HandshakeRefused(message);
    }
    if (++ignored_ <= ignored_logged_in_full)
      spdlog::warn("ignored a malformed message from {}: {}", proto::printable(peer), bad.reason);
    answer_error(peer, "the coupler could not read your message (" + bad.reason + ")", step);
    return true;
  }
  const auto &envelope = incoming.envelope();
  const std::string owner = proto::participant_of(peer);
  const bool known = knows(owner);
  if (known)
    last_seen_[owner] = Clock::now();
  if (envelope.has_heartbeat()) {
    if (known && envelope.heartbeat().stop_signal() != 0 && participant_stop_signal_ == 0) {
      participant_stop_signal_ = envelope.heartbeat().stop_signal();
      if (stop_by_.empty())
        stop_by_ = "participant " + owner;
    }
    return true;
  }
  if (known && envelope.has_error())
    throw ParticipantFailed(owner, "participant " + owner + " reported an error at step " +
                                       std::to_string(envelope.step()) + ": " + envelope.error().message());
  if (known || (envelope.has_hello() && admission_open_))
    return false;
  const bool late = envelope.has_hello();
  if (++ignored_ <= ignored_logged_in_full)
    spdlog::warn("ignored {} from {}, which {}", proto::body_name(envelope), proto::printable(peer),
                 late ? "came after the run started (participants join only at the start)" : "has not joined the run");
  else if (is_power_of_ten(ignored_))
    spdlog::warn("ignored {} messages from processes outside the run so far", ignored_);
  answer_error(peer, late ? "the run has started: participants join only at the start" : "you have not joined this run: send Hello first", step);
  return true;
}

void ParticipantTable::send_heartbeats_if_due(std::uint64_t step) {
  const auto now = Clock::now();
  if (now - last_heartbeat_sent_ < liveness_.heartbeat_interval)
    return;
  last_heartbeat_sent_ = now;
  for (const auto &id : ids_) {
    proto::Envelope beat = proto::make_envelope(proto::v2::ROLE_COUPLER, step);
    beat.mutable_heartbeat()->set_wall_time_s(seconds(now.time_since_epoch()));
    try {
      channel_.send(id, beat);
    } catch (const proto::TransportError &) {
      // Not reading or gone: check_liveness() names it once its timeout has passed.
    }
  }
}

void ParticipantTable::check_liveness(std::uint64_t step) const {
  const auto now = Clock::now();
  for (const auto &[id, seen] : last_seen_)
    if (now - seen > liveness_.timeout)
      throw ParticipantFailed(id, "participant " + id + " has sent nothing, not even a heartbeat, for " +
                                      std::to_string(seconds(now - seen)).substr(0, 5) + " s at step " +
                                      std::to_string(step) +
                                      " (coupling.timeout_s): its process died or its machine is unreachable");
}

void ParticipantTable::answer_error(const std::string &peer, const std::string &message, std::uint64_t step) noexcept {
  try {
    proto::Envelope error = proto::make_envelope(proto::v2::ROLE_COUPLER, step);
    error.mutable_error()->set_message(message);
    error.mutable_error()->set_fatal(false);
    channel_.try_send(peer, error); // never waits: a peer that does not read gets nothing
  } catch (...) {
    // The peer is gone; nothing to answer.
  }
}

void ParticipantTable::answer_unexpected(const proto::Incoming &incoming, std::uint64_t step,
                                         const std::string &expectation) noexcept {
  try {
    const auto &envelope = incoming.envelope();
    answer_error(incoming.peer(),
                 "unexpected " + std::string(proto::body_name(envelope)) + " for step " +
                     std::to_string(envelope.step()) + expectation,
                 step);
  } catch (...) {
    // Nothing to answer with (out of memory): the wait goes on.
  }
}

void ParticipantTable::allow_clean_stop(std::chrono::milliseconds grace) { clean_stop_grace_ = grace; }

int ParticipantTable::stop_requested() const {
  if (stop_signal_ && *stop_signal_ != 0) {
    if (stop_by_.empty())
      stop_by_ = "the coupler";
    return *stop_signal_;
  }
  return participant_stop_signal_;
}

void ParticipantTable::shutdown_all(const std::string &reason, bool success, std::uint64_t step,
                                    bool interrupted) noexcept {
  for (const auto &id : ids_) {
    try {
      proto::Envelope shutdown = proto::make_envelope(proto::v2::ROLE_COUPLER, step);
      shutdown.mutable_shutdown()->set_reason(reason);
      shutdown.mutable_shutdown()->set_success(success);
      shutdown.mutable_shutdown()->set_interrupted(interrupted);
      channel_.send(id, shutdown);
    } catch (...) {
      // A dead participant cannot be told.
    }
  }
}

double ParticipantTable::take_wait_s() {
  const double w = wait_s_;
  wait_s_ = 0.0;
  return w;
}

} // namespace fsi::coupler
