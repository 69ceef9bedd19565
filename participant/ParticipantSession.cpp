#include "ParticipantSession.hpp"

#include "common/Durations.hpp"
#include "proto/TransportError.hpp"

#include <spdlog/spdlog.h>

namespace fsi::participant {

using proto::Envelope;
using proto::Message;

using common::to_ms;
using std::chrono::milliseconds;

ParticipantSession::ParticipantSession(SessionSettings settings)
    : settings_(std::move(settings)), channel_(settings_.coupler, settings_.role, settings_.name, settings_.options) {}

ParticipantSession::~ParticipantSession() { stop_heartbeat(); }

const proto::v2::Welcome &ParticipantSession::handshake(const std::vector<proto::v2::StructureTopology> &structures) {
  Envelope hello = proto::make_envelope(settings_.role, 0);
  auto *body = hello.mutable_hello();
  body->set_role(settings_.role);
  body->set_participant_name(settings_.name);
  body->set_protocol_version(proto::current_protocol_version);
  body->set_case_fingerprint(settings_.case_fingerprint);
  for (const auto &s : structures)
    *body->add_structures() = s;
  channel_.send(hello);
  // The coupler heartbeats those who joined while it waits for the others: skip those.
  const auto deadline = std::chrono::steady_clock::now() + settings_.handshake_timeout;
  Envelope *welcome = nullptr;
  while (!welcome) {
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - std::chrono::steady_clock::now());
    Envelope &message = wait_for_message(std::max(left, milliseconds(1)), "Welcome").envelope();
    if (!message.has_heartbeat())
      welcome = &message;
  }
  Envelope &reply = *welcome;
  if (!reply.has_welcome())
    throw CouplerLost("participant " + routing_id() + ": the coupler at " + settings_.coupler.str() +
                      " answered the handshake with " + std::string(proto::body_name(reply)) + " instead of Welcome");
  welcome_ = reply.welcome();
  start_heartbeat(to_ms(welcome_.heartbeat_interval_s()));
  return welcome_;
}

Message &ParticipantSession::wait_for_message(milliseconds timeout, const char *waiting_for) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    if (settings_.stop_signal && *settings_.stop_signal != 0)
      on_stop_signal(*settings_.stop_signal);
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
      throw CouplerLost("participant " + routing_id() + ": no message from the coupler at " + settings_.coupler.str() +
                        " for " + std::to_string(timeout.count() / 1000.0) + " s while waiting for " + waiting_for +
                        "; is the coupler running and reachable?");
    // Short slices so that a stop signal is seen promptly.
    if (!channel_.receive_into(incoming_, std::min(left, milliseconds(200))))
      continue;
    const Envelope &envelope = incoming_.envelope();
    if (envelope.has_heartbeat())
      return incoming_; // the caller decides whether it counts
    if (envelope.has_error())
      throw RunStopped(envelope.error().message());
    if (envelope.has_shutdown() && !envelope.shutdown().success()) {
      if (envelope.shutdown().interrupted())
        throw Interrupted(reported_signal_, envelope.shutdown().reason(), true);
      throw RunStopped(envelope.shutdown().reason());
    }
    return incoming_;
  }
}

void ParticipantSession::on_stop_signal(int signal) {
  if (!heartbeat_.joinable()) // before Welcome: no run to end cleanly
    throw Interrupted(signal);
  const auto now = std::chrono::steady_clock::now();
  if (reported_signal_ == 0) { // the coupler ends the run at the next step boundary
    spdlog::warn("participant {}: signal {} received: the coupler is told, and ends the run at the next step "
                 "boundary (with a checkpoint when run.checkpoint_interval_s > 0)",
                 routing_id(), signal);
    signal_seen_ = now;
    {
      std::lock_guard lock(heartbeat_mutex_);
      reported_signal_ = signal;
    }
    heartbeat_wakeup_.notify_all(); // tell it now, not at the next beat
  } else if (now - signal_seen_ > settings_.stop_grace) {
    throw Interrupted(signal,
                      "interrupted by signal " + std::to_string(signal) + "; the coupler had not ended the run " +
                          std::to_string(settings_.stop_grace.count() / 1000) + " s later",
                      false);
  }
}

Message &ParticipantSession::next_request() {
  const milliseconds timeout = to_ms(welcome_.timeout_s());
  while (true) {
    Message &message = wait_for_message(timeout, "the next request");
    if (!message.envelope().has_heartbeat())
      return message;
  }
}

void ParticipantSession::send(Message &message) {
  message.envelope().set_protocol_version(proto::current_protocol_version);
  message.envelope().set_sender_role(settings_.role);
  channel_.send(message);
}

void ParticipantSession::report_error(const std::string &message, std::uint64_t step) noexcept {
  try {
    Envelope error = proto::make_envelope(settings_.role, step);
    error.mutable_error()->set_message(message);
    error.mutable_error()->set_fatal(true);
    channel_.send(error);
  } catch (...) {
    // The coupler may be gone already; the caller exits non-zero anyway.
  }
}

void ParticipantSession::start_heartbeat(milliseconds interval) {
  stop_heartbeat();
  heartbeat_stop_ = false;
  heartbeat_ = std::thread([this, interval] { heartbeat_loop(interval); });
}

void ParticipantSession::stop_heartbeat() {
  if (!heartbeat_.joinable())
    return;
  {
    std::lock_guard lock(heartbeat_mutex_);
    heartbeat_stop_ = true;
  }
  heartbeat_wakeup_.notify_all();
  heartbeat_.join();
}

void ParticipantSession::heartbeat_loop(milliseconds interval) {
  // Its own socket (ZeroMQ sockets are single-threaded), so heartbeats go out while the main
  // thread is busy solving: the coupler tells a slow participant from a dead one.
  try {
    proto::ChannelOptions options = settings_.options;
    options.send_timeout = milliseconds(1);
    options.linger = milliseconds(0); // stale heartbeats are worth nothing
    proto::ParticipantChannel beat(settings_.coupler, settings_.role,
                                   settings_.name + std::string(proto::heartbeat_suffix), options);
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock lock(heartbeat_mutex_);
    int reported = 0;
    while (!heartbeat_stop_) {
      Envelope envelope = proto::make_envelope(settings_.role, 0);
      envelope.mutable_heartbeat()->set_wall_time_s(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      reported = reported_signal_;
      envelope.mutable_heartbeat()->set_stop_signal(reported);
      try {
        beat.send(envelope);
      } catch (const proto::TransportError &) {
        // Queue full: the coupler is not reading; the main thread's timeout handles it.
      }
      heartbeat_wakeup_.wait_for(lock, interval, [&] { return heartbeat_stop_ || reported_signal_ != reported; });
    }
  } catch (const std::exception &) {
    // Could not even open the socket: without heartbeats the coupler reports this participant.
  }
}

} // namespace fsi::participant
