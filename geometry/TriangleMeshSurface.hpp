#pragma once
// A closed triangle mesh (an impeller, a volute casing) as a collision surface. Built once in
// the body frame. Near the surface (after prepare_culling), each cell of a VoxelSideGrid
// lists the few triangles that can hold the closest point of its points (NearTriangleLists),
// and the angle-weighted pseudo-normal of the closest feature gives the side
// (PseudoNormals): a near query costs a handful of exact point-triangle distances. Far cells
// are classified inside or outside once; elsewhere a BVH (TriangleBvh) finds the closest
// triangle, and CGAL::Side_of_triangle_mesh decides the side where a pseudo-normal cannot
// (a self-intersecting mesh, a point on the surface, a knife-thin feature).

#include "geometry/RigidSurface.hpp"
#include "geometry/TriangleSoup.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace fsi::geometry {

class TriangleMeshSurface final : public RigidSurface {
public:
  /// Which side of the closed surface holds the fluid.
  enum class FluidSide {
    outside, ///< the mesh is a solid body (impeller, obstacle)
    inside   ///< the mesh is a casing (volute, pipe) whose interior holds the fluid
  };

  /// Loads an ASCII or binary STL file. Throws a MeshError subclass naming the file: missing
  /// file, unreadable or empty file, mesh not closed (with the number of border edges) or
  /// degenerate (zero-area triangles, no enclosed volume).
  explicit TriangleMeshSurface(const std::string &stl_path,
                               FluidSide fluid_side = FluidSide::outside);

  /// Builds the surface from arrays (generated meshes, tests); `source_name` stands for the
  /// file name in error messages. Same checks as the file constructor.
  static std::unique_ptr<TriangleMeshSurface>
  from_triangles(const PointArray &vertices_m, const TriangleArray &triangles, FluidSide fluid_side,
                 const std::string &source_name = "in-memory mesh");

  ~TriangleMeshSurface() override;
  TriangleMeshSurface(TriangleMeshSurface &&) noexcept;
  TriangleMeshSurface &operator=(TriangleMeshSurface &&) noexcept;

  SurfaceDistance distance(const Vec3 &point_body_m) const override;
  std::string describe() const override;
  bool may_be_within(const Vec3 &point_body_m, double radius_m) const override;
  /// Builds (or widens) the voxel culling grid and the per-cell candidate triangles for
  /// query radii up to radius_m (about a second per 100k triangles when radius_m is twice
  /// the triangle size).
  void prepare_culling(double radius_m) override;

  /// Exact test: is the point strictly inside the closed surface (whatever the fluid side)?
  bool is_inside_mesh(const Vec3 &point_body_m) const;

  std::size_t n_triangles() const;
  FluidSide fluid_side() const;
  /// Volume enclosed by the surface (m^3), positive.
  double enclosed_volume_m3() const;

private:
  TriangleMeshSurface(const TriangleSoup &soup, FluidSide fluid_side, const std::string &source);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace fsi::geometry
