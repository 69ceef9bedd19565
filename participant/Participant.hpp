#pragma once
// The one loop of a participant of a coupled run (docs/protocol.md): join the coupler (Hello,
// Welcome, a restart's resume), then answer each request until the coupler ends the run. The
// loop itself answers CheckpointRequest and Shutdown, keeps the step count and the bookkeeping
// of implicit coupling (a step's start state, its repeats, its acceptance), and turns every way
// a run can end into the model's finish() and the process's exit code. A role (FluidParticipant,
// StructureParticipant) adds a handler per request it serves and translates the messages into
// its model's domain types.

#include "Model.hpp"
#include "ParticipantSession.hpp"

#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fsi::participant {

class Participant {
public:
  virtual ~Participant();
  Participant(const Participant &) = delete;
  Participant &operator=(const Participant &) = delete;

  /// Returns the exit code: 0 completed, 1 failed, diverged, stopped by the coupler or lost it,
  /// 2 a bad input (a checkpoint that cannot be resumed from), 130 interrupted.
  int run();

protected:
  /// role_name: "fluid", "structure" (messages and reports).
  Participant(Model &model, SessionSettings settings, std::string role_name);

  using Handler = std::function<void(const proto::Message &)>;
  /// The handler of one kind of request (an Envelope body, named as the protocol names it).
  void on(proto::Envelope::BodyCase body, std::string body_name, Handler handler);

  /// Hello's structures (the structure participant declares its topology).
  virtual std::vector<StructureTopology> declared_structures() const { return {}; }
  /// After the handshake and a restart's resume: the structure sends its initial state.
  virtual void joined() {}

  /// An advance of step `step` begins (`body` names the request): checks the step, and under
  /// implicit coupling keeps the step's start state, or on a repeat goes back to it.
  void begin_advance(std::uint64_t step, bool repeat, const char *body);
  /// The advance is done: one more step (under implicit coupling an iterate until accepted).
  void end_advance();

  ParticipantSession &session() { return *session_; }
  const RunPlan &plan() const { return plan_; }

private:
  void join();
  void dispatch(const proto::Message &message);
  void checkpoint(const proto::Message &request);
  /// Implicit coupling: the last advanced step is accepted (the next request is not its repeat).
  void accept_pending();
  int complete(const std::string &reason);
  /// The exit code for the exception that ended the run, after the model's finish().
  int stopped(const std::exception_ptr &error);
  int finish(RunEnd::Kind kind, const std::string &reason, int exit_code);
  void report(const std::string &message) noexcept;

  Model &model_;
  SessionSettings settings_;
  std::string role_name_;
  std::unique_ptr<ParticipantSession> session_;
  struct Route {
    proto::Envelope::BodyCase body;
    std::string name;
    Handler handler;
  };
  std::vector<Route> routes_;
  RunPlan plan_;
  long steps_ = 0;       ///< steps completed
  bool pending_ = false; ///< implicit coupling: step steps_ - 1 is an iterate not yet accepted
};

} // namespace fsi::participant
