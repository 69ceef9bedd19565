#include "FluidParticipant.hpp"

#include "BodyPoses.hpp"

#include "common/Durations.hpp"
#include "proto/PackedPoints.hpp"

namespace fsi::participant {

namespace {
SessionSettings fluid_settings(SessionSettings settings) {
  settings.role = proto::v2::ROLE_FLUID;
  if (!settings.stop_signal)
    settings.stop_signal = &FluidParticipant::stop_signal();
  return settings;
}
} // namespace

std::atomic<int> &FluidParticipant::stop_signal() {
  static std::atomic<int> signal{0};
  return signal;
}

FluidParticipant::FluidParticipant(FluidModel &model, SessionSettings settings)
    : Participant(model, fluid_settings(std::move(settings)), "fluid"), model_(model) {
  on(proto::Envelope::kInterpolateRequest, "InterpolateRequest", [this](const auto &m) { interpolate(m); });
  on(proto::Envelope::kFluidAdvance, "FluidAdvance", [this](const auto &m) { advance(m); });
}

void FluidParticipant::interpolate(const proto::Message &request) {
  const auto start = common::Clock::now();
  const auto &body = request.envelope().interpolate_request();
  const proto::PointsView x = request.points(body.position_m(), plan().n_points(), "InterpolateRequest.position_m");
  auto *reply = interpolate_reply_.envelope().mutable_interpolate_reply();
  model_.interpolate(body.time_s(), x, interpolate_reply_.add_points(*reply->mutable_velocity_m_per_s(), x.rows()));
  reply->set_solve_wall_s(common::seconds_since(start));
  interpolate_reply_.envelope().set_step(request.envelope().step());
  session().send(interpolate_reply_);
}

void FluidParticipant::advance(const proto::Message &request) {
  const auto start = common::Clock::now();
  const auto &body = request.envelope().fluid_advance();
  const auto step = request.envelope().step();
  const proto::PointsView force =
      request.points(body.force_density_n_per_measure(), plan().n_points(), "FluidAdvance.force_density_n_per_measure");
  const FluidStep fluid_step{static_cast<long>(step), body.time_s(), body.dt_s(), read_poses(body.rigid_bodies())};
  begin_advance(step, body.repeat(), "FluidAdvance");
  if (body.has_spread_position_m()) // the law's own IB points: Eq. (8) spreads at X^n
    model_.spread_at(request.points(body.spread_position_m(), plan().n_points(), "FluidAdvance.spread_position_m"));
  loads_.clear();
  model_.advance(fluid_step, force, loads_);
  auto *reply = advance_reply_.envelope().mutable_advance_reply();
  write_loads(loads_, *reply->mutable_rigid_body_loads());
  reply->set_time_s(body.time_s() + body.dt_s());
  reply->set_solve_wall_s(common::seconds_since(start));
  advance_reply_.envelope().set_step(step);
  session().send(advance_reply_);
  end_advance();
}

} // namespace fsi::participant
