#include "InitialShape.hpp"

#include <cmath>
#include <stdexcept>

namespace fsi::structure {

PointArray initial_shape(const LagrangianGrid &grid, const Vec3 &origin_m, const Frame &frame,
                         double curvature_1_per_m) {
  PointArray x(grid.n_points(), 3);
  const double k = curvature_1_per_m;
  for (int i1 = 0; i1 < grid.n1(); ++i1) {
    const double s1 = i1 * grid.ds1();
    const double along = std::abs(k) < 1e-12 ? s1 : std::sin(k * s1) / k;
    const double across = std::abs(k) < 1e-12 ? 0.5 * k * s1 * s1 : (1.0 - std::cos(k * s1)) / k;
    for (int i2 = 0; i2 < grid.n2(); ++i2) {
      const double s2 = grid.is_filament() ? 0.0 : i2 * grid.ds2();
      x.row(grid.index(i1, i2)) = (origin_m + along * frame.e1 + s2 * frame.e2 + across * frame.normal).transpose();
    }
  }
  return x;
}

} // namespace fsi::structure
