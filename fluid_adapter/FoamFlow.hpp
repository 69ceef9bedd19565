#pragma once
// The OpenFOAM flow solver as the rest of the code sees it: no OpenFOAM header here. The
// implementation (solver/, OpenFoamFlow.H) is the only code that includes OpenFOAM:
// a PIMPLE step of pimpleFoam (v1912) with an extra momentum source, the FSI acceleration.

#include "common/Types.hpp"
#include "fluid_adapter/PisoLimit.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fsi::fluid {

struct FoamFlowSettings {
  std::filesystem::path case_directory; ///< prepared OpenFOAM case (mesh present)
  double time_step_s = 1e-4;
  double end_time_s = 1.0;
  bool parallel = false; ///< started by mpirun on a decomposed case (processor*/ folders)
};

/// A face between a penalized cell and a free one, with the free water's pressure force on it.
struct InterfaceFace {
  long body_cell = -1;        ///< this rank's penalized cell
  Vec3 centre_m;              ///< the face centre
  Vec3 pressure_m4_per_s2;    ///< -p S (p kinematic, the free cell's; S out of the body cell): times rho, N
};

class FoamFlow {
public:
  /// Reads the mesh and fields at the case's start time; throws std::runtime_error (with
  /// OpenFOAM's message) when the case is unusable.
  static std::unique_ptr<FoamFlow> create(const FoamFlowSettings &settings);
  /// The process's exit, to call with main's exit code once every flow is destroyed: under
  /// MPI it ends OpenFOAM's parallel run (and does not return); otherwise returns the code.
  static int end_process(int exit_code);
  virtual ~FoamFlow() = default;

