#pragma once
// The answer of a rigid surface to "how far is this point from you?" (Eq. 11 inputs).

#include "common/Types.hpp"

namespace fsi::geometry {

/// Signed distance and wall normal of one point, both in the body frame of the surface.
struct SurfaceDistance {
  /// epsilon_c of Eq. 11: positive on the fluid side, negative inside the solid (m).
  double signed_distance_m = 0.0;
  /// n_w of Eq. 11: unit normal of the rigid surface at the closest point, pointing into
  /// the fluid (for a point inside the solid it points towards the way out).
  Vec3 normal_into_fluid = Vec3::UnitZ();
};

} // namespace fsi::geometry
