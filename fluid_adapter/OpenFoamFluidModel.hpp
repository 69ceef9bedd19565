#pragma once
// The OpenFOAM fluid as a fluid model of the protocol (fsi-openfoam-fluid), OpenFOAM-free:
// each step it builds the kernel stencil of Eqs. (6-7) at X^n (cells found through a spatial
// index built once per mesh, again after a moving mesh moved), interpolates U_ib^n, then spreads F_fsi^n (Eq. 8) at the same
// points, divides by rho_f (OpenFOAM's incompressible momentum equation is per unit density)
// and hands the acceleration to FoamFlow for one PIMPLE step. Rigid bodies (closed STL
// surfaces with a prescribed motion) are penalized (Eqs. 9-10): chi and u_rib at t^{n+1} from
// each body's swept candidate cells, the penalization implicit in the momentum matrix; the
// force and torque of the fluid on each body go back to the coupler.
//
// A moving mesh (a rotor's cell zone turning behind an AMI, constant/dynamicMeshDict) moves at
// the start of each step, before the bodies are penalized there: a body turning with its cells
// keeps the same chi (no cell switches; docs/model.md), a static body lies in the fixed cells.
//
// MPI: every rank holds a model over its own cells. The master (rank 0) talks to the coupler
// through participant::FluidParticipant and broadcasts each request to the other ranks, which run follow().
// Kernel widths (the nearest cell over all ranks), weight sums and interpolated velocities are
// reduced over the ranks; spreading touches only local cells.

#include "FoamFlow.hpp"
#include "OpenFoamConfig.hpp"
#include "fluid_adapter/ibm/CellIndex.hpp"
#include "fluid_adapter/ibm/KernelStencil.hpp"
#include "fluid_adapter/ibm/NearestCells.hpp"
#include "fluid_adapter/rigid/BodyIndicator.hpp"
#include "fluid_adapter/rigid/BodyLoads.hpp"
#include "fluid_adapter/rigid/BodyPartLoads.hpp"
#include "fluid_adapter/rigid/ImmersedWallDistance.hpp"
#include "fluid_adapter/rigid/RigidBody.hpp"
#include "fluid_adapter/rigid/RunawayLoadCheck.hpp"
#include "participant/FluidModel.hpp"

#include <filesystem>
#include <memory>

namespace fsi::fluid {

/// Wall times of the last step of the flow (s), on this rank.
struct FlowStepTimings {
  double penalization_s = 0.0; ///< rigid bodies: chi and u_rib update (Eq. 10), immersed wall distance
  double fluid_solve_s = 0.0;  ///< the PIMPLE step (with turbulence, writing, function objects)
  double loads_s = 0.0;        ///< rigid bodies: the penalization force and the loads (sums over ranks)
};

/// The cells a moving sharp body switches in the last step, over all ranks: newly covered ones
/// (chi 0 -> > 0) have their water set to the body's velocity at once, which destroys the kinetic
/// energy of the difference, 1/2 rho V |u - u_rib|^2: a dissipation of the immersed boundary,
/// not of the flow, that a body-fitted mesh does not have. A blade sliding along its own
/// surface switches its whole staircase each time it advances by a cell.
struct PenalizationSwitching {
  double cells_switched_on = 0.0;  ///< newly covered cells
  double cells_switched_off = 0.0; ///< newly uncovered cells
  double power_w = 0.0;            ///< the kinetic energy destroyed in the newly covered cells over dt (W)
  /// After the step: the water crossing into penalized cells through their faces with free ones
  /// (m^3/s) and the kinetic energy per second destroyed there (W): FoamFlow::immersed_transpiration.
  double transpiration_m3_per_s = 0.0;
  double transpiration_power_w = 0.0;
  /// The rate of change of the kinetic energy of the fluid the bodies hold, sum rho V u_rib .
  /// ddt(u) over the cells inside a body at both ends of the step (W): the inertia left out of
  /// their loads. A body turning at omega about its axis: its torque is this over omega.
  double held_fluid_power_w = 0.0;
};

class OpenFoamFluidModel final : public participant::FluidModel {
public:
  OpenFoamFluidModel(const OpenFoamConfig &config, FoamFlow &flow,
                     std::vector<std::unique_ptr<rigid::RigidBody>> rigid_bodies = {});

