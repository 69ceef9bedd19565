#pragma once
// A rigid immersed body of the sharp-interface IBM (section 2.4 of the paper): a closed
// triangulated surface given once in the body frame, and the prescribed motion that places it
// in the world (x_world = pose_at(t) * x_body). The surface is the collision module's
// TriangleMeshSurface, so the body-frame AABB tree, the exact CGAL inside test and the voxel
// classification that spares most points that test are built once, here.

#include "motion/CoupledMotion.hpp"
#include "motion/RigidMotion.hpp"
#include "common/Types.hpp"
#include "geometry/RegionSoup.hpp"
#include "geometry/TriangleMeshSurface.hpp"
#include "geometry/TriangleSoup.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace fsi::fluid::rigid {

class RigidBody {
public:
  using Soup = geometry::TriangleSoup;
  using Surface = geometry::TriangleMeshSurface;

  /// Loads a closed STL surface (body frame, metres); its `solid NAME` blocks are the body's
  /// parts. Throws a geometry::MeshError naming the file when it is missing, unreadable, open
  /// or degenerate.
  static std::unique_ptr<RigidBody> from_stl(const std::string &name, const std::string &stl_path,
                                             std::shared_ptr<const motion::RigidMotion> motion);
  /// Same from arrays (generated meshes, tests): one part named "".
  static std::unique_ptr<RigidBody> from_soup(const std::string &name, const Soup &soup,
                                              std::shared_ptr<const motion::RigidMotion> motion);
  /// Same with named parts (the soup's regions).
  static std::unique_ptr<RigidBody> from_region_soup(const std::string &name, const geometry::RegionSoup &regions,
                                                     std::shared_ptr<const motion::RigidMotion> motion);

  const std::string &name() const { return name_; }
  /// Where the body is: its declared motion, or in a coupled run the poses the coupler sends.
  const motion::RigidMotion &motion() const { return *motion_; }
  /// The motion the case declares: what kind of motion it is (an axis rotation sweeps a body
  /// of revolution: SweptRegion), never evaluated for a pose in a coupled run.
  const motion::RigidMotion &declared_motion() const { return declared_motion_ ? *declared_motion_ : *motion_; }
  /// A coupled run: from now on the body is where the coupler says (section 2.3). Moving
  /// bodies only (a static body needs no pose). Returns the motion to feed.
  motion::CoupledMotion &take_poses_from_coupler();
  /// Its coupled motion, or nullptr when the body evaluates its own (static, precursor).
  motion::CoupledMotion *coupled_motion() const { return coupled_motion_.get(); }
  const Surface &surface() const { return *surface_; }
  /// Vertices and triangles in the body frame (for the swept-region bounds).
  const Soup &soup() const { return soup_; }
  /// The surface's parts: the names of the STL's `solid NAME` blocks (one "" for a file or
  /// soup without names), and the part of each triangle of soup().
  const std::vector<std::string> &part_names() const { return part_names_; }
  const std::vector<int> &part_of_triangle() const { return part_of_triangle_; }
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
  std::vector<std::string> part_names_{""};
  std::vector<int> part_of_triangle_;
  std::unique_ptr<Surface> surface_;
  std::shared_ptr<const motion::RigidMotion> motion_;
  std::shared_ptr<const motion::RigidMotion> declared_motion_; ///< set once the coupler moves the body
  std::shared_ptr<motion::CoupledMotion> coupled_motion_;
  Eigen::AlignedBox3d body_box_m_;
};

} // namespace fsi::fluid::rigid
