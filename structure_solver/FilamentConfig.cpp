#include "FilamentConfig.hpp"

#include "InitialShape.hpp"
#include "LagrangianSheet.hpp"

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
    make_frame(direction, effective_bend_direction(direction, bend_direction, initial.curvature_1_per_m));
  } catch (const std::invalid_argument &e) {
    v.fail_value("bend_direction", std::string("is invalid for a pre-curved filament: ") + e.what() + ".");
  }
}

std::unique_ptr<StructureModel> FilamentConfig::build(const BuildContext &context) const {
  LagrangianGrid grid(n_points, 1, length_m, 0.0);
  const Frame bent =
      make_frame(direction, effective_bend_direction(direction, bend_direction, initial.curvature_1_per_m));
  // initial_shape bends toward e1 x e2; choose e2 so that this normal is bend_direction.
  const Frame frame{bent.e1, bent.e2.cross(bent.e1), bent.e2};
  SheetSetup setup{context.name, "filament", grid, initial_shape(grid, origin_m, frame, initial.curvature_1_per_m)};
  fill_shared_setup(setup, *this, context);
  setup.edges.s1_min = ends.start;
  setup.edges.s1_max = ends.end;
  setup.mass_per_measure = linear_density_kg_per_m;
  setup.tension_coefficient = tension_coefficient_n;
  setup.bending_rigidity = bending_rigidity_n_m2;
  setup.damping_per_measure = damping_kg_per_m_s;
  return std::make_unique<LagrangianSheet>(std::move(setup));
}

} // namespace fsi::structure
