#include "MembraneConfig.hpp"

#include "InitialShape.hpp"
#include "LagrangianSheet.hpp"

namespace fsi::structure {

double SheetMaterial::tension_coefficient() const {
  if (elastic_moduli)
    return elastic_moduli->youngs_modulus_pa * elastic_moduli->thickness_m;
  return coefficients.value_or(SheetCoefficients{}).tension_coefficient_n_per_m;
}

double SheetMaterial::bending_rigidity() const {
  if (elastic_moduli) {
    const auto &m = *elastic_moduli;
    return m.youngs_modulus_pa * m.thickness_m * m.thickness_m * m.thickness_m /
           (12.0 * (1.0 - m.poisson_ratio * m.poisson_ratio));
  }
  return coefficients.value_or(SheetCoefficients{}).bending_rigidity_n_m;
}

void MembraneConfig::validate(common::ConfigReader &v) const {
  try {
    make_frame(s1_direction, s2_direction);
  } catch (const std::invalid_argument &e) {
    v.fail_value("s2_direction", std::string("is invalid: ") + e.what() + ".");
  }
}

std::unique_ptr<StructureModel> MembraneConfig::build(const BuildContext &context) const {
  LagrangianGrid grid(n_points[0], n_points[1], size_m[0], size_m[1]);
  const Frame frame = make_frame(s1_direction, s2_direction);
  SheetSetup setup{context.name, "membrane", grid, initial_shape(grid, origin_m, frame, initial.curvature_1_per_m)};
  fill_shared_setup(setup, *this, context);
  setup.edges = edges.conditions;
  setup.mass_per_measure = material.mass_per_area_kg_per_m2;
  setup.tension_coefficient = material.tension_coefficient();
  setup.bending_rigidity = material.bending_rigidity();
  setup.damping_per_measure = material.damping_kg_per_m2_s;
  setup.compression = material.compression;
  return std::make_unique<LagrangianSheet>(std::move(setup));
}

} // namespace fsi::structure
