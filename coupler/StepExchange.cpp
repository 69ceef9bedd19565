#include "StepExchange.hpp"

#include "CouplingErrors.hpp"
#include "common/Durations.hpp"
#include "proto/BodyPose.hpp"
#include "proto/TransportError.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace fsi::coupler {

using common::Clock;
using common::seconds_since;
using common::to_ms;

using proto::v2::Envelope;

namespace {
void write_pose(const std::string &name, const motion::RigidMotion &motion, double t, proto::v2::RigidBodyPose &out) {
  proto::BodyPose pose;
  pose.name = name;
  pose.pose = motion.pose_at(t);
  // Rigid velocity field v(x) = v_o + omega x (x - o): recovered from three points.
  const Vec3 o = pose.pose.translation();
  pose.origin_velocity_m_per_s = motion.velocity_at(o, t);
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = pose.pose.linear().col(k);
    // (v(o + e) - v_o) = omega x e; sum over an orthonormal basis: omega = 1/2 sum e x (omega x e).
    pose.angular_velocity_rad_per_s += 0.5 * e.cross(motion.velocity_at(o + e, t) - pose.origin_velocity_m_per_s);
  }
  proto::write_body_pose(pose, out);
}

/// What a rejected array says, with the likely cause when a value is not finite.
std::string rejected(const proto::MalformedMessageError &e) {
  const std::string what = e.what();
  return what.find("not finite") == std::string::npos ? what
                                                      : what + " (its solver has most likely diverged; see its log)";
}
} // namespace

namespace {
std::vector<participant::LifeSpec> life_specs(const Roster &roster) {
  std::vector<participant::LifeSpec> specs;
  for (const auto &t : roster.topology) {
    try {
      specs.push_back(participant::life_spec_of(t));
    } catch (const proto::MalformedMessageError &e) {
      throw ParticipantFailed(roster.structure_id, "participant " + roster.structure_id +
                                                       " declared a structure the coupler cannot take: " + e.what());
    }
  }
  return specs;
}
} // namespace

StepExchange::StepExchange(ParticipantTable &participants, const Roster &roster, CouplingLaw &law,
                           MovingBodies moving_bodies, double time_step_s, double step_timeout_s)
    : participants_(participants), roster_(roster), law_(law), moving_bodies_(std::move(moving_bodies)),
      dt_(time_step_s), step_timeout_s_(step_timeout_s), life_(life_specs(roster), time_step_s) {
  first_point_.push_back(0);
  for (const auto &t : roster_.topology)
    first_point_.push_back(first_point_.back() + static_cast<Eigen::Index>(t.n1()) * t.n2());
  idle_ = life_.idle();
}

std::vector<std::string> StepExchange::structure_names() const {
  std::vector<std::string> names;
  for (const auto &t : roster_.topology)
    names.push_back(t.name());
  return names;
}

void StepExchange::begin_step(long n) {
  const double t = static_cast<double>(n) * dt_;
  for (const std::size_t i : life_.release(t))
    spdlog::info("structure '{}' released at t = {:g} s ({} in the scene)", roster_.topology[i].name(), t,
                 life_.n_in_scene());
  idle_ = life_.idle();
}

void StepExchange::end_step(long n) {
  std::vector<PointArray> x(roster_.topology.size());
  std::vector<const PointArray *> pointers;
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = state_.x_now_m.middleRows(first_point_[i], first_point_[i + 1] - first_point_[i]);
    pointers.push_back(&x[i]);
  }
  const double t = static_cast<double>(n + 1) * dt_;
  for (const std::size_t i : life_.remove_past_planes(pointers, t))
    spdlog::info("structure '{}' removed at t = {:g} s: past its remove_when_past plane ({} left in the scene)",
                 roster_.topology[i].name(), t, life_.n_in_scene());
  for (const std::size_t i : life_.tear_overstretched(max_stretch_ratio_, t))
    spdlog::warn("structure '{}' torn off the scene at t = {:g} s: stretch ratio {:.4g} above its "
                 "tear_above_stretch_ratio ({} left in the scene)", roster_.topology[i].name(), t,
                 max_stretch_ratio_[i], life_.n_in_scene());
  idle_ = life_.idle();
}

void StepExchange::zero_idle(PointArray &force_density) const {
  for (const std::uint32_t i : idle_)
    force_density.middleRows(first_point_[i], first_point_[i + 1] - first_point_[i]).setZero();
}

