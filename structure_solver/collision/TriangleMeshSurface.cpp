#include "structure_solver/collision/TriangleMeshSurface.hpp"

#include "structure_solver/collision/MeshErrors.hpp"
#include "structure_solver/collision/StlIo.hpp"
#include "structure_solver/collision/TriangleSoupChecks.hpp"
#include "structure_solver/collision/VoxelSideGrid.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <sstream>
#include <vector>

namespace fsi::structure::collision {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using SideOf = CGAL::Side_of_triangle_mesh<Mesh, Kernel>;
using Tree = SideOf::AABB_tree;
namespace PMP = CGAL::Polygon_mesh_processing;

/// Below this fraction of the bounding-box diagonal a point counts as on the surface and
/// takes the face normal instead of the (ill-defined) direction to the closest point.
constexpr double kOnSurfaceFraction = 1e-9;

Vec3 to_vec3(const Point &p) { return {p.x(), p.y(), p.z()}; }

/// Enclosed volume of each connected component (m^3, by the divergence theorem: the sign
/// depends on the component's orientation).
std::vector<double> component_volumes_m3(Mesh &mesh) {
  auto component_of = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  std::vector<double> volumes_m3(PMP::connected_components(mesh, component_of), 0.0);
  for (auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Vec3 a = to_vec3(mesh.point(mesh.source(h))), b = to_vec3(mesh.point(mesh.target(h))),
               c = to_vec3(mesh.point(mesh.target(mesh.next(h))));
    volumes_m3[component_of[f]] += a.dot(b.cross(c)) / 6.0;
  }
  mesh.remove_property_map(component_of);
  return volumes_m3;
}

/// Throws MeshDegenerateError when a connected component encloses a negligible volume (a flat
/// closed surface); CGAL's orientation step requires every component to bound a volume.
void check_component_volumes(Mesh &mesh, const std::string &source) {
  Eigen::AlignedBox3d box_m;
  for (auto v : mesh.vertices())
    box_m.extend(to_vec3(mesh.point(v)));
  const double diagonal_m = box_m.diagonal().norm();
  const std::vector<double> volumes_m3 = component_volumes_m3(mesh);
  for (std::size_t k = 0; k < volumes_m3.size(); ++k) {
    if (std::abs(volumes_m3[k]) <= 1e-9 * diagonal_m * diagonal_m * diagonal_m) {
      std::ostringstream reason;
      reason << "closed component " << k + 1 << " of " << volumes_m3.size()
             << " encloses a volume of " << std::abs(volumes_m3[k])
             << " m^3, negligible for a mesh of size " << diagonal_m << " m";
      throw MeshDegenerateError(source, reason.str());
    }
  }
}

/// Orients the soup consistently and converts it to a closed, outward-oriented mesh.
Mesh build_oriented_mesh(const TriangleSoup &soup, const std::string &source) {
  std::vector<Point> points;
  points.reserve(static_cast<std::size_t>(soup.vertices_m.rows()));
  for (Eigen::Index v = 0; v < soup.vertices_m.rows(); ++v) {
    points.emplace_back(soup.vertices_m(v, 0), soup.vertices_m(v, 1), soup.vertices_m(v, 2));
  }
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(static_cast<std::size_t>(soup.triangles.rows()));
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    polygons.push_back({static_cast<std::size_t>(soup.triangles(t, 0)),
                        static_cast<std::size_t>(soup.triangles(t, 1)),
                        static_cast<std::size_t>(soup.triangles(t, 2))});
  }
  PMP::orient_polygon_soup(points, polygons);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (!CGAL::is_closed(mesh)) { // non-manifold edges split by the orientation step
    std::size_t n_border = 0;
    for (auto h : mesh.halfedges())
      n_border += mesh.is_border(h) ? 1 : 0;
    throw MeshNotClosedError(source, n_border);
  }
  check_component_volumes(mesh, source);
  PMP::orient_to_bound_a_volume(mesh);
  return mesh;
}

} // namespace

struct TriangleMeshSurface::Impl {
  std::string source;
  FluidSide fluid_side = FluidSide::outside;
  Mesh mesh;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<SideOf> side_of;
  std::vector<Vec3> outward_face_normals;
  Eigen::AlignedBox3d box_m;
  double volume_m3 = 0.0;
  std::unique_ptr<VoxelSideGrid> grid;

