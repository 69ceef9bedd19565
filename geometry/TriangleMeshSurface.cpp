#include "geometry/TriangleMeshSurface.hpp"

#include "geometry/NearTriangleLists.hpp"
#include "geometry/OrientedMesh.hpp"
#include "geometry/PseudoNormals.hpp"
#include "geometry/StlIo.hpp"
#include "geometry/TriangleBvh.hpp"
#include "geometry/TriangleSoupChecks.hpp"
#include "geometry/VoxelSideGrid.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace fsi::geometry {
namespace {

using SideOf = CGAL::Side_of_triangle_mesh<Mesh, MeshKernel>;
using Tree = SideOf::AABB_tree;
namespace PMP = CGAL::Polygon_mesh_processing;

/// Below this fraction of the bounding-box diagonal a point counts as on the surface and
/// takes the face normal instead of the (ill-defined) direction to the closest point.
constexpr double kOnSurfaceFraction = 1e-9;

/// The pseudo-normal decides the side only when the direction from the closest point makes
/// an angle with it clearly away from 90 degrees (cosine above this); otherwise (a knife-thin
/// edge or spike, round-off at a feature boundary) the exact inside test does.
constexpr double kClearCosine = 1e-3;

} // namespace

struct TriangleMeshSurface::Impl {
  /// Closest point of the mesh to a query point (its face, and the feature of that face),
  /// and the side of the query point.
  struct Query {
    std::int32_t face = -1;
    TrianglePoint closest;
    bool inside = false;
  };

  std::string source;
  FluidSide fluid_side = FluidSide::outside;
  Mesh mesh;
  std::unique_ptr<TriangleBvh> bvh; ///< exact closest triangle anywhere
  std::unique_ptr<PseudoNormals> pseudo_normals;
  bool signs_from_normals = true; ///< false for a self-intersecting mesh
  std::unique_ptr<Tree> tree;     ///< for the exact inside test only
  std::unique_ptr<SideOf> side_of;
  Eigen::AlignedBox3d box_m;
  double on_surface_m = 0.0;
  double volume_m3 = 0.0;
  std::unique_ptr<VoxelSideGrid> grid;      ///< after prepare_culling()
  std::unique_ptr<NearTriangleLists> lists; ///< after prepare_culling()

  void build_queries();
  bool is_inside_exact(const Vec3 &p) const {
    return (*side_of)(MeshPoint(p.x(), p.y(), p.z())) == CGAL::ON_BOUNDED_SIDE;
  }
  /// Closest point and side: from the cell's candidate list when it settles the closest
  /// triangle (near cells), else from the BVH and the grid's classification.
  Query query(const Vec3 &p) const;
  /// Side of a point near the surface: the sign of (p - c).n with n the pseudo-normal of
  /// the closest feature, or the exact inside test when that sign is not clear-cut.
  bool is_inside_near(const Vec3 &p, std::int32_t face, const TrianglePoint &closest) const;
};

void TriangleMeshSurface::Impl::build_queries() {
  const TriangleSoup soup = mesh_to_soup(mesh);
  bvh = std::make_unique<TriangleBvh>(triangle_corners(soup));
  pseudo_normals = std::make_unique<PseudoNormals>(soup.vertices_m, soup.triangles);
  // Pseudo-normals sign the distance correctly only where the surface does not cross itself.
  signs_from_normals = !PMP::does_self_intersect(mesh);
  for (auto v : mesh.vertices())
    box_m.extend(Vec3(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()));
  on_surface_m = kOnSurfaceFraction * box_m.diagonal().norm();
  volume_m3 = PMP::volume(mesh);
  tree = std::make_unique<Tree>(faces(mesh).first, faces(mesh).second, mesh);
  tree->build();
  side_of = std::make_unique<SideOf>(*tree);
}

TriangleMeshSurface::Impl::Query TriangleMeshSurface::Impl::query(const Vec3 &p) const {
  std::int32_t start_face = -1;
  if (lists) {
    const NearTriangleLists::Hit hit = lists->nearest(p);
    if (hit.exact) // lists exist for near cells only
      return {hit.face, hit.closest, is_inside_near(p, hit.face, hit.closest)};
    start_face = hit.face;
  }
  if (start_face < 0 && grid)
    start_face = grid->hint_triangle_at(p);
  const TriangleBvh::Nearest nearest = bvh->nearest(p, start_face);
  if (nearest.face < 0) // only for a non-finite point: no triangle is at a finite distance
    return {0,
            {Vec3::Constant(std::numeric_limits<double>::quiet_NaN()), TriangleFeature::face},
            false};
  const VoxelState state = lists ? lists->state_at(p) : VoxelState::near_surface;
  const bool inside = state == VoxelState::near_surface
                          ? is_inside_near(p, nearest.face, nearest.closest)
                          : state == VoxelState::inside_mesh;
  return {nearest.face, nearest.closest, inside};
}

