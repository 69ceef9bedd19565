#include "fluid_adapter/ibm/PeskinKernel.hpp"

#include <cmath>

namespace fsi::fluid::ibm {

double PeskinKernel::phi(double r) {
  const double a = std::abs(r);
  if (a < 1.0)
    return 0.125 * (3.0 - 2.0 * a + std::sqrt(1.0 + 4.0 * a - 4.0 * a * a));
  if (a < support_radius)
    return 0.125 * (5.0 - 2.0 * a - std::sqrt(-7.0 + 12.0 * a - 4.0 * a * a));
  return 0.0;
}

double PeskinKernel::delta_per_m3(const Vec3 &offset_m, double width_m) {
  const double inverse_width = 1.0 / width_m;
  return phi(offset_m.x() * inverse_width) * phi(offset_m.y() * inverse_width) *
         phi(offset_m.z() * inverse_width) * inverse_width * inverse_width * inverse_width;
}

} // namespace fsi::fluid::ibm
