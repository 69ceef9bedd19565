#pragma once
// The interpolation that Sec. 2.3 names for U_ib: "linear interpolation from the velocity
// value at the closest cell center", u(X) = u_c + grad(u)_c (X - x_c), with c the cell whose
// centre is nearest to X and the cell-centre gradient supplied by the caller.
//
// Gradient layout: row c holds the Jacobian J_ij = d u_i / d x_j row-major
// (J_xx J_xy J_xz J_yx ...), in 1/s. OpenFOAM's fvc::grad(U) is the transpose
// ((grad U)_ij = d u_j / d x_i): copy it with T.T() (or component (j, i)).
// Exact for linear fields on any mesh; error O(h^2) for smooth fields with an exact gradient.

#include "fluid_adapter/ibm/NearestCells.hpp"

namespace fsi::fluid::ibm {

/// n_cells x 9, row-major Jacobian per cell (see above).
using CellGradientArray = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>;

class ClosestCellLinear {
public:
  /// Borrows cells and nearest (built from the same points), which must outlive this object.
  ClosestCellLinear(const EulerianCells &cells, const NearestCells &nearest);

  /// U at every point (n x 3, m/s). Points owned by another rank get zero, so the results
  /// of all ranks add up to the full interpolation.
  PointArray interpolate(const PointArray &points_m, const PointArray &cell_velocity_m_per_s,
                         const CellGradientArray &cell_velocity_gradient_per_s) const;

private:
  const EulerianCells &cells_;
  const NearestCells &nearest_;
};

} // namespace fsi::fluid::ibm
