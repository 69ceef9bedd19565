#include "StructureParticipant.hpp"

#include "proto/BodyPose.hpp"

#include "common/ConfigError.hpp"
#include "common/UserError.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"
#include "common/ExitCodes.hpp"

#include <spdlog/spdlog.h>

#include <cmath>

namespace fsi::structure {

namespace {
/// A request the coupler should never send: a bug on its side or a foreign coupler.
class ProtocolViolation : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};
} // namespace

StructureParticipant::StructureParticipant(StructureRun &run, proto::SessionSettings settings)
    : run_(run), settings_(std::move(settings)) {
  settings_.role = proto::v2::ROLE_STRUCTURE;
  settings_.case_fingerprint = run_.config().case_fingerprint;
  settings_.stop_signal = &StructureRun::stop_signal();
}

std::vector<proto::v2::StructureTopology> StructureParticipant::topology() const {
  std::vector<proto::v2::StructureTopology> out;
  for (const auto &s : run_.scene().structures()) {
    proto::v2::StructureTopology t;
    t.set_name(s->name());
    t.set_model(s->model());
    t.set_n1(static_cast<std::uint32_t>(s->grid_shape().first));
    t.set_n2(static_cast<std::uint32_t>(s->grid_shape().second));
    const Eigen::VectorXd &m = s->point_measures();
    t.mutable_point_measure()->Assign(m.data(), m.data() + m.size());
    t.set_mass_per_measure(s->mass_per_measure());
    out.push_back(std::move(t));
  }
  return out;
}

