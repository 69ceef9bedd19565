#include "FilamentConfig.hpp"

#include <stdexcept>

namespace fsi::structure {

namespace {
/// bend_direction only matters for a pre-curved filament; otherwise any perpendicular will do.
Vec3 effective_bend_direction(const Vec3 &direction, const Vec3 &bend_direction, double curvature) {
  if (curvature != 0.0 || direction.normalized().cross(bend_direction).norm() > 1e-6 * bend_direction.norm())
    return bend_direction;
  const Eigen::Index least_aligned = [&] {
    Eigen::Index i;
    direction.cwiseAbs().minCoeff(&i);
    return i;
  }();
  return Vec3::Unit(least_aligned);
}
} // namespace

void FilamentConfig::validate(common::ConfigReader &v) const {
  if (direction.norm() == 0.0)
    v.fail_value("direction", "must not be the zero vector.");
  try {
    (void)frame();
  } catch (const std::invalid_argument &e) {
    v.fail_value("bend_direction", std::string("is invalid for a pre-curved filament: ") + e.what() + ".");
  }
}

Frame FilamentConfig::frame() const {
  const Frame bent = make_frame(direction, effective_bend_direction(direction, bend_direction, initial.curvature_1_per_m));
  // A pre-curved shape bends toward e1 x e2; choose e2 so that this normal is bend_direction.
  return {bent.e1, bent.e2.cross(bent.e1), bent.e2};
}

} // namespace fsi::structure