bool TriangleMeshSurface::Impl::is_inside_near(const Vec3 &p, std::int32_t face,
                                               const TrianglePoint &closest) const {
  if (signs_from_normals) {
    const Vec3 from_surface_m = p - closest.point_m;
    const double length_m = from_surface_m.norm();
    const double along_normal_m = from_surface_m.dot(pseudo_normals->normal(face, closest.feature));
    if (length_m > on_surface_m && std::abs(along_normal_m) > kClearCosine * length_m)
      return along_normal_m < 0.0;
  }
  return is_inside_exact(p);
}

TriangleMeshSurface::TriangleMeshSurface(const std::string &stl_path, FluidSide fluid_side)
    : TriangleMeshSurface(read_stl(stl_path), fluid_side, stl_path) {}

TriangleMeshSurface::TriangleMeshSurface(const TriangleSoup &soup, FluidSide fluid_side,
                                         const std::string &source)
    : impl_(std::make_unique<Impl>()) {
  check_triangle_soup(soup, source);
  impl_->source = source;
  impl_->fluid_side = fluid_side;
  impl_->mesh = build_oriented_mesh(soup, source);
  impl_->build_queries();
}

std::unique_ptr<TriangleMeshSurface>
TriangleMeshSurface::from_triangles(const PointArray &vertices_m, const TriangleArray &triangles,
                                    FluidSide fluid_side, const std::string &source_name) {
  const TriangleSoup soup{vertices_m, triangles};
  return std::unique_ptr<TriangleMeshSurface>(
      new TriangleMeshSurface(soup, fluid_side, source_name));
}

TriangleMeshSurface::~TriangleMeshSurface() = default;
TriangleMeshSurface::TriangleMeshSurface(TriangleMeshSurface &&) noexcept = default;
TriangleMeshSurface &TriangleMeshSurface::operator=(TriangleMeshSurface &&) noexcept = default;

SurfaceDistance TriangleMeshSurface::distance(const Vec3 &point_body_m) const {
  const Impl::Query query = impl_->query(point_body_m);
  const Vec3 from_surface_m = point_body_m - query.closest.point_m;
  const double unsigned_m = from_surface_m.norm();
  const double sign = query.inside == (impl_->fluid_side == FluidSide::inside) ? 1.0 : -1.0;
  if (unsigned_m <= impl_->on_surface_m) {
    const double outward_is_fluid = impl_->fluid_side == FluidSide::outside ? 1.0 : -1.0;
    return {sign * unsigned_m,
            outward_is_fluid * impl_->pseudo_normals->normal(query.face, TriangleFeature::face)};
  }
  return {sign * unsigned_m, sign * from_surface_m / unsigned_m};
}

bool TriangleMeshSurface::may_be_within(const Vec3 &point_body_m, double radius_m) const {
  const bool fluid_outside = impl_->fluid_side == FluidSide::outside;
  if (impl_->grid && radius_m <= impl_->grid->radius_m()) {
    // The lists' copy of the classification: the cell's word is then at hand for distance().
    const VoxelState state = impl_->lists->state_at(point_body_m);
    if (state == VoxelState::near_surface)
      return true;
    return (state == VoxelState::outside_mesh) != fluid_outside; // far: only solid matters
  }
  return !fluid_outside || impl_->box_m.exteriorDistance(point_body_m) <= radius_m;
}

void TriangleMeshSurface::prepare_culling(double radius_m) {
  if (impl_->grid && radius_m <= impl_->grid->radius_m())
    return;
  const Impl &impl = *impl_;
  impl_->lists.reset();
  impl_->grid.reset(); // the grid's own flood fill must use exact inside tests
  const TriangleSoup soup = mesh_to_soup(impl_->mesh); // faces in the order of the BVH's
  const std::vector<VoxelSideGrid::Triangle> corners = triangle_corners(soup);
  impl_->grid = std::make_unique<VoxelSideGrid>(
      corners, radius_m, [&impl](const Vec3 &p) { return impl.is_inside_exact(p); });
  const FeatureRegions regions(soup.vertices_m, soup.triangles);
  impl_->lists = std::make_unique<NearTriangleLists>(*impl_->grid, corners, regions);
}

bool TriangleMeshSurface::is_inside_mesh(const Vec3 &point_body_m) const {
  if (impl_->lists) {
    const VoxelState state = impl_->lists->state_at(point_body_m);
    if (state != VoxelState::near_surface)
      return state == VoxelState::inside_mesh;
  }
  return impl_->query(point_body_m).inside;
}

std::string TriangleMeshSurface::describe() const {
  std::ostringstream out;
  out << "triangle mesh '" << impl_->source << "' (" << n_triangles() << " triangles, fluid "
      << (impl_->fluid_side == FluidSide::outside ? "outside" : "inside") << ", enclosed volume "
      << impl_->volume_m3 << " m^3)";
  return out.str();
}

std::size_t TriangleMeshSurface::n_triangles() const { return impl_->mesh.number_of_faces(); }

TriangleMeshSurface::FluidSide TriangleMeshSurface::fluid_side() const { return impl_->fluid_side; }

double TriangleMeshSurface::enclosed_volume_m3() const { return impl_->volume_m3; }

} // namespace fsi::geometry
