#include "CouplingRun.hpp"

#include "Admission.hpp"
#include "CouplingErrors.hpp"
#include "common/Durations.hpp"
#include "ExplicitStep.hpp"
#include "ImplicitStep.hpp"
#include "common/ExitCodes.hpp"
#include "common/Version.hpp"
#include "common/Logging.hpp"
#include "motion/MotionFactory.hpp"
#include "proto/PackedPoints.hpp"
#include "proto/TransportError.hpp"

#include <spdlog/spdlog.h>

#include <unistd.h>

#include <fstream>

namespace fsi::coupler {

using common::Clock;
using common::seconds_since;
using common::to_ms;

using proto::v2::Envelope;

std::atomic<int> &CouplingRun::stop_signal() {
  static std::atomic<int> signal{0};
  return signal;
}

CouplingRun::CouplingRun(CouplingSetup setup, std::filesystem::path output_dir, std::string endpoint_override)
    : config_(std::move(setup)), output_dir_(std::move(output_dir)), endpoint_override_(std::move(endpoint_override)) {
  dt_ = config_.run.time_step_s;
  n_steps_ = config_.run.n_steps();
}

CouplingRun::~CouplingRun() = default;

int CouplingRun::run() {
  long step = 0;
  try {
    open();
    admit();
    receive_initial_state();
    check_stability();
    return run_steps(step);
  } catch (const ParticipantFailed &e) {
    // A stop signal, and a participant stopped before the step boundary (signalled before
    // Welcome, past its grace, or killed by the launcher after its own grace)
    if (participants_ && participants_->stop_requested() != 0)
      return interrupted(step);
    return failed(e.participant, e.what(), step);
  } catch (const HandshakeRefused &e) {
    return refused(e.what(), step);
  } catch (const StopRequested &) {
    return interrupted(step);
  }
}

int CouplingRun::run_steps(long &step) {
  report_->start();
  // From here a stop signal (Ctrl-C) ends the run at a step boundary, after its checkpoint.
  participants_->allow_clean_stop(clean_stop_grace);
  for (step = checkpoints_->first_step(); step < n_steps_; ++step) {
    advance_one_step(step);
    report_->record_step(step + 1, exchange_->timings(), *scheme_, exchange_->coupled().force_density_n_per_measure,
                         roster_.measures);
    const bool stopping = participants_->stop_requested() != 0;
    if (checkpoints_->due(step + 1, n_steps_, stopping))
      checkpoint(step + 1);
    if (stopping)
      return interrupted_at_boundary(step + 1);
    const bool past = structures_past_stop_plane();
    report_->progress(step + 1, step + 1 == n_steps_ || past, *scheme_);
    if (past) {
      spdlog::info("every structure point is past run.stop_when_past at t = {} s (step {} of {}): the run ends here",
                   static_cast<double>(step + 1) * dt_, step + 1, n_steps_);
      return completed(step + 1);
    }
  }
  return completed(n_steps_);
}

int CouplingRun::completed(long n_done) {
  participants_->shutdown_all(n_done < n_steps_ ? "run completed: every structure point is past run.stop_when_past"
                                                : "run completed",
                              true, static_cast<std::uint64_t>(n_done));
  results_->set_status("completed");
  spdlog::info("completed: {} steps; timings and FSI force in {}", n_done, results_->path().string());
  return common::exit_code_success;
}

int CouplingRun::failed(const std::string &participant, const std::string &what, long step) {
  spdlog::error("{}", what);
  if (participants_)
    participants_->shutdown_all(std::string("stopped by the coupler: ") + what, false, step);
  if (results_)
    results_->set_status(std::string("failed: ") + what);
  if (!stability_note_.empty())
    spdlog::error("likely cause: {}", stability_note_);
  spdlog::error("run stopped at step {} because of participant {}; results so far are kept in {}", step, participant,
                output_dir_.string());
  return common::exit_code_run_failed;
}

int CouplingRun::refused(const std::string &what, long step) {
  spdlog::error("{}", what);
  if (participants_)
    participants_->shutdown_all(std::string("stopped by the coupler: ") + what, false, step);
  if (results_)
    results_->set_status(std::string("refused: ") + what);
  return common::exit_code_bad_input;
}

int CouplingRun::interrupted_at_boundary(long n) {
  const int signal = participants_->stop_requested();
  const std::string when = "after step " + std::to_string(n) + " (t = " + fmt::format("{:g}", static_cast<double>(n) * dt_) + " s)";
  const std::string saved = checkpoints_->enabled() ? "; checkpoint written: ./fsi run --restart resumes from it"
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
  checkpoints_ = std::make_unique<RunCheckpoints>(output_dir_, config_);
  if (config_.restart) {
    checkpoints_->find_restart(n_steps_);
    try {
      results_ = std::make_unique<CouplingResults>(output_dir_ / "coupling.h5", checkpoints_->first_step());
    } catch (const std::runtime_error &e) {
      throw HandshakeRefused(std::string("--restart: ") + e.what());
    }
  } else {
    results_ = std::make_unique<CouplingResults>(output_dir_ / "coupling.h5", config_.case_yaml, common::code_version());
  }
  report_ = std::make_unique<RunReport>(*results_, n_steps_, dt_, config_.run.progress_interval_s,
                                        checkpoints_->first_step());
  law_ = c.parameters->build();
  if (c.scheme == CouplingConfig::Scheme::implicit) {
    auto implicit = std::make_unique<ImplicitStep>(c.implicit);
    spdlog::info("coupling law: {}, implicit: {} acceleration, tolerance {:g}, {} to {} iterations a step",
                 law_->name(), implicit->accelerator_name(), c.implicit.tolerance, c.implicit.min_iterations,
                 c.implicit.max_iterations);
    scheme_ = std::move(implicit);
  } else {
    scheme_ = std::make_unique<ExplicitStep>();
    spdlog::info("coupling law: {}", law_->name());
  }
}

MovingBodies CouplingRun::moving_bodies() const {
  MovingBodies bodies;
  for (std::size_t i = 0; i < config_.rigid_surfaces.size(); ++i)
    if (const auto &motion = config_.rigid_surfaces[i].motion)
      bodies.emplace_back("surface" + std::to_string(i), motion::make_motion(*motion, config_.gravity_m_per_s2.norm()));
  return bodies;
}

void CouplingRun::admit() {
  Admission admission(*participants_, *channel_, config_);
  roster_ = admission.admit();
  admission.welcome(roster_, {n_steps_, dt_, config_.coupling.scheme == CouplingConfig::Scheme::implicit,
                              &checkpoints_->restart()});
  exchange_ = std::make_unique<StepExchange>(*participants_, roster_, *law_, moving_bodies(), dt_,
                                             config_.coupling.step_timeout_s);
  // A law with a state per point (the feedback integral, the IB points) would carry on integrating
  // at a structure that waits or is gone, and hit it with that at its release.
  if (law_->name() != "penalty")
    for (std::size_t i = 0; i < roster_.topology.size(); ++i)
      if (exchange_->life().release_time_s(i) > 0.0 || roster_.topology[i].remove_when_past_size() > 0)
        throw HandshakeRefused("structure '" + roster_.topology[i].name() + "' enters or leaves the scene during "
                               "the run (release_time_s, remove_when_past, a feed): that works with coupling.law: "
                               "penalty only, not " + law_->name());
}

void CouplingRun::receive_initial_state() {
  // The structure's first AdvanceReply, right after Welcome: X^0 and V^0. Eq. (4) keeps
  // V^n = (X^n - X^{n-1}) / dt, so X^{-1} = X^0 - V^0 dt is the structure's own X^{n-1}.
  const proto::Message &message = exchange_->await(roster_.structure_id, Envelope::kAdvanceReply,
                                                   checkpoints_->first_step(), "initial state (AdvanceReply)");
  if (checkpoints_->restart()) {
    resume_state(message);
    return;
  }
  const auto &reply = message.envelope().advance_reply();
  const Eigen::Index n = roster_.n_points();
  auto &state = exchange_->state();
  try {
    state.x_now_m = message.finite_points(reply.position_m(), n, "AdvanceReply.position_m");
    const PointArray v0 = message.finite_points(reply.velocity_m_per_s(), n, "AdvanceReply.velocity_m_per_s");
    state.x_prev_m = state.x_now_m - dt_ * v0;
    law_->start(state.x_now_m); // X_ib^0 = X^0
  } catch (const proto::MalformedMessageError &e) {
    throw ParticipantFailed(roster_.structure_id,
                            "participant " + roster_.structure_id + " sent a bad initial state: " + e.what());
  }
  spdlog::info("initial state received: {} Lagrangian points in {} structure(s)", n, roster_.topology.size());
}

void CouplingRun::resume_state(const proto::Message &message) {
  // X^k and X^{k-1} are the coupler's own, from its checkpoint (X^k - V^k dt would round
  // differently); the structure's X^k must be the same, bit for bit.
  const checkpoint::StateArchive own = checkpoints_->restart_state();
  const Eigen::Index n = roster_.n_points();
  auto &state = exchange_->state();
  state.x_now_m = own.points("x_m", n);
  state.x_prev_m = own.points("x_previous_m", n);
  law_->start(state.x_now_m);
  law_->load_state(own, n);   // the IB points, the feedback integral
  exchange_->life().load(own, exchange_->structure_names(), static_cast<double>(checkpoints_->first_step()) * dt_);
  scheme_->load_state(own, n); // implicit: the next step's F_0, IQN-ILS's columns
  const PointArray theirs = message.points(message.envelope().advance_reply().position_m(), n, "AdvanceReply.position_m");
  const long first = checkpoints_->first_step();
  if (!(theirs.array() == state.x_now_m.array()).all())
    throw ParticipantFailed(roster_.structure_id, "participant " + roster_.structure_id +
                                                      " resumed from positions other than the coupler's checkpoint "
                                                      "of step " + std::to_string(first));
  spdlog::info("restart: resumed from the checkpoint of step {} (t = {:g} s) in {}", first,
               checkpoints_->restart()->time_s, checkpoints_->restart()->folder.string());
}

void CouplingRun::advance_one_step(long n) {
  const auto step_start = Clock::now();
  participants_->take_wait_s();
  auto &timings = exchange_->timings();
  timings = StepTimings{};
  exchange_->begin_step(n);        // the structures released at t^n enter the scene
  scheme_->advance(n, *exchange_); // Eq. (5), then Eq. (8) + PIMPLE || Eq. (4) + Eq. (11)
  exchange_->end_step(n);          // those past their removal plane at X^{n+1} leave it
  record_rigid_body_loads();
  timings.waiting_s = participants_->take_wait_s();
  timings.step_wall_s = seconds_since(step_start);
}

// ---- helpers ------------------------------------------------------------------------------

void CouplingRun::check_stability() {
  const bool implicit = config_.coupling.scheme == CouplingConfig::Scheme::implicit;
  for (const auto &s : roster_.topology) {
    const double rho = s.mass_per_measure();
    if (!(rho > 0.0))
      continue;
    const double limit = config_.coupling.parameters->stable_time_step_s(rho);
    spdlog::info("structure '{}': coupling time step limit {:.3g} s (dt = {:.3g} s)", s.name(), limit, dt_);
    if (dt_ > limit && implicit)
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
  // X^{n+1} of every structure, as the structure solver sent it (after Eq. 11).
  return config_.run.stop_when_past && config_.run.stop_when_past->all_past(exchange_->state().x_now_m);
}

void CouplingRun::checkpoint(long n) {
  checkpoint::StateArchive own;
  own.put_integer("step", n);
  own.put_points("x_m", exchange_->state().x_now_m);
  own.put_points("x_previous_m", exchange_->state().x_prev_m);
  law_->save_state(own);
  scheme_->save_state(own);
  exchange_->life().save(own, exchange_->structure_names());
  checkpoints_->write(n, static_cast<double>(n) * dt_, *participants_, roster_, own, *results_);
}

void CouplingRun::record_rigid_body_loads() {
  for (const auto &load : exchange_->rigid_body_loads()) {
    try {
      const Vec3 force = proto::read_vector3(load.force_n(), "RigidBodyLoad.force_n");
      const Vec3 torque = proto::read_vector3(load.torque_n_m(), "RigidBodyLoad.torque_n_m");
      results_->write_rigid_body_load(load.name(), force.data(), torque.data());
    } catch (const proto::MalformedMessageError &e) {
      throw ParticipantFailed(roster_.fluid_id, "participant " + roster_.fluid_id + " sent a bad rigid-body load: " + e.what());
    }
  }
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