int StructureParticipant::run() {
  run_.start(StructureRun::Resume::when_told); // the coupler says where the run starts
  for (const auto &s : run_.scene().structures())
    loads_.push_back(PointArray::Zero(s->n_points(), 3));
  long step = 0;
  // Implicit coupling: the scene holds an iterate of step `step`, not a state; a run that ends
  // then keeps the state at the step's start (what the results and the status say).
  bool iterate_pending = false;
  const auto settle = [&] {
    if (iterate_pending)
      run_.restore_step_start();
    iterate_pending = false;
  };
  try {
    session_ = std::make_unique<proto::ParticipantSession>(settings_);
    spdlog::info("joining the coupler at {} as {}", settings_.coupler.str(), session_->routing_id());
    const auto &welcome = session_->handshake(topology());
    if (std::abs(welcome.time_step_s() - run_.config().run.time_step_s) > 1e-12 * run_.config().run.time_step_s ||
        static_cast<long>(welcome.n_steps()) != run_.n_steps())
      throw ProtocolViolation("the coupler runs " + std::to_string(welcome.n_steps()) + " steps of " +
                              std::to_string(welcome.time_step_s()) + " s; this case has " +
                              std::to_string(run_.n_steps()) + " steps of " +
                              std::to_string(run_.config().run.time_step_s) + " s");
    spdlog::info("joined: {} steps of {} s", welcome.n_steps(), welcome.time_step_s());
    step = static_cast<long>(welcome.first_step());
    if (step > 0)
      run_.resume_from(step, welcome.checkpoint_checksum());
    else
      run_.begin_fresh();
    send_state(static_cast<std::uint64_t>(step), 0.0, true); // the initial state X^0, V^0 (a restart: X^k, V^k)
    // Implicit coupling: a step may come again (StructureAdvance.repeat) until the coupler
    // moves on; its output waits until then (the next request is of another kind or step).
    const bool implicit = welcome.implicit_coupling();
    const proto::Message *next = nullptr; // a request read but not handled yet (implicit coupling)
    for (; step < run_.n_steps(); ++step) { // Envelope.step: t^step -> t^{step+1}
      if (!next)
        next = &session_->next_request();
      while (next->envelope().has_checkpoint_request()) { // at the step boundary, before step `step`
        write_checkpoint(next->envelope(), step);
        next = &session_->next_request();
      }
      const proto::Envelope &request = next->envelope();
      if (request.has_shutdown() && request.shutdown().success()) { // run.stop_when_past, seen by the coupler
        run_.finish("completed", step);
        spdlog::info("completed at step {} of {}: the coupler ended the run ({})", step, run_.n_steps(),
                     request.shutdown().reason());
        return 0;
      }
      check_request(request, step);
      if (request.structure_advance().repeat())
        throw ProtocolViolation("StructureAdvance.repeat for step " + std::to_string(step) +
                                (implicit ? ", which has not been advanced yet" : " in an explicit run"));
      if (implicit) {
        run_.save_step_start();
        iterate_pending = true;
      }
      while (true) {
        unpack_loads(*next);
        take_rigid_poses(next->envelope().structure_advance());
        const auto start = std::chrono::steady_clock::now();
        const StepOutcome outcome = run_.advance_step(step, &loads_, !implicit);
        const double solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (outcome.kind == StepOutcome::Kind::diverged) {
          session_->report_error("structure diverged at " + outcome.message, static_cast<std::uint64_t>(step));
          return common::exit_code_run_failed;
        }
        if (outcome.kind == StepOutcome::Kind::interrupted) {
          session_->report_error("participant " + session_->routing_id() + " " + outcome.message,
                                 static_cast<std::uint64_t>(step));
          return common::exit_code_interrupted;
        }
        send_state(static_cast<std::uint64_t>(step), solve_s, false);
        if (!implicit) { // the step is done: the next request is read at the next step
          next = nullptr;
          break;
        }
        next = &session_->next_request();
        if (!next->envelope().has_structure_advance() || !next->envelope().structure_advance().repeat())
          break;
        check_request(next->envelope(), step); // a repeat of this step
        run_.restore_step_start();
      }
      if (implicit) { // accepted: now the stretch and speed guards, and the output
        iterate_pending = false;
        const StepOutcome accepted = run_.accept_step(step);
        if (accepted.kind == StepOutcome::Kind::diverged) {
          session_->report_error("structure diverged at " + accepted.message, static_cast<std::uint64_t>(step));
          return common::exit_code_run_failed;
        }
      }
    }
    if (!next)
      next = &session_->next_request();
    while (next->envelope().has_checkpoint_request()) { // the checkpoint at the end of the run
      write_checkpoint(next->envelope(), step);
      next = &session_->next_request();
    }
    const proto::Envelope &last = next->envelope();
    if (!last.has_shutdown())
      throw ProtocolViolation("expected Shutdown after the last step, got " + std::string(proto::body_name(last)));
    run_.finish("completed", run_.n_steps());
    spdlog::info("completed: the coupler ended the run ({})", last.shutdown().reason());
    return 0;
  } catch (const proto::Interrupted &e) {
    settle();
    run_.finish("interrupted", step);
    if (session_ && !e.by_coupler)
      session_->report_error("participant " + session_->routing_id() + " " + e.what(),
                             static_cast<std::uint64_t>(step));
    spdlog::warn("{} (the structure's state is that of step {})", e.what(), step);
    return common::exit_code_interrupted;
  } catch (const proto::RunStopped &e) {
    settle();
    spdlog::error("the coupler stopped the run at step {}: {}", step, e.what());
    run_.finish(std::string("stopped: ") + e.what(), step);
  } catch (const proto::CouplerLost &e) {
    settle();
    spdlog::error("{}", e.what());
    run_.finish(std::string("coupler lost: ") + e.what(), step);
  } catch (const ProtocolViolation &e) {
    settle();
    const std::string message = "participant structure at step " + std::to_string(step) + ": " + e.what();
    spdlog::error("{}", message);
    if (session_)
      session_->report_error(message, static_cast<std::uint64_t>(step));
    run_.finish("failed: " + message, step);
  } catch (const proto::TransportError &e) {
    settle();
    spdlog::error("transport failed at step {}: {}", step, e.what());
    run_.finish(std::string("failed: ") + e.what(), step);
  } catch (const common::UserError &e) { // a checkpoint the coupler named that cannot be resumed from
    spdlog::error("{}", e.what());
    if (session_)
      session_->report_error("participant structure: " + std::string(e.what()), static_cast<std::uint64_t>(step));
    return common::exit_code_bad_input;
  } catch (const std::exception &e) { // writing results failed (a full disk, a read-only folder), ...
    const std::string message = "participant structure failed at step " + std::to_string(step) + ": " + e.what();
    spdlog::error("{}", message);
    if (session_) // the coupler stops the run at once instead of after its timeout
      session_->report_error(message, static_cast<std::uint64_t>(step));
    try {
      settle();
      run_.finish("failed: " + message, step);
    } catch (const std::exception &) {
      // the results file itself may be what cannot be written
    }
  }
  spdlog::error("results up to step {} are kept", step);
  return common::exit_code_run_failed;
}

