#include "StepSystemFactory.hpp"

#include "FrozenTension.hpp"
#include "LinearizedTension.hpp"
#include "StabilizedTension.hpp"

namespace fsi::structure {

const StepSystemFactory &StepSystemFactory::builtin() {
  static const StepSystemFactory factory = [] {
    StepSystemFactory f;
    f.add({"frozen", [](const StepSettings &s) { return std::make_unique<FrozenTension>(s); }});
    f.add({"stabilized", [](const StepSettings &s) { return std::make_unique<StabilizedTension>(s); }});
    f.add({"linearized", [](const StepSettings &s) { return std::make_unique<LinearizedTension>(s); }});
    return f;
  }();
  return factory;
}

} // namespace fsi::structure
