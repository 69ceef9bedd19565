#pragma once
// Abstract rigid surface seen by the collision model (Sec. 2.5): anything that can answer a
// signed-distance query in its own body frame. The pose of the body in the world is supplied
// separately (motion::RigidMotion), so a surface is built once and never moves.

#include "geometry/SurfaceDistance.hpp"

#include <string>

namespace fsi::geometry {

class RigidSurface {
public:
  virtual ~RigidSurface() = default;

  /// Signed distance and normal of a body-frame point (exact, never culled).
  virtual SurfaceDistance distance(const Vec3 &point_body_m) const = 0;

  /// One line for the log, e.g. "plane through (0, 0, 0) with normal (0, 0, 1)".
  virtual std::string describe() const = 0;

  /// Cheap conservative test: returns false only when the point is certainly on the fluid
  /// side AND farther than radius_m from the surface (so it needs no correction). The
  /// default always answers true.
  virtual bool may_be_within(const Vec3 &point_body_m, double radius_m) const;

  /// Lets a surface precompute culling data for queries of radius up to radius_m (called by
  /// CollisionSet when the surface is added). The default does nothing.
  virtual void prepare_culling(double radius_m);
};

} // namespace fsi::geometry