  virtual std::string describe() const = 0;
  virtual const PointArray &cell_centres_m() const = 0;
  virtual const Eigen::VectorXd &cell_volumes_m3() const = 0;
  /// Cell-centre velocities (m/s), N_cells x 3.
  virtual void cell_velocities(PointArray &u_m_per_s) const = 0;
  /// After advance(): each cell's discrete velocity derivative in time as the ddt scheme makes
  /// it, on the cells as they moved (fvc::ddt(U), m/s^2), N_cells x 3.
  virtual void cell_accelerations(PointArray &a_m_per_s2) const = 0;
  /// Cell-centre velocity gradients, N_cells x 9, row-major J_ij = du_i / dx_j (1/s).
  virtual void cell_velocity_gradients(Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> &grad) const = 0;
  /// The FSI source of the next step, per unit mass (f_fsi / rho_f, m/s^2), N_cells x 3.
  virtual void set_fsi_acceleration(const PointArray &a_m_per_s2) = 0;
  /// Penalization of rigid bodies (Eqs. 9-10), implicit in the momentum matrix: per cell the
  /// rate chi / tau (1/s, 0 outside bodies) and the body velocity u_rib (m/s). Until this is
  /// called the momentum equation has no penalization term at all.
  virtual void set_penalization(const Eigen::VectorXd &rate_per_s, const PointArray &u_rib_m_per_s) = 0;
  /// The rate chi / tau (1/s) per cell as the fields the flow started from hold it (a restart's
  /// set: that of its last step); empty when they have none.
  virtual const Eigen::VectorXd &penalization_rate_at_start() const = 0;
  /// After advance(): the penalization source per unit density, -rate (u - u_rib) (m/s^2).
  virtual void penalization_acceleration(PointArray &a_m_per_s2) const = 0;
  /// Per penalized cell, the part of its pressure gradient that its faces with other penalized
  /// cells make, sum p_f S_f / V over those faces (m/s^2, p kinematic, p_f the linear face
  /// value); 0 elsewhere. Over a body it cancels face by face; cell by cell it is the pressure
  /// inside the body (solved, or extrapolated into holes), which a load split by part takes off
  /// each cell before giving it to the part of the surface closest to it. `couple_m2_per_s2`:
  /// per cell, sum (x_f - x_c) x (+-p_f S_f) / V, the torque (per unit density and volume) of
  /// moving those face forces to the cell centre, so that the torques cancel too.
  virtual void interior_pressure_acceleration(PointArray &a_m_per_s2, PointArray &couple_m2_per_s2) const = 0;
  /// This rank's faces between penalized and free cells (those of its processor patches on the
  /// body's side), each with the free water's pressure force on it, the face's pressure the free
  /// cell's (as pressure_gradient takes it). Its part off a body's surface normal is the pressure
  /// the steps of a staircase take.
  virtual void interface_pressure_faces(std::vector<InterfaceFace> &faces) const = 0;
  /// InterfaceFlux::body_normal: per cell the velocity whose flux the faces of a penalized cell
  /// with free cells carry (m/s: the body velocity's component along its surface normal); the
  /// penalized cells become holes of the pressure equation (their pressure extrapolated from the
  /// free neighbours). Until called, the faces carry the solver's interpolated flux.
  virtual void set_interface_velocity(const PointArray &u_m_per_s) = 0;
  /// After advance(): the water crossing into penalized cells through the faces they share with
  /// free cells (m^3/s, from phi; this rank's internal faces), and the kinetic energy per
  /// second destroyed as the penalization sets it to the body's velocity, 1/2 sum |phi_in|
  /// |u_free - u_rib|^2 (m^5/s^3: times rho, W). A staircase body whose velocity is not along
  /// its faces (a blade turning along itself) swallows and returns water all over its surface.
  virtual void immersed_transpiration(double &inflow_m3_per_s, double &power_per_density) const = 0;
  /// After advance(): the free cells (over every rank) that the bodies and walls cut off from
  /// every open boundary and from the pressure reference in that step, whose pressure was held
  /// (InterfaceFlux::body_normal; 0 otherwise).
  virtual long cut_off_cells() const = 0;
  /// True when the turbulence model uses the wall distance (Spalart-Allmaras RAS/DES/DDES).
  virtual bool uses_wall_distance() const = 0;
  /// Immersed rigid bodies as walls for the turbulence model (section 2.6): the wall distance
  /// becomes min(distance to the mesh's walls, wall_distance_m) per cell (+inf: unchanged),
  /// and after each turbulence update nuTilda and nut are set to 0 in cells with
  /// inside_fraction >= 0.5 (the condition nuTilda = 0 at immersed walls). Laminar: no effect.
  virtual void set_immersed_walls(const Eigen::VectorXd &wall_distance_m, const Eigen::VectorXd &inside_fraction) = 0;
  /// The immersed walls' shear by Spalding's law (OpenFoamConfig::immersed_wall_model): each
  /// momentum equation adds, on every face between a penalized and a free cell, the viscosity
  /// that makes the face's viscous flux the law's wall shear for the free cell's velocity
  /// relative to the body's, tangential to the face, at the free cell's distance to the
  /// immersed surface (set_immersed_walls, which must then be given that distance).
  virtual void use_immersed_wall_function(bool on) = 0;
  /// A k-omega model's omega and production G held in the free cells next to the immersed
  /// walls as omegaWallFunction holds them next to mesh walls (ImmersedWallOmega), from the free
  /// cell's distance to the immersed surface (set_immersed_walls). Returns whether it does: a
  /// model without omega does not, and throws common::UserError when `required`.
  virtual bool use_immersed_omega_wall_function(bool required) = 0;
  /// The PIMPLE settings of system/fvSolution that decide the time-step limit (PisoLimit).
  virtual PisoSettings piso_settings() const = 0;
  /// The largest viscous number nu_eff dt sum 1/dx^2 over the cells of every rank (collective).
  virtual ViscousNumber max_viscous_number(double dt_s) const = 0;
  /// The mesh moves (the case has a constant/dynamicMeshDict: a cell zone turning with a rotor
  /// behind an AMI, pimpleFoam's solidBody motion). Its cells move at every start_step().
  virtual bool mesh_moves() const = 0;
  /// Starts the next time step of dt: the time advances to its end and a moving mesh moves
  /// there, so that cell_centres_m() are the centres at the step's end, where the rigid bodies
  /// are penalized (Eqs. 9-10). Then advance() solves the step.
  virtual void start_step(double dt_s) = 0;
  /// One PIMPLE time step of dt (started by start_step, or here if it was not); writes fields at
  /// the case's write interval. On failure the state of the step's start is put back (a moving
  /// mesh's points too) and std::runtime_error names the step, the cell and the likely cause.
  virtual void advance(double dt_s) = 0;
  /// Implicit coupling (collective): keeps every field's values and the time before a step,
  /// and puts them back so that the next advance() repeats that step. The old-time fields are
  /// not copied: the first advance of the step shifted them, and a repeat at the same time
  /// index does not shift them again.
  /// Not on a moving mesh (the mesh would have to move back too): std::runtime_error.
  virtual void save_step_start() = 0;
  virtual void restore_step_start() = 0;
  virtual double time_s() const = 0;
  /// Writes the current fields now (end of run, last good state, a checkpoint).
  virtual void write_now() = 0;
  /// The name of the current time's folder ("0.07").
  virtual std::string time_name() const = 0;
  /// Whether it writes its fields in binary (system/controlDict's writeFormat): exactly, so that
  /// a checkpoint resumes bit for bit; ascii keeps writePrecision digits.
  virtual bool writes_binary() const = 0;
  /// The OpenFOAM case folder it runs in.
  virtual std::filesystem::path case_directory() const = 0;

  // MPI (OpenFOAM's Pstream): this rank, the number of ranks, and the collective operations
  // the immersed boundary needs. Serial runs: rank 0 of 1, and the operations do nothing.
  virtual int rank() const = 0;
  virtual int n_ranks() const = 0;
  /// The master's data on every rank (resized to the master's size).
  virtual void broadcast_from_master(std::vector<double> &data) const = 0;
  /// Element-wise sum / minimum over the ranks, on every rank.
  virtual void sum_over_ranks(double *data, std::size_t n) const = 0;
  virtual void min_over_ranks(double *data, std::size_t n) const = 0;
};

} // namespace fsi::fluid
