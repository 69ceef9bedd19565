#include "FluidParticipant.hpp"

#include "BodyPoses.hpp"

#include "common/Durations.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"

#include <algorithm>

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
  take_idle(body.idle_structures());
  const proto::PointsView x = request.points(body.position_m(), plan().n_points(), "InterpolateRequest.position_m");
  auto *reply = interpolate_reply_.envelope().mutable_interpolate_reply();
  model_.interpolate(body.time_s(), x, interpolate_reply_.add_points(*reply->mutable_velocity_m_per_s(), x.rows()));
  reply->set_solve_wall_s(common::seconds_since(start));
  interpolate_reply_.envelope().set_step(request.envelope().step());
  session().send(interpolate_reply_);
}

void FluidParticipant::take_idle(const google::protobuf::RepeatedField<std::uint32_t> &idle_structures) {
  std::vector<std::uint32_t> idle(idle_structures.begin(), idle_structures.end());
  if (idle == idle_structures_)
    return;
  std::vector<bool> points(static_cast<std::size_t>(plan().n_points()), false);
  std::size_t first = 0, s = 0;
  for (const auto &structure : plan().structures) {
    const auto n = static_cast<std::size_t>(structure.n_points());
    if (std::find(idle.begin(), idle.end(), s) != idle.end())
      std::fill(points.begin() + static_cast<long>(first), points.begin() + static_cast<long>(first + n), true);
    first += n;
    ++s;
  }
  for (const auto i : idle)
    if (i >= plan().structures.size())
      throw proto::MalformedMessageError("idle_structures names structure " + std::to_string(i) + "; the run has " +
                                         std::to_string(plan().structures.size()));
  model_.set_idle_points(points);
  idle_structures_ = std::move(idle);
}

void FluidParticipant::advance(const proto::Message &request) {
  const auto start = common::Clock::now();
  const auto &body = request.envelope().fluid_advance();
  take_idle(body.idle_structures());
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
