#pragma once
// A rigid immersed body of the sharp-interface IBM (section 2.4 of the paper): a closed
// triangulated surface given once in the body frame, and the prescribed motion that places it
// in the world (x_world = pose_at(t) * x_body). The surface is the collision module's
// TriangleMeshSurface, so the body-frame AABB tree, the exact CGAL inside test and the voxel
// classification that spares most points that test are built once, here.

#include "motion/RigidMotion.hpp"
#include "common/Types.hpp"
#include "geometry/TriangleMeshSurface.hpp"
#include "geometry/TriangleSoup.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <string>

namespace fsi::fluid::rigid {

class RigidBody {
public:
  using Soup = geometry::TriangleSoup;
  using Surface = geometry::TriangleMeshSurface;

  /// Loads a closed STL surface (body frame, metres). Throws a geometry::MeshError naming
  /// the file when it is missing, unreadable, open or degenerate.
  static std::unique_ptr<RigidBody> from_stl(const std::string &name, const std::string &stl_path,
                                             std::shared_ptr<const motion::RigidMotion> motion);
  /// Same from arrays (generated meshes, tests).
  static std::unique_ptr<RigidBody> from_soup(const std::string &name, const Soup &soup,
                                              std::shared_ptr<const motion::RigidMotion> motion);

  const std::string &name() const { return name_; }
  const motion::RigidMotion &motion() const { return *motion_; }
  const Surface &surface() const { return *surface_; }
  /// Vertices and triangles in the body frame (for the swept-region bounds).
  const Soup &soup() const { return soup_; }
  /// Axis-aligned bounding box of the surface in the body frame (m).
  const Eigen::AlignedBox3d &body_box_m() const { return body_box_m_; }

  /// Exact side test of a body-frame point (strictly inside the closed surface). Thread-safe.
  bool contains_body_point(const Vec3 &point_body_m) const {
    return body_box_m_.contains(point_body_m) && surface_->is_inside_mesh(point_body_m);
  }

private:
  RigidBody(std::string name, Soup soup, std::unique_ptr<Surface> surface,
            std::shared_ptr<const motion::RigidMotion> motion);

  std::string name_;
  Soup soup_;
  std::unique_ptr<Surface> surface_;
  std::shared_ptr<const motion::RigidMotion> motion_;
  Eigen::AlignedBox3d body_box_m_;
};

} // namespace fsi::fluid::rigid
