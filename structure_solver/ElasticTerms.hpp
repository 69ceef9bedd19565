#pragma once
// The discrete elastic energy of a sheet or filament and its derivatives (section 2.2).
//
// Continuous model (Eq. 3 with a constant bending rigidity, see the paper file's header):
//   E = phi/4 * int sum_ij (T_ij - T0_ij)^2 dA  +  zeta/2 * int sum_ij |d2X/ds_i ds_j|^2 dA,
//   T_ij = X_i . X_j,  sigma_ij = phi (T_ij - T0_ij),
// whose variation is the force density of Eq. (3):
//   -dE/dX = sum_ij d_i(sigma_ij d_j X) - zeta (X_1111 + 2 X_1122 + X_2222).
// Discretisation on the staggered grid: T_11 and T_22 (stretching) at edge mid-points, T_12
// (shearing) and X_12 (twisting) at cell centres, X_11 and X_22 (bending) at the points.
// Each term is a small stencil; the energy is a weighted sum over stencils, so the discrete
// force is exactly -grad E (energy-consistent, symmetric system matrix) and the free-edge
// conditions come out as the natural boundary conditions. Clamped edges add ghost points
// X_ghost = X_inner -/+ 2 ds t, t the prescribed tangent, folded into a constant c.

#include "BoundaryConditions.hpp"
#include "CompressionResponse.hpp"
#include "LagrangianGrid.hpp"
#include "common/Types.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace fsi::structure {

/// Stretching along one grid edge: T = |X_b - X_a|^2 / ds^2.
struct TensionTerm {
  int a, b;
  double inv_ds_squared;
  double rest_value; ///< T0 from the initial shape
  double measure;    ///< edge length or edge area
};

/// Shearing in one cell: T_12 = a . b with a = dX/ds1 and b = dX/ds2 at the cell centre.
struct ShearTerm {
  std::array<int, 4> points;    ///< (i,j), (i+1,j), (i,j+1), (i+1,j+1)
  std::array<double, 4> coef_a; ///< a = sum coef_a[k] X_k
  std::array<double, 4> coef_b;
  double rest_value;
  double measure;

  /// a = dX/ds1 and b = dX/ds2 at the cell centre, for positions x.
  void tangents(const PointArray &x, Vec3 &a, Vec3 &b) const {
    a = Vec3::Zero(), b = Vec3::Zero();
    for (int p = 0; p < 4; ++p) {
      a += coef_a[p] * x.row(points[p]).transpose();
      b += coef_b[p] * x.row(points[p]).transpose();
    }
  }
};

/// Bending or twisting: D = sum coef[k] X_k + R(t) ghost_body - rest, energy zeta/2 w |D|^2.
struct BendingTerm {
  std::array<int, 4> points{};
  std::array<double, 4> coef{};
  int n_points = 0;
  double weight = 0.0;          ///< measure (x 2 for the twisting term X_12)
  Vec3 ghost_body = Vec3::Zero(); ///< constant from a clamped edge's ghost point (rotates with the clamp)
  Vec3 rest = Vec3::Zero();       ///< rest value (pre-curvature), zero for a flat rest state
};

struct ElasticEnergy {
  double tension_j = 0.0;
  double bending_j = 0.0;
  double total() const { return tension_j + bending_j; }
};

class ElasticTerms {
public:
  /// Builds all stencils for `grid` with conditions `bc`; rest lengths from `initial_m`.
  /// With `curved_rest_state`, the bending rest values are those of the initial shape.
  /// `compression` says whether compressed edges push back (elastic) or go slack.
  ElasticTerms(const LagrangianGrid &grid, const EdgeConditions &bc, const PointArray &initial_m,
               double tension_coefficient, double bending_rigidity, bool curved_rest_state,
               CompressionResponse compression = CompressionResponse::elastic);

  ElasticEnergy energy(const PointArray &x, const Eigen::Matrix3d &clamp_rotation) const;
  /// Adds -grad E at x to `forces` (N, one row per point).
  void add_forces(const PointArray &x, const Eigen::Matrix3d &clamp_rotation, PointArray &forces) const;
  /// Largest edge stretch |dX/ds| / |dX0/ds| over all edges.
  double max_stretch_ratio(const PointArray &x) const;
  /// Index of the point at the more stretched end of the most stretched edge.
  int most_stretched_point(const PointArray &x) const;

  /// Stretching tension phi (T - T0) of an edge; zero in compression when slack.
  double sigma(const TensionTerm &t, const PointArray &x) const;
  /// d sigma / d T of an edge at x: phi, or zero for a slack edge in compression.
  double tension_stiffness(const TensionTerm &t, const PointArray &x) const;
  double sigma(const ShearTerm &t, const PointArray &x) const;
  Vec3 bending_value(const BendingTerm &t, const PointArray &x, const Eigen::Matrix3d &clamp_rotation) const;

  const std::vector<TensionTerm> &tension() const { return tension_; }
  const std::vector<ShearTerm> &shear() const { return shear_; }
  const std::vector<BendingTerm> &bending() const { return bending_; }
  double tension_coefficient() const { return phi_; }
  double bending_rigidity() const { return zeta_; }

private:
  void add_tension_terms(const LagrangianGrid &grid, const PointArray &x0);
  void add_shear_terms(const LagrangianGrid &grid, const PointArray &x0);
  void add_bending_terms(const LagrangianGrid &grid, const EdgeConditions &bc, const PointArray &x0);
  void add_bending_line(const LagrangianGrid &grid, bool along_1, int line, EdgeCondition at_min,
                        EdgeCondition at_max, const PointArray &x0);
  void add_twist_terms(const LagrangianGrid &grid);

  double phi_, zeta_;
  CompressionResponse compression_;
  std::vector<TensionTerm> tension_;
  std::vector<ShearTerm> shear_;
  std::vector<BendingTerm> bending_;
};

} // namespace fsi::structure
