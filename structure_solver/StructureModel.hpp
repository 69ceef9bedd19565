#pragma once
// The interface every structure model implements (membrane, filament, ...). A model owns its
// Lagrangian points and advances them one time step given nodal loads; the scene applies
// collisions (Eq. 11) through correct_positions().

#include "checkpoint/StateArchive.hpp"
#include "common/Types.hpp"

#include <functional>
#include <string>

namespace fsi::structure {

struct StructureEnergy {
  double kinetic_j = 0.0;
  double elastic_j = 0.0;   ///< tension + bending
  double potential_j = 0.0; ///< gravitational, -sum m g.X
  double total() const { return kinetic_j + elastic_j + potential_j; }
};

class StructureModel {
public:
  virtual ~StructureModel() = default;

  virtual const std::string &name() const = 0;
  /// Registry name of the model ("membrane", "filament").
  virtual std::string model() const = 0;
  /// Grid shape (n1, n2); n2 == 1 for filaments. Points are row-major over (s1, s2).
  virtual std::pair<int, int> grid_shape() const = 0;
  int n_points() const { return grid_shape().first * grid_shape().second; }

  virtual double time_s() const = 0;
  virtual const PointArray &positions_m() const = 0;
  virtual const PointArray &velocities_m_per_s() const = 0;
  /// Measure (area m^2 or length m) carried by each point: force density x measure = force.
  virtual const Eigen::VectorXd &point_measures() const = 0;
  /// rho_1: mass per unit area (kg/m^2) of a sheet, per unit length (kg/m) of a filament.
  virtual double mass_per_measure() const = 0;
  /// Smallest Lagrangian spacing Delta s (m), for the rule Delta s / Delta t >= 100 m/s.
  virtual double lagrangian_spacing_m() const = 0;
  /// Speed of stretching waves, sqrt(2 phi / rho_1) (m/s). The tension coefficients are
  /// frozen at X^n in Eq. (4), so stretching is explicit: the step is stable for about
  /// Delta s / Delta t >= this speed (measured: see the closing note of issue 2).
  virtual double tension_wave_speed_m_per_s() const = 0;
  /// False when stretching is implicit (solver.tension: stabilized): no stretching-wave limit.
  virtual bool explicit_stretching() const { return true; }

  /// Advances to t + dt under gravity and the given load density (force per unit measure,
  /// N/m^2 or N/m; e.g. -F_fsi of Eq. 3). Returns linear-solver iterations (diagnostics).
  virtual int advance(const PointArray &load_density) = 0;

  /// Applies a position correction (collisions, Eq. 11) to X^{n+1}; prescribed points stay.
  virtual void correct_positions(const std::function<void(PointArray &)> &correction) = 0;

  /// Frees what only advancing needs (the step's matrices and factorisation): a structure gone
  /// from the scene keeps its state, energy and stretch for the output, and is never advanced
  /// again (advance() then throws std::logic_error).
  virtual void retire() = 0;
  virtual bool retired() const = 0;

  /// Puts the model back to a saved state (positions and velocities at the current time);
  /// used to write the last good state after a divergence.
  virtual void restore_state(const PointArray &x_m, const PointArray &v_m_per_s, double time_s) = 0;

  /// Puts everything the next step depends on (for Eq. 4: X^n, X^{n-1}, V^n and the time, bit
  /// for bit) into `archive` under `prefix` ("structures/<name>/"), for an exact restart.
  virtual void save_state(checkpoint::StateArchive &archive, const std::string &prefix) const = 0;
  /// Takes the state save_state() wrote; throws checkpoint::CheckpointError naming the entry when
  /// one is missing or of another size (a checkpoint of another grid).
  virtual void load_state(const checkpoint::StateArchive &archive, const std::string &prefix) = 0;

  virtual StructureEnergy energy() const = 0;
  virtual double max_stretch_ratio() const = 0;
  /// The configured guard: the run stops when max_stretch_ratio() exceeds it.
  virtual double stretch_limit() const = 0;
  /// The second guard: the run stops when a point moves faster than this (a runaway that
  /// barely stretches the structure, e.g. beyond the stability limit of the penalty law).
  virtual double speed_limit_m_per_s() const = 0;
  /// Index of the point that best explains a divergence (non-finite or most stretched).
  virtual int worst_point() const = 0;
  /// "(i1, i2) = (3, 7)": a point's grid coordinates, for messages.
  virtual std::string describe_point(int index) const = 0;
};

} // namespace fsi::structure
