#pragma once
// Builds the FlowField a case's `fluid.prescribed` section describes.

#include "FlowField.hpp"
#include "PrescribedFlowConfig.hpp"

#include <memory>

namespace fsi::prescribed_flow {

/// Throws common::ConfigError for a field that cannot be built (zero axis, shear direction
/// not perpendicular to the gradient, malformed table).
std::unique_ptr<FlowField> make_flow(const PrescribedFlowConfig &config);

} // namespace fsi::prescribed_flow
