#include "CouplingRun.hpp"

#include "CouplingErrors.hpp"
#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CheckpointError.hpp"
#include "common/FormatDuration.hpp"
#include "common/Logging.hpp"
#include "motion/MotionFactory.hpp"
#include "proto/BodyPose.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"
#include "common/ExitCodes.hpp"

#include <spdlog/spdlog.h>

#include <unistd.h>

#include <cmath>
#include <fstream>

namespace fsi::coupler {

namespace {
using Clock = std::chrono::steady_clock;
using proto::v2::Envelope;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

Eigen::Map<const Eigen::VectorXd> as_vector(const PointArray &points) { return {points.data(), points.size()}; }

std::chrono::milliseconds to_ms(double s) { return std::chrono::milliseconds(static_cast<long long>(s * 1e3)); }

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
} // namespace

std::atomic<int> &CouplingRun::stop_signal() {
  static std::atomic<int> signal{0};
  return signal;
}

CouplingRun::CouplingRun(CouplingSetup setup, std::filesystem::path output_dir, std::string endpoint_override)
    : config_(std::move(setup)), output_dir_(std::move(output_dir)), endpoint_override_(std::move(endpoint_override)) {
  config_yaml_ = config_.case_yaml;
  dt_ = config_.run.time_step_s;
  n_steps_ = config_.run.n_steps();
}

CouplingRun::~CouplingRun() = default;

int CouplingRun::run() {
  long step = 0;
  try {
    open();
    handshake();
    receive_initial_state();
    check_stability();
    start_ = last_progress_ = Clock::now();
    // From here a stop signal (Ctrl-C) ends the run at a step boundary, after its checkpoint.
    participants_->allow_clean_stop(clean_stop_grace);
    long n_done = n_steps_;
    for (step = first_step_; step < n_steps_; ++step) {
      advance_one_step(step);
      record_step(step + 1);
      const bool stopping = participants_->stop_requested() != 0;
      // Every interval, at the end (a later --restart with a later end time runs further), and
      // when a signal stops the run.
      if (checkpoint_every_ > 0 && ((step + 1) % checkpoint_every_ == 0 || step + 1 == n_steps_ || stopping))
        checkpoint(step + 1);
      if (stopping)
        return interrupted_at_boundary(step + 1);
      const bool past = structures_past_stop_plane();
      report_progress(step + 1, step + 1 == n_steps_ || past);
      if (past) {
        n_done = step + 1;
        spdlog::info("every structure point is past run.stop_when_past at t = {} s (step {} of {}): the run ends here",
                     static_cast<double>(n_done) * dt_, n_done, n_steps_);
        break;
      }
    }
    participants_->shutdown_all(n_done < n_steps_ ? "run completed: every structure point is past run.stop_when_past"
                                                  : "run completed",
                                true, static_cast<std::uint64_t>(n_done));
    results_->set_status("completed");
    spdlog::info("completed: {} steps; timings and FSI force in {}", n_done, results_->path().string());
    return 0;
  } catch (const ParticipantFailed &e) {
    // A stop signal, and a participant stopped before the step boundary (signalled before
    // Welcome, past its grace, or killed by the launcher after its own grace)
    if (participants_ && participants_->stop_requested() != 0)
      return interrupted(step);
    spdlog::error("{}", e.what());
    if (participants_)
      participants_->shutdown_all(std::string("stopped by the coupler: ") + e.what(), false, step);
    if (results_)
      results_->set_status(std::string("failed: ") + e.what());
    if (!stability_note_.empty())
      spdlog::error("likely cause: {}", stability_note_);
    spdlog::error("run stopped at step {} because of participant {}; results so far are kept in {}", step,
                  e.participant, output_dir_.string());
    return common::exit_code_run_failed;
  } catch (const HandshakeRefused &e) {
    spdlog::error("{}", e.what());
    if (participants_)
      participants_->shutdown_all(std::string("stopped by the coupler: ") + e.what(), false, step);
    if (results_)
      results_->set_status(std::string("refused: ") + e.what());
    return common::exit_code_bad_input;
  } catch (const StopRequested &) {
    return interrupted(step);
  }
}

int CouplingRun::interrupted_at_boundary(long n) {
  const int signal = participants_->stop_requested();
  const std::string when = "after step " + std::to_string(n) + " (t = " + fmt::format("{:g}", static_cast<double>(n) * dt_) + " s)";
  const std::string saved = checkpoint_every_ > 0 ? "; checkpoint written: ./fsi run --restart resumes from it"
                                                  : "; no checkpoint (run.checkpoint_interval_s is 0)";
  spdlog::warn("interrupted by signal {} at {} {}{}", signal, participants_->stop_requested_by(), when, saved);
  participants_->shutdown_all("interrupted by signal " + std::to_string(signal) + " at " +
                                  participants_->stop_requested_by() + " " + when + saved,
                              false, static_cast<std::uint64_t>(n), true);
  results_->set_status("interrupted");
  return common::exit_code_interrupted;
}

int CouplingRun::interrupted(long step) {
  spdlog::warn("interrupted by signal {} at step {}, within the step: telling the participants to stop",
               participants_ ? participants_->stop_requested() : stop_signal().load(), step);
  if (participants_)
    participants_->shutdown_all("interrupted (signal at the coupler)", false, step);
  if (results_)
    results_->set_status("interrupted");
  return common::exit_code_interrupted;
}

// ---- the run, step by step ------------------------------------------------------------------

void CouplingRun::open() {
  std::filesystem::create_directories(output_dir_);
  common::add_log_file(output_dir_ / "coupler.log");
  const auto &c = config_.coupling;
  const auto endpoint = proto::Endpoint::parse(endpoint_override_.empty() ? c.endpoint : endpoint_override_);
  try {
    channel_ = std::make_unique<proto::CouplerChannel>(endpoint, config_.channel);
  } catch (const proto::TransportError &e) {
    throw HandshakeRefused(std::string("cannot listen: ") + e.what());
  }
  write_endpoint_file(channel_->endpoint().str());
  spdlog::info("coupler listening on {} (protocol version {}, case fingerprint {}, {})", channel_->endpoint().str(),
               proto::current_protocol_version, config_.case_fingerprint,
               config_.channel.curve ? "CURVE: encrypted, admitting " + std::to_string(config_.channel.curve->admitted.size()) +
                                           " participant keys"
                                     : std::string("plaintext"));
  participants_ = std::make_unique<ParticipantTable>(
      *channel_, Liveness{to_ms(c.heartbeat_interval_s), to_ms(c.timeout_s), to_ms(c.step_timeout_s)}, &stop_signal());
  checkpoints_ = std::make_unique<checkpoint::CheckpointSet>(output_dir_ / "checkpoints", config_.restart_fingerprint,
                                                             config_.run.checkpoint_keep);
  checkpoint_every_ = config_.run.checkpoint_every();
  if (config_.restart) {
    find_restart_set();
    try {
      results_ = std::make_unique<CouplingResults>(output_dir_ / "coupling.h5", first_step_);
    } catch (const std::runtime_error &e) {
      throw HandshakeRefused(std::string("--restart: ") + e.what());
    }
  } else {
    results_ = std::make_unique<CouplingResults>(output_dir_ / "coupling.h5", config_yaml_, FSI_VERSION);
  }
  law_ = c.parameters->build();
  implicit_ = c.scheme == CouplingConfig::Scheme::implicit;
  if (implicit_) {
    accelerator_ = make_accelerator(c.implicit);
    spdlog::info("coupling law: {}, implicit: {} acceleration, tolerance {:g}, {} to {} iterations a step",
                 law_->name(), accelerator_->name(), c.implicit.tolerance, c.implicit.min_iterations,
                 c.implicit.max_iterations);
  } else {
    spdlog::info("coupling law: {}", law_->name());
  }
  for (std::size_t i = 0; i < config_.rigid_surfaces.size(); ++i)
    if (const auto &motion = config_.rigid_surfaces[i].motion)
      moving_bodies_.emplace_back("surface" + std::to_string(i),
                                  motion::make_motion(*motion, config_.gravity_m_per_s2.norm()));
}

void CouplingRun::handshake() {
  const auto deadline = Clock::now() + to_ms(config_.coupling.handshake_timeout_s);
  while (fluid_id_.empty() || structure_id_.empty()) {
    const std::string missing = structure_id_.empty() ? (fluid_id_.empty() ? "structure and fluid" : "structure")
                                                       : "fluid";
    proto::Incoming *incoming = nullptr;
    try {
      incoming = &participants_->next(deadline, missing, "Hello", 0);
    } catch (const ParticipantFailed &e) {
      if (!e.participant.empty() && participants_->knows(e.participant))
        throw;
      throw ParticipantFailed(missing, "no " + missing + " participant joined within coupling.handshake_timeout_s = " +
                                           std::to_string(config_.coupling.handshake_timeout_s) + " s at " +
                                           channel_->endpoint().str() + "; start it with ./fsi run --participant " +
                                           (structure_id_.empty() ? "structure" : "fluid") + " CASE_DIR" +
                                           (channel_->dropped_unauthenticated() > 0
                                                ? " (" + std::to_string(channel_->dropped_unauthenticated()) +
                                                      " messages were dropped as not authenticated: check that "
                                                      "each host has the keys of this case, docs/security.md)"
                                                : std::string()));
    }
    if (incoming->envelope().has_hello())
      accept_hello(*incoming);
    else
      participants_->answer_error(incoming->peer(), "the run has not started: wait for Welcome", 0);
  }
  participants_->close_admission();
  welcome(structure_id_, false, "structure.ckpt");
  welcome(fluid_id_, true, "fluid.ckpt");
  spdlog::info("participants joined: {} and {}", structure_id_, fluid_id_);
}

bool CouplingRun::accept_hello(const proto::Incoming &incoming) {
  const auto &hello = incoming.envelope().hello();
  const std::string &peer = incoming.peer();
  if (hello.protocol_version() != proto::current_protocol_version)
    refuse(peer, "participant " + peer + " speaks protocol version " + std::to_string(hello.protocol_version()) +
                     ", this coupler version " + std::to_string(proto::current_protocol_version) +
                     ": build all processes of a run from the same version");
  if (hello.case_fingerprint() != config_.case_fingerprint)
    refuse(peer, "participant " + peer + " was started with another case (fingerprint " + hello.case_fingerprint() +
                     ", the coupler's is " + config_.case_fingerprint +
                     "): give every process the same case folder (copy it to every machine)");
  const bool is_fluid = hello.role() == proto::v2::ROLE_FLUID;
  if (!is_fluid && hello.role() != proto::v2::ROLE_STRUCTURE)
    refuse(peer, "participant " + peer + " has role " + std::string(proto::role_name(hello.role())) +
                     "; a coupled run takes one fluid and one structure participant");
  std::string &slot = is_fluid ? fluid_id_ : structure_id_;
  if (!slot.empty())
    refuse(peer, "participant " + peer + " is a second " + std::string(proto::role_name(hello.role())) +
                     " participant; " + slot + " has joined already");
  if (!is_fluid) {
    if (hello.structures_size() != static_cast<int>(config_.n_structures))
      refuse(peer, "participant " + peer + " announced " + std::to_string(hello.structures_size()) +
                       " structures; the case has " + std::to_string(config_.n_structures));
    topology_.assign(hello.structures().begin(), hello.structures().end());
    Eigen::Index n = 0;
    for (const auto &s : topology_) {
      const std::uint64_t points = std::uint64_t{s.n1()} * s.n2(); // 64 bits: 2^16 x 2^16 must not wrap to 0
      if (static_cast<std::uint64_t>(s.point_measure_size()) != points)
        refuse(peer, "participant " + peer + ": structure '" + proto::printable(s.name()) + "' has " +
                         std::to_string(s.point_measure_size()) + " point measures for " + std::to_string(points) +
                         " points");
      n += static_cast<Eigen::Index>(points);
    }
    measures_.resize(n);
    Eigen::Index at = 0;
    for (const auto &s : topology_)
      for (const double m : s.point_measure())
        measures_[at++] = m;
  }
  slot = peer;
  participants_->add(peer);
  spdlog::info("participant {} joined (role {}, protocol {})", peer, proto::role_name(hello.role()),
               hello.protocol_version());
  return true;
}

void CouplingRun::refuse(const std::string &peer, const std::string &message) {
  participants_->answer_error(peer, message, 0);
  throw HandshakeRefused(message);
}

void CouplingRun::welcome(const std::string &id, bool with_structures, const std::string &part) {
  proto::Message envelope(proto::make_envelope(proto::v2::ROLE_COUPLER, 0));
  auto *w = envelope.envelope().mutable_welcome();
  if (restart_set_) {
    w->set_first_step(static_cast<std::uint64_t>(first_step_));
    try {
      w->set_checkpoint_checksum(restart_set_->checksum_of(part));
    } catch (const checkpoint::CheckpointError &e) {
      refuse(id, std::string("--restart: ") + e.what());
    }
  }
  w->set_time_step_s(dt_);
  w->set_n_steps(static_cast<std::uint64_t>(n_steps_));
  w->set_heartbeat_interval_s(config_.coupling.heartbeat_interval_s);
  w->set_timeout_s(config_.coupling.timeout_s);
  w->set_implicit_coupling(implicit_);
  if (with_structures)
    for (const auto &s : topology_)
      *w->add_structures() = s;
  participants_->send(id, envelope, 0);
}

void CouplingRun::receive_initial_state() {
  // The structure's first AdvanceReply, right after Welcome: X^0 and V^0. Eq. (4) keeps
  // V^n = (X^n - X^{n-1}) / dt, so X^{-1} = X^0 - V^0 dt is the structure's own X^{n-1}.
  const proto::Message &message =
      await(structure_id_, Envelope::kAdvanceReply, first_step_, "initial state (AdvanceReply)");
  const auto &reply = message.envelope().advance_reply();
  const Eigen::Index n = measures_.size();
  if (restart_set_) {
    // A restart: X^k and X^{k-1} are the coupler's own, from its checkpoint (X^k - V^k dt would
    // round differently); the structure's X^k must be the same, bit for bit.
    const checkpoint::StateArchive own = checkpoint::read_archive(restart_set_->folder / "coupler.ckpt");
    x_now_ = own.points("x_m", n);
    x_prev_ = own.points("x_previous_m", n);
    law_->start(x_now_);
    law_->load_state(own, n); // the IB points, the feedback integral
    if (implicit_ && own.has("implicit/guess_n_per_measure")) { // the next step's F_0
      guess_ = own.points("implicit/guess_n_per_measure", n);
      have_guess_ = true;
    }
    if (implicit_)
      accelerator_->load_state(own, 3 * n); // IQN-ILS: the columns of the last steps
    const PointArray theirs = message.points(reply.position_m(), n, "AdvanceReply.position_m");
    if (!(theirs.array() == x_now_.array()).all())
      throw ParticipantFailed(structure_id_, "participant " + structure_id_ + " resumed from positions other than "
                                             "the coupler's checkpoint of step " + std::to_string(first_step_));
    spdlog::info("restart: resumed from the checkpoint of step {} (t = {:g} s) in {}", first_step_,
                 restart_set_->time_s, restart_set_->folder.string());
    return;
  }
  try {
    x_now_ = message.finite_points(reply.position_m(), n, "AdvanceReply.position_m");
    const PointArray v0 = message.finite_points(reply.velocity_m_per_s(), n, "AdvanceReply.velocity_m_per_s");
    x_prev_ = x_now_ - dt_ * v0;
    law_->start(x_now_); // X_ib^0 = X^0
  } catch (const proto::MalformedMessageError &e) {
    throw ParticipantFailed(structure_id_, "participant " + structure_id_ + " sent a bad initial state: " + e.what());
  }
  spdlog::info("initial state received: {} Lagrangian points in {} structure(s)", n, topology_.size());
}

void CouplingRun::advance_one_step(long n) {
  const auto step_start = Clock::now();
  participants_->take_wait_s();
  timings_ = StepTimings{};
  if (implicit_) {
    advance_implicit_step(n);
  } else {
    const double t = static_cast<double>(n) * dt_;
    interpolate_fluid_velocity(n, t, law_->interpolation_points(x_now_)); // U_ib^n at X_ib^n (rigid bodies at t^n)
    apply_coupling_law(coupled_);           // X_ib^{n+1} and F_fsi^n, Eq. (5)
    advance_fluid_and_structure(n, false);  // Eq. (8) + PIMPLE || Eq. (4) + Eq. (11), concurrently
    law_->accept(coupled_);                 // the law's state (IB points, integral) moves to step n + 1
  }
  record_rigid_body_loads();
  timings_.waiting_s = participants_->take_wait_s();
  timings_.step_wall_s = seconds_since(step_start);
}

void CouplingRun::advance_implicit_step(long n) {
  // The fixed point F = H(F) of the step: H advances the fluid and the structure from t^n under
  // F (the load -F) and evaluates the coupling law at the end of the step, with X^{n+1},
  // X^n and U_ib^{n+1} = U^{n+1}(X^{n+1}). F_0 is the previous step's last H, which for the
  // penalty law is the explicit scheme's F^n: one iteration is the explicit step.
  if (!have_guess_) { // the first step of a run (or of a restart)
    interpolate_fluid_velocity(n, static_cast<double>(n) * dt_, x_now_);
    apply_coupling_law(coupled_);
    have_guess_ = true;
  } else {
    coupled_.force_density_n_per_measure = guess_;
  }
  const double t_next = static_cast<double>(n + 1) * dt_;
  const PointArray x_start = x_now_, x_before = x_prev_; // X^n, X^{n-1}: each iteration starts there
  accelerator_->begin_step();
  const auto &settings = config_.coupling.implicit;
  for (int k = 0;; ++k) {
    if (k > 0) { // back to the start of the step
      x_now_ = x_start;
      x_prev_ = x_before;
    }
    advance_fluid_and_structure(n, k > 0);             // under F_k; X^{n+1}_k
    interpolate_fluid_velocity(n, t_next, x_now_);      // U^{n+1}_k at X^{n+1}_k
    apply_coupling_law(evaluated_);                    // F~_k = H(F_k)
    const auto f = as_vector(coupled_.force_density_n_per_measure);
    const auto f_tilde = as_vector(evaluated_.force_density_n_per_measure);
    const double scale = f_tilde.norm();
    residual_ = (f_tilde - f).norm() / (scale > 0.0 ? scale : 1.0);
    iterations_ = k + 1;
    const double rms = (f_tilde - f).norm() / std::sqrt(static_cast<double>(std::max<Eigen::Index>(1, x_now_.rows())));
    const bool converged = (f_tilde - f).norm() <= settings.tolerance * scale ||
                           rms <= settings.absolute_tolerance_n_per_measure;
    if ((converged && iterations_ >= settings.min_iterations) || iterations_ >= settings.max_iterations) {
      if (!converged) {
        ++unconverged_steps_;
        if (unconverged_steps_ <= 10 || unconverged_steps_ % 1000 == 0)
          spdlog::warn("step {}: not converged after {} coupling iterations (residual {:.3g}, tolerance {:.3g}); "
                       "accepted ({} such steps so far)",
                       n, iterations_, residual_, settings.tolerance, unconverged_steps_);
      }
      break;
    }
    accelerator_->next(f, f_tilde, next_force_);
    coupled_.force_density_n_per_measure = Eigen::Map<const PointArray>(next_force_.data(), x_now_.rows(), 3);
  }
  accelerator_->end_step();
  law_->accept(evaluated_); // the law's state moves on with the end-of-step evaluation
  guess_ = evaluated_.force_density_n_per_measure;
  iterations_sum_ += iterations_;
}

namespace {
/// What a rejected array says, with the likely cause when a value is not finite.
std::string rejected(const proto::MalformedMessageError &e) {
  const std::string what = e.what();
  return what.find("not finite") == std::string::npos ? what
                                                      : what + " (its solver has most likely diverged; see its log)";
}
} // namespace

void CouplingRun::interpolate_fluid_velocity(long n, double t, const PointArray &points) {
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
  participants_->send(fluid_id_, request_, static_cast<std::uint64_t>(n));
  const proto::Message &message = await(fluid_id_, Envelope::kInterpolateReply, n, "InterpolateReply");
  const auto &reply = message.envelope().interpolate_reply();
  try {
    u_ib_ = message.finite_points(reply.velocity_m_per_s(), x_now_.rows(), "InterpolateReply.velocity_m_per_s");
  } catch (const proto::MalformedMessageError &e) {
    throw ParticipantFailed(fluid_id_, "participant " + fluid_id_ + " sent a bad InterpolateReply at step " +
                                           std::to_string(n) + ": " + rejected(e));
  }
  timings_.interpolation_s += reply.solve_wall_s();
}

void CouplingRun::apply_coupling_law(CouplingOutputs &out) {
  const auto start = Clock::now();
  law_->compute({&x_now_, &x_prev_, &u_ib_, dt_}, out);
  if (!out.force_density_n_per_measure.allFinite()) {
    Eigen::Index worst = 0;
    (out.force_density_n_per_measure.rowwise().squaredNorm().array().isFinite() == false).maxCoeff(&worst);
    throw ParticipantFailed(fluid_id_, "the FSI force is not finite at Lagrangian point " + std::to_string(worst) +
                                           ": the fluid velocity there is " +
                                           std::to_string(u_ib_.row(worst).norm()) + " m/s (NaN?)");
  }
  timings_.coupling_law_s += seconds_since(start);
}

void CouplingRun::advance_fluid_and_structure(long n, bool repeat) {
  const double t = static_cast<double>(n) * dt_;
  // Eq. (8) spreads at X^n. The fluid has the points of this step's InterpolateRequest; when
  // those are the law's own IB points (X_ib^n != X^n), or when the step is repeated (implicit
  // coupling: the last interpolation was at X^{n+1}), X^n goes with the force (a message of its
  // own: a message's array frames are kept from send to send).
  const bool spread_elsewhere = &law_->interpolation_points(x_now_) != &x_now_ || repeat;
  proto::Message &fluid_message = spread_elsewhere ? fluid_advance_spread_ : fluid_advance_;
  auto *fluid = fluid_message.envelope().mutable_fluid_advance();
  fluid->set_time_s(t);
  fluid->set_dt_s(dt_);
  const PointArray &force = coupled_.force_density_n_per_measure;
  fluid_message.add_points(*fluid->mutable_force_density_n_per_measure(), force);
  if (spread_elsewhere)
    fluid_message.add_points(*fluid->mutable_spread_position_m(), x_now_);
  fluid->set_repeat(repeat);
  auto *structure = structure_advance_.envelope().mutable_structure_advance();
  structure->set_repeat(repeat);
  structure->set_time_s(t);
  structure->set_dt_s(dt_);
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
  participants_->send(structure_id_, structure_advance_, static_cast<std::uint64_t>(n));
  participants_->send(fluid_id_, fluid_message, static_cast<std::uint64_t>(n));

  // Collect both replies, in whichever order they come.
  bool fluid_done = false, structure_done = false;
  const auto deadline = Clock::now() + to_ms(config_.coupling.step_timeout_s);
  while (!fluid_done || !structure_done) {
    const std::string &waited = structure_done ? fluid_id_ : structure_id_;
    auto &incoming = participants_->next(deadline, waited, "AdvanceReply", static_cast<std::uint64_t>(n));
    const auto &envelope = incoming.envelope();
    const bool from_fluid = incoming.peer() == fluid_id_;
    bool &done = from_fluid ? fluid_done : structure_done;
    if (!envelope.has_advance_reply() || envelope.step() != static_cast<std::uint64_t>(n) || done) {
      participants_->answer_error(incoming.peer(),
                                  "unexpected " + std::string(proto::body_name(envelope)) + " for step " +
                                      std::to_string(envelope.step()) + "; the coupler waits for the AdvanceReply of step " +
                                      std::to_string(n),
                                  n);
      continue;
    }
    const auto &reply = envelope.advance_reply();
    done = true;
    if (from_fluid) {
      timings_.fluid_solve_s += reply.solve_wall_s();
      fluid_loads_ = reply.rigid_body_loads(); // recorded once the step is accepted (implicit: the last iterate's)
      continue;
    }
    timings_.structure_solve_s += reply.solve_wall_s();
    try { // checked before anything changes: a rejected reply leaves X^n and X^{n-1} as they were
      x_next_ = incoming.message().finite_points(reply.position_m(), x_now_.rows(), "AdvanceReply.position_m");
    } catch (const proto::MalformedMessageError &e) {
      throw ParticipantFailed(structure_id_, "participant " + structure_id_ + " sent a bad AdvanceReply at step " +
                                                 std::to_string(n) + ": " + rejected(e));
    }
    x_prev_.swap(x_now_);
    x_now_.swap(x_next_);
  }
}

// ---- helpers ------------------------------------------------------------------------------

proto::Message &CouplingRun::await(const std::string &peer, Envelope::BodyCase body, long step,
                                   const std::string &what) {
  const auto deadline = Clock::now() + to_ms(config_.coupling.step_timeout_s);
  while (true) {
    auto &incoming = participants_->next(deadline, peer, what, static_cast<std::uint64_t>(step));
    auto &envelope = incoming.envelope();
    if (incoming.peer() == peer && envelope.body_case() == body && envelope.step() == static_cast<std::uint64_t>(step))
      return incoming.message();
    participants_->answer_error(incoming.peer(),
                                "unexpected " + std::string(proto::body_name(envelope)) + " for step " +
                                    std::to_string(envelope.step()) + " at step " + std::to_string(step) +
                                    "; the coupler waits for " + what + " from " + peer,
                                static_cast<std::uint64_t>(step));
  }
}

void CouplingRun::check_stability() {
  for (const auto &s : topology_) {
    const double rho = s.mass_per_measure();
    if (!(rho > 0.0))
      continue;
    const double limit = config_.coupling.parameters->stable_time_step_s(rho);
    spdlog::info("structure '{}': coupling time step limit {:.3g} s (dt = {:.3g} s)", s.name(), limit, dt_);
    if (dt_ > limit && implicit_)
      spdlog::info("structure '{}': dt exceeds the explicit scheme's limit {:.3g} s; implicit coupling iterates each "
                   "step to the law at its end, which that limit does not bind",
                   s.name(), limit);
    else if (dt_ > limit) {
      stability_note_ = fmt::format("run.time_step_s = {:.3g} s exceeds the coupling law's stability limit {:.3g} s "
                                    "for structure '{}' (rho_1 = {:.3g}): lower the penalty constant or the time "
                                    "step, or use coupling.scheme: implicit",
                                    dt_, limit, s.name(), rho);
      spdlog::warn("structure '{}': run.time_step_s = {:.3g} s exceeds the stability limit {:.3g} s of the coupling "
                   "law (rho_1 = {:.3g}); the run is expected to diverge: lower the penalty constant or the time step",
                   s.name(), dt_, limit, rho);
    }
  }
}

bool CouplingRun::structures_past_stop_plane() const {
  // x_now_ holds X^{n+1} of every structure, as the structure solver sent it (after Eq. 11).
  return config_.run.stop_when_past && config_.run.stop_when_past->all_past(x_now_);
}

void CouplingRun::find_restart_set() {
  std::vector<std::string> skipped;
  restart_set_ = checkpoints_->newest(skipped);
  for (const auto &why : skipped)
    spdlog::warn("restart: skipped a checkpoint: {}", why);
  if (!restart_set_)
    throw HandshakeRefused("--restart: no complete checkpoint of this case in " + checkpoints_->root().string() +
                           (skipped.empty() ? std::string(" (run.checkpoint_interval_s makes them)")
                                            : " (" + std::to_string(skipped.size()) + " skipped, above)"));
  first_step_ = restart_set_->step;
  if (first_step_ >= n_steps_)
    throw HandshakeRefused("--restart: the newest checkpoint is of step " + std::to_string(first_step_) +
                           ", the end of this run (" + std::to_string(n_steps_) +
                           " steps): give a later --end-time to run further");
}

void CouplingRun::checkpoint(long n) {
  const auto folder = checkpoints_->begin(n);
  for (const std::string *id : {&structure_id_, &fluid_id_}) {
    proto::Message request(proto::make_envelope(proto::v2::ROLE_COUPLER, static_cast<std::uint64_t>(n)));
    request.envelope().mutable_checkpoint_request();
    participants_->send(*id, request, static_cast<std::uint64_t>(n));
  }
  // Both answers, in whichever order they come.
  std::vector<checkpoint::CheckpointPart> parts;
  std::string structure_part, fluid_part;
  const auto deadline = Clock::now() + to_ms(config_.coupling.step_timeout_s);
  while (structure_part.empty() || fluid_part.empty()) {
    const std::string &waited = structure_part.empty() ? structure_id_ : fluid_id_;
    auto &incoming = participants_->next(deadline, waited, "CheckpointDone", static_cast<std::uint64_t>(n));
    const auto &envelope = incoming.envelope();
    std::string &slot = incoming.peer() == fluid_id_ ? fluid_part : structure_part;
    if (!envelope.has_checkpoint_done() || envelope.step() != static_cast<std::uint64_t>(n) || !slot.empty() ||
        envelope.checkpoint_done().part().empty()) {
      participants_->answer_error(incoming.peer(),
                                  "unexpected " + std::string(proto::body_name(envelope)) + " for step " +
                                      std::to_string(envelope.step()) +
                                      "; the coupler waits for the CheckpointDone of step " + std::to_string(n),
                                  n);
      continue;
    }
    slot = envelope.checkpoint_done().part();
    parts.push_back({slot, envelope.checkpoint_done().checksum()});
  }
  checkpoint::StateArchive own;
  own.put_integer("step", n);
  own.put_points("x_m", x_now_);
  own.put_points("x_previous_m", x_prev_);
  law_->save_state(own);
  if (implicit_ && have_guess_)
    own.put_points("implicit/guess_n_per_measure", guess_);
  if (implicit_)
    accelerator_->save_state(own);
  parts.push_back({"coupler.ckpt", checkpoint::write_archive(folder / "coupler.ckpt", own)});
  results_->flush(); // coupling.h5 holds every step up to this one
  checkpoints_->complete(n, static_cast<double>(n) * dt_, parts);
  spdlog::debug("checkpoint of step {} in {}", n, folder.string());
}

void CouplingRun::record_step(long n) {
  double force[3] = {0.0, 0.0, 0.0};
  const Vec3 total = (coupled_.force_density_n_per_measure.array().colwise() * measures_.array()).colwise().sum();
  for (int k = 0; k < 3; ++k)
    force[k] = total[k];
  results_->write_step(n, static_cast<double>(n) * dt_, timings_, force, iterations_, residual_);
  timings_sum_ += timings_;
  ++timings_count_;
}

void CouplingRun::record_rigid_body_loads() {
  for (const auto &load : fluid_loads_) {
    try {
      const Vec3 force = proto::read_vector3(load.force_n(), "RigidBodyLoad.force_n");
      const Vec3 torque = proto::read_vector3(load.torque_n_m(), "RigidBodyLoad.torque_n_m");
      results_->write_rigid_body_load(load.name(), force.data(), torque.data());
    } catch (const proto::MalformedMessageError &e) {
      throw ParticipantFailed(fluid_id_, "participant " + fluid_id_ + " sent a bad rigid-body load: " + e.what());
    }
  }
}

void CouplingRun::report_progress(long n, bool force) {
  const auto now = Clock::now();
  if (!force && std::chrono::duration<double>(now - last_progress_).count() < config_.run.progress_interval_s)
    return;
  last_progress_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double eta = wall * static_cast<double>(n_steps_ - n) / static_cast<double>(std::max(1L, n - first_step_));
  const double per_step_ms = 1e3 / static_cast<double>(std::max(1L, timings_count_));
  const StepTimings &sum = timings_sum_;
  const std::string iterations =
      implicit_ ? fmt::format(", {:.2f} coupling iterations/step (residual {:.2g}, {} unconverged)",
                              static_cast<double>(iterations_sum_) / static_cast<double>(std::max(1L, timings_count_)),
                              residual_, unconverged_steps_)
                : std::string();
  spdlog::info("step {}/{}  t = {:.5g} s ({:.0f}%)  wall {}  ETA {}  {:.3g} ms/step: fluid {:.3g}, structure {:.3g}, "
               "coupling overhead {:.3g}{}",
               n, n_steps_, static_cast<double>(n) * dt_, 100.0 * static_cast<double>(n) / static_cast<double>(n_steps_),
               common::format_duration(wall), common::format_duration(eta), per_step_ms * sum.step_wall_s,
               per_step_ms * (sum.interpolation_s + sum.fluid_solve_s), per_step_ms * sum.structure_solve_s,
               per_step_ms * sum.overhead_s(), iterations);
  iterations_sum_ = 0;
  timings_sum_ = StepTimings{};
  timings_count_ = 0;
}

void CouplingRun::write_endpoint_file(const std::string &endpoint) const {
  std::string text = endpoint;
  const auto bound = proto::Endpoint::parse(endpoint);
  if (bound.transport() == proto::Endpoint::Transport::tcp && (bound.host() == "*" || bound.host() == "0.0.0.0")) {
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    text = "tcp://" + std::string(host) + ":" + std::to_string(bound.port());
  }
  const auto path = output_dir_ / "coupler.endpoint", tmp = output_dir_ / "coupler.endpoint.tmp";
  std::ofstream(tmp) << text << "\n";
  std::filesystem::rename(tmp, path);
}

} // namespace fsi::coupler
