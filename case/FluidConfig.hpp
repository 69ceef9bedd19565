#pragma once
// The case's optional `fluid` section: which fluid participant the scene needs. Absent: a
// structure-only run (no coupler, no fluid process). Exactly one model when present.

#include "fluid_adapter/OpenFoamConfig.hpp"
#include "prescribed_flow/PrescribedFlowConfig.hpp"

namespace fsi::case_config {

struct FluidConfig {
  std::optional<prescribed_flow::PrescribedFlowConfig> prescribed;
  std::optional<fluid::OpenFoamConfig> openfoam;

  template <class V> void visit(V &v) {
    v.optional_section("prescribed", prescribed,
                       "Velocity from an analytic or tabulated field instead of Navier-Stokes: one-way coupling "
                       "for structures that do not disturb the flow, at a fraction of the cost.");
    v.optional_section("openfoam", openfoam,
                       "Navier-Stokes (OpenFOAM PIMPLE) with the diffuse immersed boundary of Eqs. (6-8): two-way "
                       "coupling.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      v.require_exactly_one({{"prescribed", prescribed.has_value()}, {"openfoam", openfoam.has_value()}});
  }

  /// Name of the fluid model ("prescribed", "openfoam").
  std::string model() const { return openfoam ? "openfoam" : "prescribed"; }
  /// The executable of its participant.
  std::string executable() const { return openfoam ? "fsi-openfoam-fluid" : "fsi-prescribed-flow"; }
};

} // namespace fsi::case_config
