#include "MembraneConfig.hpp"

#include "Frame.hpp"

#include <stdexcept>

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

} // namespace fsi::structure
