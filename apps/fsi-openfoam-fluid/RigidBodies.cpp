#include "RigidBodies.hpp"

#include "motion/MotionFactory.hpp"

#include <spdlog/spdlog.h>

namespace fsi::apps {

std::vector<std::unique_ptr<fluid::rigid::RigidBody>> rigid_bodies(const std::vector<geometry::SurfaceConfig> &surfaces,
                                                            double gravity_m_per_s2) {
  std::vector<std::unique_ptr<fluid::rigid::RigidBody>> bodies;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const auto &surface = surfaces[i];
    const std::string name = "surface" + std::to_string(i);
    if (surface.box || surface.plane) { // walls seen from the fluid: the OpenFOAM mesh's own walls
      spdlog::info("collisions.surfaces[{}] ({}) bounds the fluid: left to the walls of the OpenFOAM mesh", i,
                   surface.box ? "box" : "plane");
      continue;
    }
    if (!surface.mesh) {
      spdlog::warn("collisions.surfaces[{}] is an analytic surface: the fluid does not see it (give it as a closed STL "
                   "mesh to penalize it, or make it a wall of the OpenFOAM mesh)",
                   i);
      continue;
    }
    if (surface.mesh->fluid_side != geometry::FluidSide::outside) {
      spdlog::warn("collisions.surfaces[{}] has the fluid inside: it is a container, left to the OpenFOAM mesh", i);
      continue;
    }
    auto motion = surface.motion ? motion::make_motion(*surface.motion, gravity_m_per_s2)
                                 : std::make_shared<const motion::StaticPose>();
    bodies.push_back(fluid::rigid::RigidBody::from_stl(name, surface.mesh->file.string(), std::move(motion)));
  }
  return bodies;
}

} // namespace fsi::apps