  std::string describe() const override;
  void start(const participant::RunPlan &plan) override;
  void interpolate(double time_s, participant::PointsView x_m, participant::MutablePointsView u_m_per_s) override;
  void advance(const participant::FluidStep &step, participant::PointsView force_density_n_per_measure,
               std::vector<participant::BodyLoad> &loads) override;
  /// The next advance spreads at these points (the coupling law two_point_sets): a second
  /// kernel stencil, built on every rank.
  void spread_at(participant::PointsView x_m) override;
  /// Idle points (structures out of the scene) get no kernel pairs on any rank: no nearest-cell
  /// query, no interpolation (U_ib = 0), nothing spread.
  void set_idle_points(const std::vector<bool> &idle) override;
  /// Implicit coupling: every rank keeps its fields before a step, and puts them back.
  void save_step_start() override;
  void restore_step_start() override;
  void finish(const participant::RunEnd &end) override;
  /// Checkpoints (serial runs): the fields of the current time, written and copied into the set
  /// of step n in `checkpoints_root_` (FoamCheckpoint).
  checkpoint::CheckpointPart write_checkpoint(long n_completed) override;
  /// The restart was prepared before OpenFOAM started (the case starts from the checkpoint's
  /// time folder): the coupler's step and checksum must be that checkpoint's.
  void resume(long step, const std::string &checksum) override;
  /// Where checkpoints go (<output>/checkpoints), and the step whose fields this run started
  /// from (0: not a restart). Without it the model does not checkpoint.
  void set_checkpoints(std::filesystem::path root, long restart_step);
  /// The flow alone (no coupler; every rank calls it at the same step): every rank writes its
  /// fields, then the master copies them into the set of step n and returns the part (the other
  /// ranks: an empty part).
  checkpoint::CheckpointPart checkpoint_on_every_rank(long n_completed);
  /// Says so (a warning) when its checkpoints cannot resume exactly: fields written in ascii.
  void warn_unless_checkpoints_exact() const;

  /// Ranks other than the master: serve the master's broadcasts until it finishes.
  void follow();

  /// The precursor run (no structure, no coupler): one step of the flow with its rigid bodies
  /// `step` from time_s to time_s + dt_s, collective over the ranks. Returns the rigid-body loads.
  std::vector<rigid::BodyLoad> advance_without_structure(long step, double time_s, double dt_s);
  /// The split of the last step's wall time (the flow alone, the pump's cost per revolution).
  const FlowStepTimings &last_step_timings() const { return timings_; }
  /// The cells the rigid bodies switched in the last step (collective over the ranks).
  const PenalizationSwitching &last_step_switching() const { return switching_; }
  /// From the next step on, the loads of each body with named parts (its STL's `solid NAME`
  /// blocks, at least two) are also split by part (BodyPartLoads). Call on every rank.
  void split_loads_by_part();
  /// Per body: its part names (empty for a body not split) and the last step's load of each.
  const std::vector<std::string> &part_names(std::size_t body) const;
  const std::vector<std::vector<rigid::BodyLoad>> &last_step_part_loads() const { return part_loads_; }
  /// Per body, per part: the share of its last step's load that the pressure on its staircase
  /// takes off the surface (each interface face's FoamFlow::interface_pressure_faces force less
  /// its component along the surface normal at the face centre's closest point): the form drag
  /// of the steps of a body the cells resolve as a staircase; none on a surface the faces fit.
  const std::vector<std::vector<rigid::BodyLoad>> &last_step_part_staircase_loads() const {
    return part_staircase_loads_;
  }

private:
  FlowStepTimings timings_;
  PenalizationSwitching switching_;
  long cut_off_steps_ = 0; ///< steps in which the bodies cut water off (FoamFlow::cut_off_cells), for the log
  enum class Command {
    start = 1,
    interpolate = 2,
    advance = 3,
    finish = 4,
    write_now = 5,
    spread_at = 6,
    save_step = 7,
    restore_step = 8,
    set_idle = 9
  };
  void broadcast(Command command, std::vector<double> &payload);
  /// The moving bodies' poses of a step (at t + dt), appended for the other ranks: their
  /// number, then per body its index and 18 values (rotation, origin, v_o, omega).
  void pack_rigid_poses(const std::vector<participant::BodyPose> &poses, std::vector<double> &out) const;
  /// Sets the bodies' coupled motions from such a block; returns the end of the block.
  const double *unpack_rigid_poses(double time_s, const double *begin, const double *end);
  void do_start(const std::vector<double> &point_measures);
  /// Every rank writes its fields now; returns once all have (a checkpoint copies them).
  void write_fields_on_every_rank();
  void do_interpolate(PointArray &u_m_per_s);
  /// The kernel stencil of Eq. (6) at positions_ (collective: widths and weight sums).
  void build_stencil();
  /// One step (`step`, ending at time_s + dt_s; -1 on the ranks other than 0). Throws
  /// std::runtime_error when the flow diverges or a body's load runs away.
  void do_advance(long step, double time_s, double dt_s, std::vector<rigid::BodyLoad> &loads);
  void step_flow(long step, double time_s, double dt_s, std::vector<rigid::BodyLoad> &loads);
  std::vector<std::string> body_names() const;
  /// Refuses a time step over PISO's measured limit for the case's viscous number (PisoLimit),
  /// and logs that number; again only for a larger time step.
  void check_time_step(double dt_s);
  void kernel_widths(Eigen::VectorXd &widths_m);
  /// Runs one collective operation over the ranks (broadcast, reduction), timing it.
  template <class Operation> void collective(const Operation &operation);
  /// With MPI (collective): every rank's time in the Lagrangian collectives and its skipped
  /// searches, logged by the master.
  void log_lagrangian_stats();
  void penalize_rigid_bodies(double time_s, double dt_s);
  /// The mesh carries the body's cells (a moving body on a moving mesh turns with them).
  bool carries_cells(std::size_t body) const;
  rigid::BodyLoad rigid_body_load(std::size_t body, double time_s);
  /// After the solve: body_load_density_, the penalization force less the inertia of the fluid
  /// in the held cells (inside a body at both ends of the step).
  void held_fluid_load_density();

