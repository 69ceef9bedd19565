#include "StructureParticipant.hpp"

#include "BodyPoses.hpp"

#include "common/Durations.hpp"
#include "proto/TransportError.hpp"

#include <cmath>

namespace fsi::participant {

namespace {
SessionSettings structure_settings(SessionSettings settings) {
  settings.role = proto::v2::ROLE_STRUCTURE;
  return settings;
}
} // namespace

StructureParticipant::StructureParticipant(StructureModel &model, SessionSettings settings)
    : Participant(model, structure_settings(std::move(settings)), "structure"), model_(model),
      topology_(model.topology()) {
  on(proto::Envelope::kStructureAdvance, "StructureAdvance", [this](const auto &m) { advance(m); });
}

void StructureParticipant::joined() {
  send_state(static_cast<std::uint64_t>(plan().first_step), 0.0, true); // X^0, V^0 (a restart: X^k, V^k)
}

void StructureParticipant::advance(const proto::Message &request) {
  const auto &body = request.envelope().structure_advance();
  const auto step = request.envelope().step();
  const double expected_t = static_cast<double>(step) * plan().time_step_s;
  if (std::abs(body.time_s() - expected_t) > 1e-9 * std::max(1.0, expected_t))
    throw proto::MalformedMessageError("StructureAdvance for step " + std::to_string(step) + " at t = " +
                                       std::to_string(body.time_s()) + " s, expected " + std::to_string(expected_t));
  const proto::PointsView loads = request.points(body.load_density_n_per_measure(), plan().n_points(),
                                                 "StructureAdvance.load_density_n_per_measure");
  const StructureStep structure_step{static_cast<long>(step), body.time_s(), body.dt_s(),
                                     read_poses(body.rigid_bodies()), !plan().implicit,
                                     {body.idle_structures().begin(), body.idle_structures().end()}};
  begin_advance(step, body.repeat(), "StructureAdvance");
  const auto start = common::Clock::now();
  model_.advance(structure_step, loads);
  send_state(step, common::seconds_since(start), false);
  end_advance();
}

void StructureParticipant::send_state(std::uint64_t step, double solve_wall_s, bool with_velocity) {
  const Eigen::Index n = plan().n_points();
  auto *reply = reply_.envelope().mutable_advance_reply();
  reply->set_time_s(model_.time_s());
  reply->set_solve_wall_s(solve_wall_s);
  model_.positions(reply_.add_points(*reply->mutable_position_m(), n));
  // Per step only X^{n+1}: the coupler has X^n, so V^{n+1} = (X^{n+1} - X^n) / dt is not sent.
  reply->clear_velocity_m_per_s();
  reply->clear_max_stretch_ratio();
  for (const double ratio : model_.max_stretch_ratios())
    reply->add_max_stretch_ratio(ratio);
  if (with_velocity)
    model_.velocities(reply_.add_points(*reply->mutable_velocity_m_per_s(), n));
  reply_.envelope().set_step(step);
  session().send(reply_);
}

} // namespace fsi::participant
