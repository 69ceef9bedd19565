#include "SolidMesher.hpp"

#include "GmshSession.hpp"

#include <gmsh.h>

#include <cmath>
#include <unordered_map>

namespace fsi::pump {
namespace {

void set_mesh_options(const MeshSizes &sizes) {
  gmsh::option::setNumber("Mesh.MeshSizeMax", sizes.max_size_m);
  gmsh::option::setNumber("Mesh.MeshSizeMin", sizes.min_size_m);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", sizes.elements_per_2pi);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  gmsh::option::setNumber("Mesh.Algorithm", 6); // Frontal-Delaunay: regular triangles on CAD faces
}

/// The triangles of one face, as indices into `surface` (nodes appended on first use).
std::vector<std::array<int, 3>> face_triangles(int face, std::unordered_map<std::size_t, int> &index_of_node,
                                               RegionSurface &surface) {
  std::vector<std::size_t> element_tags, node_tags;
  gmsh::model::mesh::getElementsByType(2, element_tags, node_tags, face);
  std::vector<std::array<int, 3>> tris(element_tags.size());
  for (std::size_t e = 0; e < element_tags.size(); ++e)
    for (int k = 0; k < 3; ++k) {
      const std::size_t node = node_tags[3 * e + k];
      auto found = index_of_node.find(node);
      if (found == index_of_node.end()) {
        std::vector<double> coord, parametric;
        gmsh::model::mesh::getNode(node, coord, parametric);
        found = index_of_node.emplace(node, static_cast<int>(surface.vertices_m.size())).first;
        surface.vertices_m.emplace_back(coord[0], coord[1], coord[2]);
      }
      tris[e][k] = found->second;
    }
  return tris;
}

CadFace measure_face(int face, const RegionSurface &surface, std::size_t first, std::size_t end) {
  CadFace info;
  info.tag = face;
  gmsh::model::getType(2, face, info.surface_type);
  info.lower_m = Vec3::Constant(1e300);
  info.upper_m = Vec3::Constant(-1e300);
  info.min_radius_m = 1e300;
  info.max_radius_m = 0.0;
  for (std::size_t t = first; t < end; ++t) {
    const auto &tri = surface.triangles[t];
    const Vec3 &a = surface.vertices_m[tri[0]], &b = surface.vertices_m[tri[1]], &c = surface.vertices_m[tri[2]];
    const Vec3 doubled_normal = (b - a).cross(c - a);
    const Vec3 centre = (a + b + c) / 3.0;
    info.area_m2 += 0.5 * doubled_normal.norm();
    const double radius = std::hypot(centre[0], centre[1]);
    if (radius > 0.0)
      info.swirl_m2 += 0.5 * doubled_normal.dot(Vec3(-centre[1], centre[0], 0.0) / radius);
    for (const int v : tri) {
      const Vec3 &p = surface.vertices_m[v];
      info.nodes_m.push_back(p);
      info.lower_m = info.lower_m.cwiseMin(p);
      info.upper_m = info.upper_m.cwiseMax(p);
      info.min_radius_m = std::min(info.min_radius_m, std::hypot(p[0], p[1]));
      info.max_radius_m = std::max(info.max_radius_m, std::hypot(p[0], p[1]));
    }
  }
  return info;
}

} // namespace

RegionSurface mesh_solid(const std::string &part, int volume_tag, const MeshSizes &sizes,
                         const std::vector<std::string> &region_names,
                         const std::function<int(const CadFace &)> &classify) {
  gmsh_step(part, "surface meshing", [&] {
    set_mesh_options(sizes);
    gmsh::model::mesh::generate(2);
  });
  RegionSurface surface;
  surface.region_names = region_names;
  gmsh::vectorpair faces;
  gmsh_step(part, "reading the faces", [&] {
    gmsh::model::getBoundary({{3, volume_tag}}, faces, false, false, false);
  });
  std::unordered_map<std::size_t, int> index_of_node;
  std::vector<std::pair<int, std::size_t>> face_starts; // (face, first triangle)
  gmsh_step(part, "reading the triangles", [&] {
    for (const auto &[dim, face] : faces) {
      face_starts.emplace_back(face, surface.triangles.size());
      for (const auto &tri : face_triangles(face, index_of_node, surface))
        surface.triangles.push_back(tri);
    }
  });
  surface.orient_outward(part);
  surface.triangle_regions.assign(surface.triangles.size(), -1);
  for (std::size_t f = 0; f < face_starts.size(); ++f) {
    const std::size_t first = face_starts[f].second;
    const std::size_t end = f + 1 < face_starts.size() ? face_starts[f + 1].second : surface.triangles.size();
    const CadFace info =
        gmsh_step(part, "measuring a face", [&] { return measure_face(face_starts[f].first, surface, first, end); });
    const int region = classify(info);
    for (std::size_t t = first; t < end; ++t)
      surface.triangle_regions[t] = region;
  }
  surface.split_caps();
  surface.check_closed_and_outward(part);
  return surface;
}

} // namespace fsi::pump