  OpenFoamConfig config_;
  FoamFlow &flow_;
  std::filesystem::path checkpoints_root_;
  long restart_step_ = 0;
  ibm::EulerianCells cells_;
  /// Built at the first Lagrangian query after the cells moved (index()).
  std::unique_ptr<ibm::CellIndex> index_;
  const ibm::CellIndex &index();
  /// A moving mesh (FoamFlow::mesh_moves): after start_step, the cells where the flow put them.
  void follow_moving_mesh();
  /// A moving mesh: a static body's inside cells never move, and a moving body's cells stay
  /// where they were in its frame (its chi is kept: BodyIndicator, cells_move_with_body);
  /// otherwise common::UserError naming the body and what to fix. Collective.
  void check_bodies_on_moving_mesh(double time_s);
  std::vector<PointArray> static_inside_centres_m_; ///< per body: its inside cells' centres at the first step
  Eigen::VectorXd point_measures_;
  PointArray positions_, cell_velocity_, force_density_, acceleration_;
  std::unique_ptr<ibm::NearestCells> nearest_;
  std::unique_ptr<ibm::KernelStencil> stencil_;
  std::vector<bool> idle_points_; ///< empty: none idle
  std::vector<std::unique_ptr<rigid::RigidBody>> bodies_;
  rigid::RunawayLoadCheck runaway_loads_;
  double checked_dt_s_ = -1.0;
  std::vector<std::unique_ptr<rigid::BodyIndicator>> indicators_;
  std::vector<std::unique_ptr<rigid::BodyPartLoads>> part_splitters_; ///< per body; null: not split
  std::vector<std::vector<rigid::BodyLoad>> part_loads_;              ///< per body, per part
  std::vector<std::vector<rigid::BodyLoad>> part_staircase_loads_;    ///< per body, per part
  /// Per part of body b, the staircase share of its load (last_step_part_staircase_loads).
  std::vector<rigid::BodyLoad> staircase_loads(std::size_t b, double time_s, const Vec3 &centre);
  /// Each part's force and torque summed over the MPI ranks (collective).
  void sum_over_ranks(std::vector<rigid::BodyLoad> &parts) const;
  std::vector<InterfaceFace> interface_faces_; ///< scratch: FoamFlow::interface_pressure_faces
  PointArray staircase_, staircase_couple_;    ///< scratch: their off-normal part on the fluid (N/m^3, N m/m^3)
  std::vector<char> in_body_;                  ///< scratch: per cell, inside the body being split
  PointArray interior_pressure_, interior_couple_; ///< scratch: FoamFlow::interior_pressure_acceleration
  PointArray across_surface_;    ///< scratch: the penalization force less that pressure's (N/m^3)
  std::unique_ptr<rigid::ImmersedWallDistance> wall_distance_; ///< only with a wall-distance turbulence model
  Eigen::VectorXd penalization_rate_;
  PointArray rigid_velocity_, penalization_acceleration_, penalization_force_;
  Eigen::VectorXd rate_at_step_start_; ///< penalization_rate_ at save_step_start (a repeated step restores it)
  Eigen::VectorXd held_;          ///< per cell: 1 inside a body at both ends of this step, else 0
  PointArray cell_acceleration_;  ///< scratch: FoamFlow::cell_accelerations (m/s^2)
  PointArray body_load_density_;  ///< per cell: what the bodies' loads sum (N/m^3; held_fluid_load_density)
  std::vector<double> message_;
  /// Beyond this distance from a rank's cell centres no kernel reaches them (m; < 0 until
  /// the first interpolation computes it over the ranks).
  double skip_beyond_m_ = -1.0;
  double local_max_width_m_ = 0.0; ///< the largest cell size of this rank (m)
  struct LagrangianStats {
    double collectives_s = 0.0;     ///< wall time in broadcasts and reductions (MPI only)
    std::size_t interpolations = 0; ///< steps (interpolation requests) served
    std::size_t points_seen = 0, points_skipped = 0;
  } lagrangian_stats_;
};

} // namespace fsi::fluid
