#include "PrescribedFlowParticipant.hpp"

#include "common/ConfigError.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace fsi::prescribed_flow {

std::atomic<int> &PrescribedFlowParticipant::stop_signal() {
  static std::atomic<int> signal{0};
  return signal;
}

PrescribedFlowParticipant::PrescribedFlowParticipant(std::unique_ptr<FlowField> flow, proto::SessionSettings settings)
    : flow_(std::move(flow)), settings_(std::move(settings)) {
  settings_.role = proto::v1::ROLE_FLUID;
  settings_.stop_signal = &stop_signal();
}

int PrescribedFlowParticipant::run() {
  spdlog::info("prescribed flow: {} (one-way coupling: the FSI force does not act on this flow)", flow_->describe());
  try {
    session_ = std::make_unique<proto::ParticipantSession>(settings_);
    spdlog::info("joining the coupler at {} as {}", settings_.coupler.str(), session_->routing_id());
    const auto &welcome = session_->handshake();
    long n_points = 0;
    for (const auto &s : welcome.structures())
      n_points += static_cast<long>(s.n1()) * s.n2();
    spdlog::info("joined: {} steps of {} s, {} Lagrangian points", welcome.n_steps(), welcome.time_step_s(), n_points);
    while (true) {
      const proto::Envelope &request = session_->next_request();
      if (request.has_shutdown()) {
        spdlog::info("completed: {} steps ({})", steps_, request.shutdown().reason());
        return 0;
      }
      if (request.has_interpolate_request())
        interpolate(request);
      else if (request.has_fluid_advance())
        advance(request);
      else {
        const std::string message = "participant " + session_->routing_id() + " got an unexpected " +
                                    std::string(proto::body_name(request)) + " at step " +
                                    std::to_string(request.step());
        spdlog::error("{}", message);
        session_->report_error(message, request.step());
        return common::exit_code_run_failed;
      }
    }
  } catch (const proto::Interrupted &e) {
    spdlog::warn("{} at step {}", e.what(), steps_);
    if (session_)
      session_->report_error("participant " + session_->routing_id() + " " + e.what(), steps_);
    return 130;
  } catch (const proto::RunStopped &e) {
    spdlog::error("the coupler stopped the run at step {}: {}", steps_, e.what());
  } catch (const proto::CouplerLost &e) {
    spdlog::error("{}", e.what());
  } catch (const proto::TransportError &e) {
    spdlog::error("transport failed at step {}: {}", steps_, e.what());
    if (session_)
      session_->report_error(std::string("participant fluid: ") + e.what(), steps_);
  }
  return common::exit_code_run_failed;
}

void PrescribedFlowParticipant::interpolate(const proto::Envelope &request) {
  const auto start = std::chrono::steady_clock::now();
  const auto &body = request.interpolate_request();
  proto::read_points(body.position_m(), "InterpolateRequest.position_m", positions_);
  velocities_.resize(positions_.rows(), 3);
  flow_->velocities(positions_, body.time_s(), velocities_);
  auto *reply = interpolate_reply_.mutable_interpolate_reply();
  proto::write_points(velocities_, *reply->mutable_velocity_m_per_s());
  reply->set_solve_wall_s(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  interpolate_reply_.set_step(request.step());
  session_->send(interpolate_reply_);
}

void PrescribedFlowParticipant::advance(const proto::Envelope &request) {
  // One-way coupling: the flow is prescribed, so F_fsi (Eq. 8) is not spread. Check the size
  // only, so that a broken coupler is caught here too.
  const auto &body = request.fluid_advance();
  proto::view_points(body.force_density_n_per_m2(), positions_.rows(), "FluidAdvance.force_density_n_per_m2");
  auto *reply = advance_reply_.mutable_advance_reply();
  reply->set_time_s(body.time_s() + body.dt_s());
  reply->set_solve_wall_s(0.0);
  advance_reply_.set_step(request.step());
  session_->send(advance_reply_);
  ++steps_;
}

} // namespace fsi::prescribed_flow