void StepExchange::interpolate_fluid_velocity(long n, double t, const PointArray &points) {
  // Section 2.3, first bullet: rigid surfaces move before the fluid forces are computed.
  auto *request = request_.envelope().mutable_interpolate_request();
  request->set_time_s(t);
  request->mutable_rigid_bodies()->Clear();
  for (const auto &[name, motion] : moving_bodies_)
    write_pose(name, *motion, t, *request->add_rigid_bodies());
  // U_ib^n at the immersed-boundary points X_ib^n: the structure points X^n for the penalty
  // and feedback laws (see PenaltyCouplingLaw.hpp for what that makes of Eq. 5), the law's own
  // advected points for two_point_sets.
  request_.add_points(*request->mutable_position_m(), points);
  request->mutable_idle_structures()->Assign(idle_.begin(), idle_.end());
  participants_.send(roster_.fluid_id, request_, static_cast<std::uint64_t>(n));
  const proto::Message &message = await(roster_.fluid_id, Envelope::kInterpolateReply, n, "InterpolateReply");
  const auto &reply = message.envelope().interpolate_reply();
  try {
    state_.u_ib_m_per_s =
        message.finite_points(reply.velocity_m_per_s(), state_.x_now_m.rows(), "InterpolateReply.velocity_m_per_s");
  } catch (const proto::MalformedMessageError &e) {
    throw ParticipantFailed(roster_.fluid_id, "participant " + roster_.fluid_id + " sent a bad InterpolateReply at step " +
                                                  std::to_string(n) + ": " + rejected(e));
  }
  timings_.interpolation_s += reply.solve_wall_s();
}

void StepExchange::apply_coupling_law(CouplingOutputs &out) {
  const auto start = Clock::now();
  law_.compute({&state_.x_now_m, &state_.x_prev_m, &state_.u_ib_m_per_s, dt_}, out);
  zero_idle(out.force_density_n_per_measure); // nothing acts on a structure out of the scene
  if (!out.force_density_n_per_measure.allFinite()) {
    Eigen::Index worst = 0;
    (out.force_density_n_per_measure.rowwise().squaredNorm().array().isFinite() == false).maxCoeff(&worst);
    throw ParticipantFailed(roster_.fluid_id, "the FSI force is not finite at Lagrangian point " + std::to_string(worst) +
                                                  ": the fluid velocity there is " +
                                                  std::to_string(state_.u_ib_m_per_s.row(worst).norm()) + " m/s (NaN?)");
  }
  timings_.coupling_law_s += seconds_since(start);
}

void StepExchange::advance_fluid_and_structure(long n, bool repeat) {
  send_advances(n, repeat);
  // Collect both replies, in whichever order they come.
  bool fluid_done = false, structure_done = false;
  const auto deadline = Clock::now() + to_ms(step_timeout_s_);
  while (!fluid_done || !structure_done) {
    const std::string &waited = structure_done ? roster_.fluid_id : roster_.structure_id;
    auto &incoming = participants_.next(deadline, waited, "AdvanceReply", static_cast<std::uint64_t>(n));
    const auto &envelope = incoming.envelope();
    const bool from_fluid = incoming.peer() == roster_.fluid_id;
    bool &done = from_fluid ? fluid_done : structure_done;
    if (!envelope.has_advance_reply() || envelope.step() != static_cast<std::uint64_t>(n) || done) {
      participants_.answer_unexpected(incoming, n, "; the coupler waits for the AdvanceReply of step " +
                                                       std::to_string(n));
      continue;
    }
    done = true;
    if (from_fluid) {
      timings_.fluid_solve_s += envelope.advance_reply().solve_wall_s();
      fluid_loads_ = envelope.advance_reply().rigid_body_loads(); // recorded once the step is accepted
      continue;
    }
    take_structure_reply(incoming, n);
  }
}

