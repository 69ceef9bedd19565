#pragma once
// The operating point of a flow with an imposed inlet flow rate (a pump's duty):
// fluid.openfoam.operating_point. The fluid writes it into the OpenFOAM case it prepares
// (constant/operatingPoint, `flowRate` in m^3/s), which the inlet's boundary condition includes
// (flowRateInletVelocity, volumetricFlowRate $flowRate). A case whose OpenFOAM template takes
// its flow rate from there must give it. Header-only keys, no OpenFOAM header.

#include "common/ConfigReader.hpp"

#include <filesystem>
#include <string>
#include <type_traits>

namespace fsi::fluid {

struct OperatingPoint {
  double flow_rate_m3_per_s = 0.0;

  template <class V> void visit(V &v) {
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (!v.has("flow_rate_m3_per_s"))
        v.fail("needs flow_rate_m3_per_s: the volume flow rate imposed at the inlet (m^3/s, > 0).");
    v.number("flow_rate_m3_per_s", flow_rate_m3_per_s, common::Range::positive("m^3/s"),
             "Volume flow rate imposed at the inlet (written to constant/operatingPoint as flowRate; "
             "./fsi pump-curve and ./fsi rag-ensemble set it with --set).");
  }

  /// Where the OpenFOAM case holds it, relative to the case folder.
  static constexpr const char *file_name = "constant/operatingPoint";
  /// The dictionary's text (an OpenFOAM header, then `flowRate <value>;` with the shortest
  /// decimal that reads back as the same double).
  std::string dictionary() const;
  /// Writes file_name into foam_case (replacing it).
  void write(const std::filesystem::path &foam_case) const;
  /// True when the OpenFOAM case's initial velocity (0/U) includes constant/operatingPoint, i.e.
  /// its inlet flow rate must be given.
  static bool required_by(const std::filesystem::path &foam_case);
};

} // namespace fsi::fluid
