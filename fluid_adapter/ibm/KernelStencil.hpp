#pragma once
// The (cell, weight) pairs that couple each Lagrangian point X_k to the Eulerian cells in
// its kernel support, w_kc = delta_h(x_c - X_k) V_c (dimensionless; Eq. 6 with the point's
// kernel width h). Built once per time step and used by both transfers of Sec. 2.3, which are
// therefore adjoint (sum_c f_c.u_c V_c = sum_k F_k dA_k.U_k up to round-off):
//   spread (Eq. 8):  f(x_c) = sum_k F_k dA_k delta_h(x_c - X_k) = sum_k F_k dA_k w_kc / V_c
//   interpolate:     U(X_k) = sum_c u_c delta_h(x_c - X_k) V_c = sum_c w_kc u_c
//
// Sums of the weights. On a uniform mesh away from boundaries sum_c w_kc = 1 and
// sum_c w_kc (x_c - X_k) = 0 exactly (the moment conditions of Eq. 7): spreading conserves
// force and torque, interpolation reproduces linear fields. Where the support is cut by a
// boundary the sum is below 1 (force is lost, velocities are biased towards zero); on graded
// or anisotropic cells (h = cbrt(V) differs from the spacing along an axis) it differs from 1
// by an amount that does not shrink with refinement. normalise_weights() divides the
// weights by their sum: spreading then conserves force and interpolation reproduces
// constants on any mesh, and the two stay adjoint.
//
// Decomposed meshes: built on one rank's cells, the stencil holds that rank's pairs only;
// interpolate() and weight_sums() are partial sums to add over ranks, and spread() writes
// the rank's own cells. All ranks must use the same kernel widths (see NearestCells).

#include "fluid_adapter/ibm/CellIndex.hpp"

#include <cstddef>
#include <vector>

namespace fsi::fluid::ibm {

class KernelStencil {
public:
  /// points_m: n x 3 (m); kernel_width_m: h of each point (m, > 0), the same on all ranks.
  /// Borrows index.cells(), which must outlive the stencil. Throws std::invalid_argument
  /// when the sizes differ or a width is not positive and finite.
  KernelStencil(const CellIndex &index, const PointArray &points_m, const Eigen::VectorXd &kernel_width_m);
  /// The stencil of new points and widths on the same mesh (the next time step), reusing the
  /// arrays' memory. Same checks as the constructor; std::invalid_argument for another index's mesh.
  /// Points marked in `skip` (empty: none; else one flag per point) get no pairs, whatever their
  /// width: a structure out of the scene costs nothing, interpolates zero and spreads nothing.
  void rebuild(const CellIndex &index, const PointArray &points_m, const Eigen::VectorXd &kernel_width_m,
               const std::vector<bool> &skip = {});

  Eigen::Index n_points() const { return static_cast<Eigen::Index>(offsets_.size()) - 1; }
  std::size_t n_pairs() const { return cells_of_pairs_.size(); }
  /// Pairs of point k are [offsets()[k], offsets()[k + 1]) in cells() and weights().
  const std::vector<std::size_t> &offsets() const { return offsets_; }
  const std::vector<CellId> &cells() const { return cells_of_pairs_; }
  const std::vector<double> &weights() const { return weights_; }

  /// sum_c w_kc over this rank's cells, per point.
  Eigen::VectorXd weight_sums() const;
  /// Divides the weights of each point by total_weight_sums (weight_sums() added over all
  /// ranks). Points whose total is zero (no cell in reach) keep zero weights.
  void normalise_weights(const Eigen::VectorXd &total_weight_sums);

  /// Eq. 8 from point forces F_k dA_k (N, n x 3): returns the force density on this rank's
  /// cells (N/m^3, n_cells x 3).
  PointArray spread_point_forces(const PointArray &point_forces_n) const;
  /// Eq. 8 from force densities and point measures: F_k (n x 3) times dA_k (n) must be a
  /// force in N: N/m^2 and m^2 for a sheet, N/m and m for a filament.
  PointArray spread(const PointArray &force_density_n_per_measure, const Eigen::VectorXd &point_measure) const;
  /// U(X_k) = sum_c w_kc u_c for every point (n x 3) from cell values (n_cells x 3); any
  /// cell field works, velocities in m/s give m/s.
  PointArray interpolate(const PointArray &cell_velocity_m_per_s) const;

private:
  /// Appends the pairs of one point.
  void add_point(const CellIndex &index, const Vec3 &point_m, double width_m, std::vector<CellId> &found);

  const EulerianCells &mesh_;
  std::vector<std::size_t> offsets_;
  std::vector<CellId> cells_of_pairs_;
  std::vector<double> weights_;
  std::vector<CellId> found_; ///< one point's cells in reach, kept from point to point
};

} // namespace fsi::fluid::ibm
