#pragma once
// The rigid bodies the fluid penalizes (Eqs. 9-10): the closed STL meshes among the scene's
// rigid surfaces (collisions.surfaces, named surface<i>), with their declared motions. The
// structure collides with the very same surfaces (Eq. 11).

#include "fluid_adapter/rigid/RigidBody.hpp"
#include "geometry/SurfaceConfig.hpp"

#include <memory>
#include <vector>

namespace fsi::apps {

/// Boxes and planes are left to the OpenFOAM mesh's walls (logged); analytic surfaces and
/// meshes holding the fluid are skipped with a warning.
std::vector<std::unique_ptr<fluid::rigid::RigidBody>> rigid_bodies(const std::vector<geometry::SurfaceConfig> &surfaces,
                                                            double gravity_m_per_s2);

} // namespace fsi::apps
