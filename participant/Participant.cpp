#include "Participant.hpp"

#include "common/ExitCodes.hpp"
#include "common/UserError.hpp"
#include "proto/TransportError.hpp"

#include <spdlog/spdlog.h>

namespace fsi::participant {

namespace {

std::vector<proto::v2::StructureTopology> to_messages(const std::vector<StructureTopology> &structures) {
  std::vector<proto::v2::StructureTopology> out;
  for (const auto &s : structures) {
    proto::v2::StructureTopology t;
    t.set_name(s.name);
    t.set_model(s.model);
    t.set_n1(static_cast<std::uint32_t>(s.n1));
    t.set_n2(static_cast<std::uint32_t>(s.n2));
    t.mutable_point_measure()->Assign(s.point_measure.data(), s.point_measure.data() + s.point_measure.size());
    t.set_mass_per_measure(s.mass_per_measure);
    write_life_spec(s.life, t);
    out.push_back(std::move(t));
  }
  return out;
}

RunPlan plan_of(const proto::v2::Welcome &welcome) {
  RunPlan plan{welcome.time_step_s(),
               static_cast<long>(welcome.n_steps()),
               static_cast<long>(welcome.first_step()),
               welcome.implicit_coupling(),
               {}};
  for (const auto &t : welcome.structures()) {
    StructureTopology s{t.name(), t.model(),           static_cast<int>(t.n1()), static_cast<int>(t.n2()),
                        {},       t.mass_per_measure()};
    s.point_measure = Eigen::Map<const Eigen::VectorXd>(t.point_measure().data(), t.point_measure_size());
    s.life = life_spec_of(t);
    plan.structures.push_back(std::move(s));
  }
  return plan;
}

} // namespace

Participant::Participant(Model &model, SessionSettings settings, std::string role_name)
    : model_(model), settings_(std::move(settings)), role_name_(std::move(role_name)) {}

Participant::~Participant() = default;

void Participant::on(proto::Envelope::BodyCase body, std::string body_name, Handler handler) {
  routes_.push_back({body, std::move(body_name), std::move(handler)});
}

int Participant::run() {
  spdlog::info("{}: {}", role_name_, model_.describe());
  try {
    join();
    while (true) {
      const proto::Message &message = session_->next_request();
      if (message.envelope().has_shutdown())
        return complete(message.envelope().shutdown().reason());
      dispatch(message);
    }
  } catch (...) {
    return stopped(std::current_exception());
  }
}

void Participant::join() {
  session_ = std::make_unique<ParticipantSession>(settings_);
  spdlog::info("joining the coupler at {} as {}", settings_.coupler.str(), session_->routing_id());
  std::vector<StructureTopology> declared = declared_structures();
  const proto::v2::Welcome &welcome = session_->handshake(to_messages(declared));
  plan_ = plan_of(welcome);
  if (!declared.empty()) // the structure's own: Welcome forwards them to the fluid only
    plan_.structures = std::move(declared);
  spdlog::info("joined: {} steps of {} s, {} Lagrangian points", plan_.n_steps, plan_.time_step_s, plan_.n_points());
  model_.start(plan_);
  steps_ = plan_.first_step;
  if (steps_ > 0) {
    model_.resume(steps_, welcome.checkpoint_checksum());
    spdlog::info("restart: resumed from the checkpoint of step {}", steps_);
  }
  joined();
}

void Participant::dispatch(const proto::Message &message) {
  const proto::Envelope &request = message.envelope();
  if (request.has_checkpoint_request())
    return checkpoint(message);
  std::string expected;
  for (const Route &route : routes_) {
    if (route.body == request.body_case())
      return route.handler(message);
    expected += (expected.empty() ? "" : " or ") + route.name;
  }
  throw proto::MalformedMessageError("expected " + expected + ", got " + std::string(proto::body_name(request)) +
                                     " at step " + std::to_string(request.step()));
}

void Participant::begin_advance(std::uint64_t step, bool repeat, const char *body) {
  const long n = static_cast<long>(step);
  if (repeat) {
    if (!pending_ || n + 1 != steps_)
      throw proto::MalformedMessageError(
          std::string(body) + ".repeat for step " + std::to_string(step) +
          (plan_.implicit ? ", which was not the last step advanced" : " in an explicit run"));
    pending_ = false;
    model_.restore_step_start();
    --steps_;
    return;
  }
  accept_pending();
  if (n != steps_ || n >= plan_.n_steps)
    throw proto::MalformedMessageError(std::string(body) + " for step " + std::to_string(step) + " after " +
                                       std::to_string(steps_) + " of " + std::to_string(plan_.n_steps) + " steps");
  if (plan_.implicit)
    model_.save_step_start();
}

void Participant::end_advance() {
  ++steps_;
  pending_ = plan_.implicit;
}

void Participant::accept_pending() {
  if (!pending_)
    return;
  pending_ = false;
  model_.accept_step(steps_ - 1);
}

void Participant::checkpoint(const proto::Message &request) {
  accept_pending();
  const auto step = request.envelope().step();
  if (step != static_cast<std::uint64_t>(steps_))
    throw proto::MalformedMessageError("CheckpointRequest for step " + std::to_string(step) + " after " +
                                       std::to_string(steps_) + " steps");
  const checkpoint::CheckpointPart part = model_.write_checkpoint(steps_);
  proto::Message done(proto::make_envelope(settings_.role, step));
  done.envelope().mutable_checkpoint_done()->set_part(part.name);
  done.envelope().mutable_checkpoint_done()->set_checksum(part.checksum);
  session_->send(done);
}

int Participant::complete(const std::string &reason) {
  accept_pending();
  model_.finish({RunEnd::Kind::completed, reason, steps_});
  spdlog::info("completed: {} steps of {} ({})", steps_, plan_.n_steps, reason);
  return 0;
}

int Participant::stopped(const std::exception_ptr &error) {
  if (pending_) { // the run ends on an iterate of implicit coupling: keep the state at the step's start
    pending_ = false;
    --steps_;
    try {
      model_.restore_step_start();
    } catch (const std::exception &e) {
      spdlog::error("the state at the start of step {} could not be restored: {}", steps_, e.what());
    }
  }
  const std::string at = " at step " + std::to_string(steps_);
  try {
    std::rethrow_exception(error);
  } catch (const Interrupted &e) {
    spdlog::warn("{}{}", e.what(), at);
    if (!e.by_coupler)
      report("participant " + session_->routing_id() + " " + e.what());
    return finish(RunEnd::Kind::interrupted, e.what(), common::exit_code_interrupted);
  } catch (const RunStopped &e) {
    spdlog::error("the coupler stopped the run{}: {}", at, e.what());
    return finish(RunEnd::Kind::stopped, e.what(), common::exit_code_run_failed);
  } catch (const CouplerLost &e) {
    spdlog::error("{}", e.what());
    return finish(RunEnd::Kind::coupler_lost, e.what(), common::exit_code_run_failed);
  } catch (const Diverged &e) { // the model has kept its last good state and set its status
    report(role_name_ + " diverged at " + e.what());
    return common::exit_code_run_failed;
  } catch (const proto::TransportError &e) { // the transport, a bad message (a UserError too: not the user's)
    const std::string message = "participant " + role_name_ + " failed" + at + ": " + e.what();
    report(message);
    return finish(RunEnd::Kind::failed, message, common::exit_code_run_failed);
  } catch (const common::UserError &e) { // a checkpoint the coupler named that cannot be resumed from
    report("participant " + role_name_ + ": " + e.what());
    return finish(RunEnd::Kind::failed, e.what(), common::exit_code_bad_input);
  } catch (const std::exception &e) { // the model itself: writing results failed (a full disk), ...
    const std::string message = "participant " + role_name_ + " failed" + at + ": " + e.what();
    report(message);
    return finish(RunEnd::Kind::failed, message, common::exit_code_run_failed);
  }
}

int Participant::finish(RunEnd::Kind kind, const std::string &reason, int exit_code) {
  if (kind == RunEnd::Kind::failed)
    spdlog::error("{}", reason);
  try {
    model_.finish({kind, reason, steps_});
  } catch (const std::exception &e) { // the results file itself may be what cannot be written
    spdlog::error("finishing the {} failed too: {}", role_name_, e.what());
  }
  if (exit_code != common::exit_code_interrupted)
    spdlog::error("results up to step {} are kept", steps_);
  return exit_code;
}

void Participant::report(const std::string &message) noexcept {
  if (session_)
    session_->report_error(message, static_cast<std::uint64_t>(steps_));
}

} // namespace fsi::participant
