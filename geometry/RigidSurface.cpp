#include "geometry/RigidSurface.hpp"

namespace fsi::geometry {

bool RigidSurface::may_be_within(const Vec3 &, double) const { return true; }

void RigidSurface::prepare_culling(double) {}

} // namespace fsi::geometry
