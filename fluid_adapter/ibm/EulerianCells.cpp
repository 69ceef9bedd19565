#include "fluid_adapter/ibm/EulerianCells.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace fsi::fluid::ibm {

EulerianCells::EulerianCells(PointArray centres_m, Eigen::VectorXd volumes_m3)
    : centres_m_(std::move(centres_m)), volumes_m3_(std::move(volumes_m3)) {
  check();
  sizes_m_ = volumes_m3_.array().pow(1.0 / 3.0).matrix();
}

void EulerianCells::check() const {
  if (centres_m_.rows() != volumes_m3_.size())
    throw std::invalid_argument("EulerianCells: " + std::to_string(centres_m_.rows()) +
                                " cell centres but " + std::to_string(volumes_m3_.size()) +
                                " volumes; give one centre and one volume per cell");
  if (volumes_m3_.size() > std::numeric_limits<CellId>::max())
    throw std::invalid_argument("EulerianCells: too many cells for a 32-bit cell index");
  if (!centres_m_.allFinite() || !volumes_m3_.allFinite())
    throw std::invalid_argument("EulerianCells: a cell centre or volume is not finite");
  if (volumes_m3_.size() > 0 && volumes_m3_.minCoeff() <= 0.0)
    throw std::invalid_argument("EulerianCells: a cell volume is not positive (min " +
                                std::to_string(volumes_m3_.minCoeff()) + " m^3)");
}

} // namespace fsi::fluid::ibm
