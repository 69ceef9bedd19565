#pragma once
// The characteristic function chi of Eq. (10) and the body velocity u_rib of Eq. (9) at the
// cell centres of a fluid mesh, for one rigid body, updated every time step.
//
// Once per mesh (constructor): the candidate cells are those whose centre lies in the
// body's SweptRegion (its bounding box if static, the solid of revolution its surface sweeps
// about a rotation axis); their centres are packed contiguously. Every step (update(t)):
// only the candidate centres are mapped into the body frame, x_body = pose(t)^-1 x_world,
// and tested against the body-frame surface built once (RigidBody: a voxel classification
// answers points far from the surface with one look-up, a few exact point-triangle distances
// and a pseudo-normal or CGAL's Side_of_triangle_mesh answer the others), in parallel.
// A static body is evaluated once. Cells outside the candidate set keep chi = 0, u_rib = 0.
//
// Sampling:
//   * sharp (default, the paper's Eq. 10): chi = 1 if the centre is strictly inside, else 0.
//     The volume sum(chi V) converges at first order in the cell size.
//   * cell_fraction: each cell is taken as the world-aligned cube of edge cell_size_m about
//     its centre. If its centre and 8 corners are not all on one side of the surface (a cut
//     cell), chi = fraction of a regular lattice of n^3 sub-points inside the body; otherwise
//     chi is the centre's 0 or 1. A volume-fraction estimate that smooths the staircase
//     (for a static body on cubic cells, exactly the sharp indicator of the n-times finer
//     grid averaged back); it needs cell sizes and costs 9 inside tests per
//     candidate plus n^3 per cut cell. A feature thinner than a cell that misses all 9 probes
//     is seen as by the sharp indicator.
//   * inside_smoothed: chi ramps from 0 at the surface to 1 at a depth of smoothing_depth_cells
//     cell sizes inside it, chi = min(1, d / (n h)) for a centre strictly inside at distance d
//     from the surface, and 0 for every centre outside: the body never grows (a smoothing
//     centred on the surface does, and raises a cylinder's C_D by 15-30 %). Meant to switch a
//     cell that a moving body sweeps over on over n h of travel instead of at once; but with a
//     penalization time tau much below dt, any chi above tau / dt already holds the cell to the
//     body within a step, so the ramp is nearly sharp in effect: measured 13.4 -> 12.2 (n = 1)
//     and 11.7 (n = 2) GAMG iterations per step for a spinning torus (./fsi bench fluid, rows c,
//     c1, c2), C_D of a cylinder unchanged. Costs one closest-point query per inside candidate
//     within n h of the surface (the others are 1 at once); needs cell sizes.

#include "common/Types.hpp"
#include "fluid_adapter/rigid/RigidBody.hpp"
#include "fluid_adapter/rigid/RigidVelocity.hpp"
#include "fluid_adapter/rigid/SweptRegion.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsi::fluid::rigid {

struct IndicatorOptions {
  enum class Sampling { sharp, cell_fraction, inside_smoothed };
  Sampling sampling = Sampling::sharp;
  int samples_per_direction = 4;       ///< cell_fraction only: n (n^3 sub-points per cut cell), >= 2
  double smoothing_depth_cells = 1.0;  ///< inside_smoothed only: n (> 0), depth of the ramp in cell sizes
  std::size_t n_threads = 0;     ///< 0: the hardware concurrency; 1 inside an MPI rank
  /// The cells move with the body (a moving mesh's rotor zone turning with it): chi is evaluated
  /// once and kept (a centre within round-off of the surface cannot flip), u_rib follows the
  /// cells, and each update measures how far the cells drifted from the body (carried_drift_m).
  bool cells_move_with_body = false;
};

class BodyIndicator {
public:
  /// `body` is borrowed and must outlive the indicator. `cell_sizes_m` (edge of the cube of
  /// the cell's volume, e.g. cbrt(V)) is required for cell_fraction and inside_smoothed.
  BodyIndicator(const RigidBody &body, const PointArray &cell_centres_m,
                IndicatorOptions options = {}, const Eigen::VectorXd &cell_sizes_m = {});

  /// Recomputes chi and u_rib for time t (a static body only on the first call).
  void update(double time_s);
  /// The mesh moved (a rotor's cell zone turning with the body): the candidates' centres are
  /// read again from the same cells. The candidate set stays: a cell carried by the body's own
  /// rotation stays in the region it sweeps. A static body keeps its chi (its cells must not move).
  void move_cells(const PointArray &cell_centres_m);

  /// chi per cell, in [0, 1] (0 or 1 when sharp).
  const Eigen::VectorXd &chi() const { return chi_; }
  /// u_rib (m/s) per cell; set at candidate cells, 0 elsewhere.
  const PointArray &body_velocity_m_per_s() const { return velocity_m_per_s_; }
  /// Cells with chi > 0 after the last update (ascending).
  const std::vector<std::int32_t> &inside_cells() const { return inside_cells_; }
  /// Cells that can ever have chi > 0 (ascending).
  const std::vector<std::int32_t> &candidate_cells() const { return candidate_cells_; }
  /// cells_move_with_body: the largest distance, in the body frame, between a candidate's
  /// centre at the last update and where it was at the first (m): 0 up to round-off when the
  /// mesh moves as the body does.
  double carried_drift_m() const { return carried_drift_m_; }
  /// v_o and omega of the last update.
  const RigidVelocity &rigid_velocity() const { return rigid_velocity_; }
  const SweptRegion &swept_region() const { return region_; }
  const RigidBody &body() const { return body_; }
  std::size_t n_cells() const { return static_cast<std::size_t>(chi_.size()); }

private:
  double sharp_value(const Vec3 &centre_body_m) const;
  double fraction_value(const Eigen::Isometry3d &world_to_body, const Vec3 &centre_body_m,
                        double cell_size_m) const;
  double smoothed_value(const Vec3 &centre_body_m, double cell_size_m) const;
  bool needs_sizes() const { return options_.sampling != IndicatorOptions::Sampling::sharp; }

  const RigidBody &body_;
  IndicatorOptions options_;
  SweptRegion region_;
  std::vector<std::int32_t> candidate_cells_;
  PointArray candidate_centres_m_;         ///< packed world centres of the candidates
  Eigen::VectorXd candidate_sizes_m_;      ///< cell_fraction and inside_smoothed only
  Eigen::VectorXd candidate_chi_;          ///< per candidate, last update
  std::vector<std::int32_t> inside_cells_;
  Eigen::VectorXd chi_;
  PointArray velocity_m_per_s_;
  RigidVelocity rigid_velocity_;
  bool evaluated_ = false;
  PointArray first_body_centres_m_; ///< cells_move_with_body: the candidates in the body frame at the first update
  double carried_drift_m_ = 0.0;
  void follow_carried_cells(const Eigen::Isometry3d &world_to_body);
};

} // namespace fsi::fluid::rigid
