#pragma once
// Initial shapes: a flat rectangle (or straight filament) at any position and orientation,
// optionally pre-curved so that lines along s1 are circular arcs of curvature kappa bending
// toward the normal e1 x e2 (arc length is preserved, so the shape is unstretched).

#include "Frame.hpp"
#include "LagrangianGrid.hpp"
#include "common/Types.hpp"

namespace fsi::structure {

PointArray initial_shape(const LagrangianGrid &grid, const Vec3 &origin_m, const Frame &frame,
                         double curvature_1_per_m);

} // namespace fsi::structure
