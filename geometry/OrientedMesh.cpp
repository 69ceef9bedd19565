#include "geometry/OrientedMesh.hpp"

#include "geometry/MeshErrors.hpp"

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>

namespace fsi::geometry {
namespace {

using Point = MeshPoint;
namespace PMP = CGAL::Polygon_mesh_processing;

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

} // namespace

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

TriangleSoup mesh_to_soup(const Mesh &mesh) {
  TriangleSoup soup;
  soup.vertices_m.resize(static_cast<Eigen::Index>(mesh.number_of_vertices()), 3);
  for (auto v : mesh.vertices())
    soup.vertices_m.row(static_cast<Eigen::Index>(v)) = to_vec3(mesh.point(v)).transpose();
  soup.triangles.resize(static_cast<Eigen::Index>(mesh.number_of_faces()), 3);
  for (auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const auto row = static_cast<Eigen::Index>(f);
    soup.triangles(row, 0) = static_cast<int>(mesh.source(h));
    soup.triangles(row, 1) = static_cast<int>(mesh.target(h));
    soup.triangles(row, 2) = static_cast<int>(mesh.target(mesh.next(h)));
  }
  return soup;
}

std::vector<std::array<Vec3, 3>> triangle_corners(const TriangleSoup &soup) {
  std::vector<std::array<Vec3, 3>> corners(static_cast<std::size_t>(soup.triangles.rows()));
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k)
      corners[static_cast<std::size_t>(t)][k] =
          soup.vertices_m.row(soup.triangles(t, k)).transpose();
  }
  return corners;
}

} // namespace fsi::geometry
