#pragma once
// The case's optional `fluid` section: which fluid participant the scene needs. Absent: a
// structure-only run (no coupler, no fluid process). Exactly one model when present.

#include "prescribed_flow/PrescribedFlowConfig.hpp"

namespace fsi::structure {

struct FluidConfig {
  std::optional<prescribed_flow::PrescribedFlowConfig> prescribed;

  template <class V> void visit(V &v) {
    v.optional_section("prescribed", prescribed,
                       "Velocity from an analytic or tabulated field instead of Navier-Stokes: one-way coupling "
                       "for structures that do not disturb the flow, at a fraction of the cost.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (!prescribed)
        v.fail("must hold exactly one fluid model: prescribed.");
  }

  /// Registry-style name of the fluid participant ("prescribed").
  std::string model() const { return "prescribed"; }
};

} // namespace fsi::structure
