#include "FluidParticipant.hpp"

#include "TransportError.hpp"
#include "common/ExitCodes.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace fsi::proto {

namespace {
constexpr int exit_code_run_failed = 1;
double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

std::atomic<int> &FluidParticipant::stop_signal() {
  static std::atomic<int> signal{0};
  return signal;
}

FluidParticipant::FluidParticipant(FluidModel &model, SessionSettings settings)
    : model_(model), settings_(std::move(settings)) {
  settings_.role = v2::ROLE_FLUID;
  settings_.stop_signal = &stop_signal();
}

int FluidParticipant::run() {
  spdlog::info("fluid: {}", model_.describe());
  try {
    session_ = std::make_unique<ParticipantSession>(settings_);
    spdlog::info("joining the coupler at {} as {}", settings_.coupler.str(), session_->routing_id());
    const auto &welcome = session_->handshake();
    for (const auto &s : welcome.structures())
      n_points_ += static_cast<Eigen::Index>(s.n1()) * s.n2();
    spdlog::info("joined: {} steps of {} s, {} Lagrangian points", welcome.n_steps(), welcome.time_step_s(), n_points_);
    model_.start(welcome);
    implicit_ = welcome.implicit_coupling();
    if (welcome.first_step() > 0) {
      model_.resume(static_cast<long>(welcome.first_step()), welcome.checkpoint_checksum());
      steps_ = static_cast<long>(welcome.first_step());
      spdlog::info("restart: resumed from the checkpoint of step {}", steps_);
    }
    while (true) {
      const Message &message = session_->next_request();
      const Envelope &request = message.envelope();
      if (request.has_shutdown()) {
        model_.finish(true);
        spdlog::info("completed: {} steps ({})", steps_, request.shutdown().reason());
        return 0;
      }
      if (request.has_interpolate_request())
        interpolate(message);
      else if (request.has_fluid_advance())
        advance(message);
      else if (request.has_checkpoint_request())
        checkpoint(message);
      else
        throw MalformedMessageError("expected InterpolateRequest or FluidAdvance, got " +
                                    std::string(body_name(request)) + " at step " + std::to_string(request.step()));
    }
  } catch (const Interrupted &e) {
    spdlog::warn("{} at step {}", e.what(), steps_);
    model_.finish(false);
    if (session_ && !e.by_coupler)
      session_->report_error("participant " + session_->routing_id() + " " + e.what(), steps_);
    return common::exit_code_interrupted;
  } catch (const RunStopped &e) {
    spdlog::error("the coupler stopped the run at step {}: {}", steps_, e.what());
  } catch (const CouplerLost &e) {
    spdlog::error("{}", e.what());
  } catch (const std::exception &e) { // the transport, a bad message, or the model itself
    const std::string message = "participant fluid failed at step " + std::to_string(steps_) + ": " + e.what();
    spdlog::error("{}", message);
    if (session_)
      session_->report_error(message, steps_);
  }
  model_.finish(false);
  return exit_code_run_failed;
}

void FluidParticipant::interpolate(const Message &request) {
  const auto start = std::chrono::steady_clock::now();
  const auto &body = request.envelope().interpolate_request();
  const PointsView x = request.points(body.position_m(), n_points_, "InterpolateRequest.position_m");
  auto *reply = interpolate_reply_.envelope().mutable_interpolate_reply();
  model_.interpolate(body, x, interpolate_reply_.add_points(*reply->mutable_velocity_m_per_s(), n_points_));
  reply->set_solve_wall_s(seconds_since(start));
  interpolate_reply_.envelope().set_step(request.envelope().step());
  session_->send(interpolate_reply_);
}

void FluidParticipant::checkpoint(const Message &request) {
  const auto step = request.envelope().step();
  if (step != static_cast<std::uint64_t>(steps_))
    throw MalformedMessageError("CheckpointRequest for step " + std::to_string(step) + " after " +
                                std::to_string(steps_) + " steps");
  const auto [part, checksum] = model_.write_checkpoint(steps_);
  Message done(make_envelope(v2::ROLE_FLUID, step));
  done.envelope().mutable_checkpoint_done()->set_part(part);
  done.envelope().mutable_checkpoint_done()->set_checksum(checksum);
  session_->send(done);
}

void FluidParticipant::advance(const Message &request) {
  const auto start = std::chrono::steady_clock::now();
  const auto &body = request.envelope().fluid_advance();
  const PointsView force =
      request.points(body.force_density_n_per_measure(), n_points_, "FluidAdvance.force_density_n_per_measure");
  auto *reply = advance_reply_.envelope().mutable_advance_reply();
  reply->mutable_rigid_body_loads()->Clear();
  // Implicit coupling: the first advance of a step keeps its start state, a repeat goes back to it.
  if (body.repeat()) {
    if (!implicit_ || steps_ != static_cast<long>(request.envelope().step()) + 1)
      throw MalformedMessageError("FluidAdvance.repeat for step " + std::to_string(request.envelope().step()) +
                                  (implicit_ ? ", which was not the last step advanced" : " in an explicit run"));
    model_.restore_step_start();
    --steps_;
  } else if (implicit_) {
    model_.save_step_start();
  }
  if (body.has_spread_position_m()) // the law's own IB points: Eq. (8) spreads at X^n
    model_.spread_at(request.points(body.spread_position_m(), n_points_, "FluidAdvance.spread_position_m"));
  model_.advance(body, force, *reply);
  reply->set_time_s(body.time_s() + body.dt_s());
  reply->set_solve_wall_s(seconds_since(start));
  advance_reply_.envelope().set_step(request.envelope().step());
  session_->send(advance_reply_);
  ++steps_;
}

} // namespace fsi::proto
