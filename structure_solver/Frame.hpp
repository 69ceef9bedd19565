#pragma once
// The orthonormal frame a sheet or a filament is laid out in: e1 along s1, e2 along s2, and
// their normal. Configuration-side: a case with degenerate directions is refused with it.

#include "common/Types.hpp"

namespace fsi::structure {

struct Frame {
  Vec3 e1, e2, normal;
};

/// Orthonormal frame from two directions; throws std::invalid_argument when degenerate.
Frame make_frame(const Vec3 &s1_direction, const Vec3 &s2_direction);

} // namespace fsi::structure