  void build_queries();
  bool is_inside_exact(const Vec3 &p) const {
    return (*side_of)(Point(p.x(), p.y(), p.z())) == CGAL::ON_BOUNDED_SIDE;
  }
  /// Inside test using the voxel grid when it knows the answer.
  bool is_inside(const Vec3 &p) const;
  Kernel::Triangle_3 triangle_of(Mesh::Face_index face) const;
  std::vector<VoxelSideGrid::Triangle> triangles() const;
  /// Closest surface point and its face, starting from the grid's hint when there is one.
  Tree::Point_and_primitive_id closest(const Vec3 &p) const;
};

void TriangleMeshSurface::Impl::build_queries() {
  for (auto v : mesh.vertices())
    box_m.extend(to_vec3(mesh.point(v)));
  outward_face_normals.resize(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    const auto normal = PMP::compute_face_normal(f, mesh);
    outward_face_normals[static_cast<std::size_t>(f)] = Vec3(normal.x(), normal.y(), normal.z());
  }
  volume_m3 = PMP::volume(mesh);
  tree = std::make_unique<Tree>(faces(mesh).first, faces(mesh).second, mesh);
  tree->build();
  tree->accelerate_distance_queries();
  side_of = std::make_unique<SideOf>(*tree);
}

bool TriangleMeshSurface::Impl::is_inside(const Vec3 &p) const {
  if (grid) {
    const VoxelState state = grid->state_at(p);
    if (state != VoxelState::near_surface)
      return state == VoxelState::inside_mesh;
  }
  return is_inside_exact(p);
}

Kernel::Triangle_3 TriangleMeshSurface::Impl::triangle_of(Mesh::Face_index face) const {
  const auto h = mesh.halfedge(face);
  return {mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
          mesh.point(mesh.target(mesh.next(h)))};
}

std::vector<VoxelSideGrid::Triangle> TriangleMeshSurface::Impl::triangles() const {
  // Indexed like the faces, so that the grid's hint indices are face indices.
  std::vector<VoxelSideGrid::Triangle> result(mesh.number_of_faces());
  for (auto f : mesh.faces()) {
    const Kernel::Triangle_3 t = triangle_of(f);
    result[static_cast<std::size_t>(f)] = {to_vec3(t[0]), to_vec3(t[1]), to_vec3(t[2])};
  }
  return result;
}

Tree::Point_and_primitive_id TriangleMeshSurface::Impl::closest(const Vec3 &p) const {
  const Point query(p.x(), p.y(), p.z());
  const std::int32_t hint = grid ? grid->hint_triangle_at(p) : -1;
  if (hint < 0)
    return tree->closest_point_and_primitive(query);
  const Mesh::Face_index face(static_cast<Mesh::size_type>(hint));
  const Point on_hint = Kernel::Construct_projected_point_3()(triangle_of(face), query);
  return tree->closest_point_and_primitive(query, {on_hint, face});
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
  const auto [closest, face] = impl_->closest(point_body_m);
  const Vec3 from_surface_m = point_body_m - to_vec3(closest);
  const double unsigned_m = from_surface_m.norm();
  const bool in_fluid = impl_->is_inside(point_body_m) == (impl_->fluid_side == FluidSide::inside);
  const double sign = in_fluid ? 1.0 : -1.0;
  if (unsigned_m <= kOnSurfaceFraction * impl_->box_m.diagonal().norm()) {
    const double outward_is_fluid = impl_->fluid_side == FluidSide::outside ? 1.0 : -1.0;
    return {sign * unsigned_m,
            outward_is_fluid * impl_->outward_face_normals[static_cast<std::size_t>(face)]};
  }
  return {sign * unsigned_m, sign * from_surface_m / unsigned_m};
}

bool TriangleMeshSurface::may_be_within(const Vec3 &point_body_m, double radius_m) const {
  const bool fluid_outside = impl_->fluid_side == FluidSide::outside;
  if (impl_->grid && radius_m <= impl_->grid->radius_m()) {
    const VoxelState state = impl_->grid->state_at(point_body_m);
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
  impl_->grid.reset(); // the grid's own flood fill must use exact inside tests
  impl_->grid = std::make_unique<VoxelSideGrid>(
      impl.triangles(), radius_m, [&impl](const Vec3 &p) { return impl.is_inside_exact(p); });
}

bool TriangleMeshSurface::is_inside_mesh(const Vec3 &point_body_m) const {
  return impl_->is_inside(point_body_m);
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

} // namespace fsi::structure::collision
