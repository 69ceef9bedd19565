#pragma once
// The uniform structured Lagrangian grid of a sheet (n1 x n2 points over (s1, s2)) or of a
// filament (n2 == 1). Points are ordered row-major over (s1, s2): index = i1 * n2 + i2.
// Points sit on the edges of the material domain [0, L1] x [0, L2], so each point carries
// the trapezoidal share of the domain (its "measure": an area for a sheet, a length for a
// filament), and the masses and load integrals below are exact for piecewise-linear fields.

#include <Eigen/Core>

namespace fsi::structure {

class LagrangianGrid {
public:
  /// A sheet: n1 x n2 points over lengths (L1, L2); a filament: n2 == 1, length_2 ignored.
  LagrangianGrid(int n1, int n2, double length_1_m, double length_2_m);

  int n1() const { return n1_; }
  int n2() const { return n2_; }
  int n_points() const { return n1_ * n2_; }
  bool is_filament() const { return n2_ == 1; }
  int index(int i1, int i2) const { return i1 * n2_ + i2; }
  double ds1() const { return ds1_; }
  double ds2() const { return ds2_; }
  /// Smallest Lagrangian step Delta s (m), for the time-step rule of section 2.2.
  double min_spacing_m() const;

  /// Trapezoidal weight (1 or 1/2) of a point along one direction.
  static double end_weight(int i, int n) { return (n > 1 && (i == 0 || i == n - 1)) ? 0.5 : 1.0; }
  /// Measure carried by a point: area (m^2) for a sheet, length (m) for a filament.
  double point_measure(int i1, int i2) const;
  /// Measure of a tension edge along s1 (between (i1,i2) and (i1+1,i2)) or along s2.
  double edge_measure_1(int i2) const;
  double edge_measure_2(int i1) const;
  /// Measure of a cell (sheets only).
  double cell_measure() const { return ds1_ * ds2_; }

  Eigen::VectorXd point_measures() const;

private:
  int n1_, n2_;
  double ds1_, ds2_;
};

} // namespace fsi::structure
