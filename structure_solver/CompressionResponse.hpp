#pragma once
// How a sheet's stretching tension answers compression (sigma_11, sigma_22 of Eq. 3).
//  - elastic: sigma = phi (T - T0) of either sign, the paper's model. A compressed edge pushes
//    back, and under the frozen-tension step its negative tension makes the system matrix
//    indefinite once dt^2 |sigma| 4 / (rho_1 ds^2) nears 1: a stiff sheet crumpled by the flow
//    (phi = 100 N/m at the pump's hub) then diverges within a few steps.
//  - slack:   sigma = phi max(0, T - T0), tension-field (wrinkling) theory. Cloth buckles in
//    compression at scales far below the Lagrangian spacing and carries almost no compressive
//    load; the energy phi/4 max(0, T - T0)^2 stays C1, the force continuous, and the stretching
//    part of the step matrix stays positive. Shearing (sigma_12) and bending are unchanged.

#include <string>
#include <utility>
#include <vector>

namespace fsi::structure {

enum class CompressionResponse { elastic, slack };

inline const std::vector<std::pair<std::string, CompressionResponse>> &compression_response_names() {
  static const std::vector<std::pair<std::string, CompressionResponse>> names{
      {"elastic", CompressionResponse::elastic}, {"slack", CompressionResponse::slack}};
  return names;
}

} // namespace fsi::structure