void StructureParticipant::write_checkpoint(const proto::Envelope &request, long step) {
  if (request.step() != static_cast<std::uint64_t>(step))
    throw ProtocolViolation("CheckpointRequest for step " + std::to_string(request.step()) + " after " +
                            std::to_string(step) + " steps");
  const auto folder = run_.checkpoints().folder(step);
  std::filesystem::create_directories(folder);
  const checkpoint::CheckpointPart part = run_.write_checkpoint_part(folder, step);
  proto::Message done(proto::make_envelope(proto::v2::ROLE_STRUCTURE, static_cast<std::uint64_t>(step)));
  done.envelope().mutable_checkpoint_done()->set_part(part.name);
  done.envelope().mutable_checkpoint_done()->set_checksum(part.checksum);
  session_->send(done);
}

void StructureParticipant::take_rigid_poses(const proto::v2::StructureAdvance &advance) {
  // Eq. (11) corrects against the surfaces at the end of the step, where the coupler put them.
  const double end_time_s = advance.time_s() + advance.dt_s();
  for (const auto &message : advance.rigid_bodies()) {
    const proto::BodyPose pose = proto::read_body_pose(message);
    motion::CoupledMotion *motion = run_.scene().coupled_motion(pose.name);
    if (!motion)
      throw ProtocolViolation("the coupler sent the pose of '" + pose.name +
                              "', which is not a moving surface of this case");
    motion->set(end_time_s, pose.pose, pose.origin_velocity_m_per_s, pose.angular_velocity_rad_per_s);
  }
  if (advance.rigid_bodies_size() != static_cast<int>(run_.scene().n_coupled_motions()))
    throw ProtocolViolation("the coupler sent " + std::to_string(advance.rigid_bodies_size()) +
                            " rigid-body poses; this case has " + std::to_string(run_.scene().n_coupled_motions()) +
                            " moving surfaces");
}

void StructureParticipant::check_request(const proto::Envelope &request, long step) const {
  if (request.has_shutdown())
    throw ProtocolViolation("the coupler ended the run early (" + request.shutdown().reason() + ")");
  if (!request.has_structure_advance())
    throw ProtocolViolation("expected StructureAdvance, got " + std::string(proto::body_name(request)));
  const double expected_t = static_cast<double>(step) * run_.config().run.time_step_s;
  if (request.step() != static_cast<std::uint64_t>(step) ||
      std::abs(request.structure_advance().time_s() - expected_t) > 1e-9 * std::max(1.0, expected_t))
    throw ProtocolViolation("StructureAdvance for step " + std::to_string(request.step()) + " (t = " +
                            std::to_string(request.structure_advance().time_s()) + " s), expected step " +
                            std::to_string(step));
}

void StructureParticipant::unpack_loads(const proto::Message &request) {
  Eigen::Index total = 0;
  for (const auto &l : loads_)
    total += l.rows();
  proto::PointsView all = [&] {
    try {
      return request.points(request.envelope().structure_advance().load_density_n_per_measure(), total,
                            "StructureAdvance.load_density_n_per_measure");
    } catch (const proto::MalformedMessageError &e) {
      throw ProtocolViolation(e.what());
    }
  }();
  Eigen::Index at = 0;
  for (auto &l : loads_) {
    l = all.middleRows(at, l.rows());
    at += l.rows();
  }
}

void StructureParticipant::send_state(std::uint64_t step, double solve_wall_s, bool with_velocity) {
  const auto &structures = run_.scene().structures();
  Eigen::Index total = 0;
  for (const auto &s : structures)
    total += s->n_points();
  auto *reply = reply_.envelope().mutable_advance_reply();
  reply->set_time_s(run_.scene().time_s());
  reply->set_solve_wall_s(solve_wall_s);
  auto x = reply_.add_points(*reply->mutable_position_m(), total);
  Eigen::Index at = 0;
  for (const auto &s : structures) {
    x.middleRows(at, s->n_points()) = s->positions_m();
    at += s->n_points();
  }
  // Per step only X^{n+1}: the coupler has X^n, so V^{n+1} = (X^{n+1} - X^n) / dt is not sent.
  reply->clear_velocity_m_per_s();
  if (with_velocity) {
    auto v = reply_.add_points(*reply->mutable_velocity_m_per_s(), total);
    at = 0;
    for (const auto &s : structures) {
      v.middleRows(at, s->n_points()) = s->velocities_m_per_s();
      at += s->n_points();
    }
  }
  reply_.envelope().set_step(step);
  session_->send(reply_);
}

} // namespace fsi::structure