void StepExchange::send_advances(long n, bool repeat) {
  const double t = static_cast<double>(n) * dt_;
  // Eq. (8) spreads at X^n. The fluid has the points of this step's InterpolateRequest; when
  // those are the law's own IB points (X_ib^n != X^n), or when the step is repeated (implicit
  // coupling: the last interpolation was at X^{n+1}), X^n goes with the force (a message of its
  // own: a message's array frames are kept from send to send).
  const bool spread_elsewhere = &law_.interpolation_points(state_.x_now_m) != &state_.x_now_m || repeat;
  proto::Message &fluid_message = spread_elsewhere ? fluid_advance_spread_ : fluid_advance_;
  auto *fluid = fluid_message.envelope().mutable_fluid_advance();
  fluid->set_time_s(t);
  fluid->set_dt_s(dt_);
  zero_idle(coupled_.force_density_n_per_measure); // an implicit step's guess or accelerated force too
  const PointArray &force = coupled_.force_density_n_per_measure;
  fluid_message.add_points(*fluid->mutable_force_density_n_per_measure(), force);
  fluid->mutable_idle_structures()->Assign(idle_.begin(), idle_.end());
  if (spread_elsewhere)
    fluid_message.add_points(*fluid->mutable_spread_position_m(), state_.x_now_m);
  fluid->set_repeat(repeat);
  auto *structure = structure_advance_.envelope().mutable_structure_advance();
  structure->set_repeat(repeat);
  structure->set_time_s(t);
  structure->set_dt_s(dt_);
  structure->mutable_idle_structures()->Assign(idle_.begin(), idle_.end());
  // Signs: Eq. (1) adds +f_fsi, spread from F_fsi (Eq. 8), to the fluid; Eq. (3) subtracts
  // F_fsi from the structure. The fluid gets F_fsi, the structure the load -F_fsi.
  structure_advance_.add_points(*structure->mutable_load_density_n_per_measure(), force.rows()) = -force;
  // Section 2.3: the rigid surfaces move; both participants use them at the end of the step.
  fluid->mutable_rigid_bodies()->Clear();
  structure->mutable_rigid_bodies()->Clear();
  for (const auto &[name, motion] : moving_bodies_) {
    write_pose(name, *motion, t + dt_, *fluid->add_rigid_bodies());
    *structure->add_rigid_bodies() = fluid->rigid_bodies(fluid->rigid_bodies_size() - 1);
  }
  participants_.send(roster_.structure_id, structure_advance_, static_cast<std::uint64_t>(n));
  participants_.send(roster_.fluid_id, fluid_message, static_cast<std::uint64_t>(n));
}

void StepExchange::take_structure_reply(const proto::Incoming &incoming, long n) {
  const auto &reply = incoming.envelope().advance_reply();
  timings_.structure_solve_s += reply.solve_wall_s();
  try { // checked before anything changes: a rejected reply leaves X^n and X^{n-1} as they were
    x_next_ = incoming.message().finite_points(reply.position_m(), state_.x_now_m.rows(), "AdvanceReply.position_m");
  } catch (const proto::MalformedMessageError &e) {
    throw ParticipantFailed(roster_.structure_id, "participant " + roster_.structure_id +
                                                      " sent a bad AdvanceReply at step " + std::to_string(n) + ": " +
                                                      rejected(e));
  }
  const auto &stretch = reply.max_stretch_ratio();
  bool any_tears = false;
  for (std::size_t i = 0; i < life_.size(); ++i)
    any_tears = any_tears || life_.tears(i);
  if (any_tears && static_cast<std::size_t>(stretch.size()) != life_.size())
    throw ParticipantFailed(roster_.structure_id, "participant " + roster_.structure_id + " sent " +
                                                      std::to_string(stretch.size()) + " max_stretch_ratio values at "
                                                      "step " + std::to_string(n) + " for " +
                                                      std::to_string(life_.size()) + " structures, some of which tear");
  max_stretch_ratio_.assign(stretch.begin(), stretch.end());
  state_.x_prev_m.swap(state_.x_now_m);
  state_.x_now_m.swap(x_next_);
}

proto::Message &StepExchange::await(const std::string &peer, Envelope::BodyCase body, long step,
                                    const std::string &what) {
  const auto deadline = Clock::now() + to_ms(step_timeout_s_);
  while (true) {
    auto &incoming = participants_.next(deadline, peer, what, static_cast<std::uint64_t>(step));
    auto &envelope = incoming.envelope();
    if (incoming.peer() == peer && envelope.body_case() == body && envelope.step() == static_cast<std::uint64_t>(step))
      return incoming.message();
    participants_.answer_unexpected(incoming, static_cast<std::uint64_t>(step),
                                    " at step " + std::to_string(step) + "; the coupler waits for " + what + " from " +
                                        peer);
  }
}

} // namespace fsi::coupler
