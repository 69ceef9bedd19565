#pragma once
// The smoothed Dirac function of Sec. 2.3: Peskin's 4-point kernel phi (Eq. 7) and its 3D
// tensor product delta_h (Eq. 6). The extracted Eq. (7) reads "+ sqrt(...)" on the outer
// branch 1 <= |r| < 2; Peskin's kernel has "- sqrt(...)", the only sign that makes phi
// continuous at |r| = 1 and 2 and gives sum_j phi(s - j) = 1. The paper's |r^2| means r^2.

#include "common/Types.hpp"

namespace fsi::fluid::ibm {

class PeskinKernel {
public:
  /// phi vanishes for |r| >= support_radius (r in units of the kernel width h).
  static constexpr double support_radius = 2.0;

  /// Eq. 7 (dimensionless). For any shift s: sum_j phi(s - j) = 1,
  /// sum_j (s - j) phi(s - j) = 0 and sum_j phi(s - j)^2 = 3/8.
  static double phi(double r);

  /// Eq. 6: delta_h(offset) = phi(x/h) phi(y/h) phi(z/h) / h^3, in 1/m^3, for the offset
  /// x_cell - X_point (m) and the kernel width h = width_m (m, > 0).
  static double delta_per_m3(const Vec3 &offset_m, double width_m);
};

} // namespace fsi::fluid::ibm
