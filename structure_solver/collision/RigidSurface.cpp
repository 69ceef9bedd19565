#include "structure_solver/collision/RigidSurface.hpp"

namespace fsi::structure::collision {

bool RigidSurface::may_be_within(const Vec3 &, double) const { return true; }

void RigidSurface::prepare_culling(double) {}

} // namespace fsi::structure::collision
