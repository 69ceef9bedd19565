#pragma once
// The exchanges of one coupled step with the two participants (section 2.3), and the
// Lagrangian state they move (all structures concatenated, N x 3, SI): the rigid bodies posed
// and the fluid velocity interpolated at the points, the coupling law evaluated, and both
// participants advanced concurrently under its force, their replies checked before anything
// changes. A step scheme (ExplicitStep, ImplicitStep) strings these together.

#include "CouplingLaw.hpp"
#include "ParticipantTable.hpp"
#include "Roster.hpp"
#include "StepTimings.hpp"
#include "motion/RigidMotion.hpp"
#include "participant/LifeCycle.hpp"
#include "proto/Message.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fsi::coupler {

using MovingBodies = std::vector<std::pair<std::string, std::shared_ptr<const motion::RigidMotion>>>;

/// X^n, X^{n-1} and U_ib^n of every Lagrangian point (SI).
struct LagrangianState {
  PointArray x_now_m, x_prev_m, u_ib_m_per_s;
};

class StepExchange {
public:
  StepExchange(ParticipantTable &participants, const Roster &roster, CouplingLaw &law, MovingBodies moving_bodies,
               double time_step_s, double step_timeout_s);

  /// The structures released at the start of step n enter the scene (participant::LifeCycle).
  void begin_step(long n);
  /// After step n is accepted: the structures past their removal plane at X^{n+1} are gone.
  void end_step(long n);
  /// U_ib at `points` at time t (the rigid bodies posed at t first), into state().u_ib_m_per_s.
  void interpolate_fluid_velocity(long n, double t, const PointArray &points);
  /// The law with X^n, X^{n-1}, U_ib of state() into `out`; refuses a force that is not finite.
  void apply_coupling_law(CouplingOutputs &out);
  /// Both participants advance step n under coupled().force_density_n_per_measure (repeat:
  /// again, from the step's start); X^{n+1} becomes state().x_now_m.
  void advance_fluid_and_structure(long n, bool repeat);
  /// The next message of `peer` with this body and step (others are answered with an error).
  proto::Message &await(const std::string &peer, proto::v2::Envelope::BodyCase body, long step, const std::string &what);
  /// The fluid's forces on the rigid bodies of the step's last advance.
  const google::protobuf::RepeatedPtrField<proto::v2::RigidBodyLoad> &rigid_body_loads() const { return fluid_loads_; }

  LagrangianState &state() { return state_; }
  const LagrangianState &state() const { return state_; }
  /// F_fsi^n, the force the participants are advanced under (and the law's X_ib^{n+1}).
  CouplingOutputs &coupled() { return coupled_; }
  CouplingLaw &law() { return law_; }
  StepTimings &timings() { return timings_; }
  participant::LifeCycle &life() { return life_; }
  const participant::LifeCycle &life() const { return life_; }
  /// The structures' names, in the order of the arrays.
  std::vector<std::string> structure_names() const;
  double time_step_s() const { return dt_; }

private:
  void send_advances(long n, bool repeat);
  /// Zero force on the points of the structures not in the scene.
  void zero_idle(PointArray &force_density) const;
  /// The structure's reply: X^{n+1}, checked, becomes X^n.
  void take_structure_reply(const proto::Incoming &incoming, long n);

  ParticipantTable &participants_;
  const Roster &roster_;
  CouplingLaw &law_;
  MovingBodies moving_bodies_;
  double dt_, step_timeout_s_;

  LagrangianState state_;
  PointArray x_next_; ///< a structure reply, checked before it becomes X^{n+1}
  std::vector<double> max_stretch_ratio_; ///< the structure reply's, per structure (for the tears)
  CouplingOutputs coupled_;
  participant::LifeCycle life_;
  std::vector<Eigen::Index> first_point_; ///< per structure, its first row in the arrays (and the total last)
  std::vector<std::uint32_t> idle_;       ///< life_.idle() of the step
  StepTimings timings_;
  google::protobuf::RepeatedPtrField<proto::v2::RigidBodyLoad> fluid_loads_; ///< of the step's last advance
  proto::Message request_, fluid_advance_, fluid_advance_spread_, structure_advance_; // headers reused step to step
};

} // namespace fsi::coupler
