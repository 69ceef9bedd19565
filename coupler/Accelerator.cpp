#include "Accelerator.hpp"

#include "AitkenRelaxation.hpp"
#include "ConstantRelaxation.hpp"
#include "IqnIlsAccelerator.hpp"

namespace fsi::coupler {

std::unique_ptr<Accelerator> make_accelerator(const ImplicitCouplingConfig &config) {
  switch (config.acceleration) {
  case Acceleration::constant:
    return std::make_unique<ConstantRelaxation>(config.relaxation);
  case Acceleration::aitken:
    return std::make_unique<AitkenRelaxation>(config.relaxation);
  case Acceleration::iqn_ils:
    return std::make_unique<IqnIlsAccelerator>(config.relaxation, config.reuse_steps);
  }
  return nullptr;
}

} // namespace fsi::coupler
