#include "geometry/MeshGenerators.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

namespace fsi::geometry {
namespace {

using Face = std::array<int, 3>;

struct UnitSphereMesh {
  std::vector<Vec3> vertices;
  std::vector<Face> faces;
};

UnitSphereMesh make_icosahedron() {
  const double phi = 0.5 * (1.0 + std::sqrt(5.0));
  UnitSphereMesh m;
  m.vertices = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  for (Vec3 &v : m.vertices)
    v.normalize();
  m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return m;
}

/// Splits every face in four, putting the new vertices on the unit sphere.
void subdivide(UnitSphereMesh &m) {
  std::map<std::pair<int, int>, int> midpoint_of;
  auto midpoint = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    const auto found = midpoint_of.find(key);
    if (found != midpoint_of.end())
      return found->second;
    m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
    const int index = static_cast<int>(m.vertices.size()) - 1;
    midpoint_of.emplace(key, index);
    return index;
  };
  std::vector<Face> finer;
  finer.reserve(4 * m.faces.size());
  for (const Face &f : m.faces) {
    const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
    finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
  }
  m.faces = std::move(finer);
}

TriangleSoup to_soup(const std::vector<Vec3> &vertices_m, const std::vector<Face> &faces) {
  TriangleSoup soup;
  soup.vertices_m.resize(static_cast<Eigen::Index>(vertices_m.size()), 3);
  for (std::size_t v = 0; v < vertices_m.size(); ++v) {
    soup.vertices_m.row(static_cast<Eigen::Index>(v)) = vertices_m[v].transpose();
  }
  soup.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    soup.triangles.row(static_cast<Eigen::Index>(f)) << faces[f][0], faces[f][1], faces[f][2];
  }
  return soup;
}

} // namespace

TriangleSoup make_icosphere(const Vec3 &centre_m, double radius_m, int n_subdivisions) {
  if (!(radius_m > 0.0) || n_subdivisions < 0 || n_subdivisions > 8) {
    throw std::invalid_argument("make_icosphere: need radius_m > 0 and 0 <= n_subdivisions <= 8.");
  }
  UnitSphereMesh m = make_icosahedron();
  for (int level = 0; level < n_subdivisions; ++level)
    subdivide(m);
  for (Vec3 &v : m.vertices)
    v = centre_m + radius_m * v;
  return to_soup(m.vertices, m.faces);
}

TriangleSoup make_torus(const Vec3 &centre_m, double major_radius_m, double minor_radius_m,
                        int n_around, int n_tube) {
  if (!(minor_radius_m > 0.0) || !(major_radius_m > minor_radius_m) || n_around < 3 || n_tube < 3) {
    throw std::invalid_argument("make_torus: need 0 < minor_radius_m < major_radius_m and at "
                                "least 3 segments each way.");
  }
  std::vector<Vec3> vertices;
  for (int i = 0; i < n_around; ++i) {
    const double theta = 2.0 * M_PI * i / n_around;
    for (int j = 0; j < n_tube; ++j) {
      const double psi = 2.0 * M_PI * j / n_tube;
      const double ring_m = major_radius_m + minor_radius_m * std::cos(psi);
      vertices.push_back(centre_m + Vec3(ring_m * std::cos(theta), ring_m * std::sin(theta),
                                         minor_radius_m * std::sin(psi)));
    }
  }
  std::vector<Face> faces;
  auto id = [&](int i, int j) { return (i % n_around) * n_tube + (j % n_tube); };
  for (int i = 0; i < n_around; ++i) {
    for (int j = 0; j < n_tube; ++j) {
      faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return to_soup(vertices, faces);
}

TriangleSoup make_box(const Vec3 &min_m, const Vec3 &max_m) {
  if (!(min_m.array() < max_m.array()).all())
    throw std::invalid_argument("make_box: need min_m < max_m on every axis.");
  std::vector<Vec3> vertices; // corner v is (x, y, z) = bits (0, 1, 2) of v
  for (int v = 0; v < 8; ++v)
    vertices.emplace_back(v & 1 ? max_m.x() : min_m.x(), v & 2 ? max_m.y() : min_m.y(), v & 4 ? max_m.z() : min_m.z());
  const std::vector<Face> faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return to_soup(vertices, faces);
}

TriangleSoup make_ring(const Vec3 &base_centre_m, double inner_radius_m, double outer_radius_m, double height_m,
                       int n_around) {
  if (!(inner_radius_m >= 0.0) || !(outer_radius_m > inner_radius_m) || !(height_m > 0.0) || n_around < 3)
    throw std::invalid_argument("make_ring: need 0 <= inner_radius_m < outer_radius_m, height_m > 0 and at "
                                "least 3 corners around.");
  const bool disc = inner_radius_m == 0.0;
  // Vertices: the outer circle at the bottom and the top, then the inner circle at the bottom
  // and the top (a ring) or the two cap centres (a disc).
  std::vector<Vec3> vertices;
  auto add_circle = [&](double radius_m, double z_m) {
    for (int i = 0; i < n_around; ++i) {
      const double angle = 2.0 * M_PI * i / n_around;
      vertices.push_back(base_centre_m + Vec3(radius_m * std::cos(angle), radius_m * std::sin(angle), z_m));
    }
  };
  add_circle(outer_radius_m, 0.0);
  add_circle(outer_radius_m, height_m);
  if (disc) {
    vertices.push_back(base_centre_m);
    vertices.push_back(base_centre_m + Vec3(0.0, 0.0, height_m));
  } else {
    add_circle(inner_radius_m, 0.0);
    add_circle(inner_radius_m, height_m);
  }
  auto id = [&](int circle, int i) { return circle * n_around + i % n_around; }; // circle 0..3 as added
  const int bottom_centre = 2 * n_around, top_centre = 2 * n_around + 1;
  std::vector<Face> faces;
  for (int i = 0; i < n_around; ++i) {
    faces.push_back({id(0, i), id(0, i + 1), id(1, i + 1)}); // outer wall, facing out
    faces.push_back({id(0, i), id(1, i + 1), id(1, i)});
    if (disc) {
      faces.push_back({bottom_centre, id(0, i + 1), id(0, i)}); // bottom cap, facing -z
      faces.push_back({top_centre, id(1, i), id(1, i + 1)});    // top cap, facing +z
      continue;
    }
    faces.push_back({id(2, i), id(3, i + 1), id(2, i + 1)}); // inner wall, facing the axis
    faces.push_back({id(2, i), id(3, i), id(3, i + 1)});
    faces.push_back({id(0, i), id(2, i), id(2, i + 1)}); // bottom annulus, facing -z
    faces.push_back({id(0, i), id(2, i + 1), id(0, i + 1)});
    faces.push_back({id(1, i), id(1, i + 1), id(3, i + 1)}); // top annulus, facing +z
    faces.push_back({id(1, i), id(3, i + 1), id(3, i)});
  }
  return to_soup(vertices, faces);
}

TriangleSoup append_soup(const TriangleSoup &first, const TriangleSoup &second) {
  TriangleSoup both;
  both.vertices_m.resize(first.vertices_m.rows() + second.vertices_m.rows(), 3);
  both.vertices_m << first.vertices_m, second.vertices_m;
  both.triangles.resize(first.triangles.rows() + second.triangles.rows(), 3);
  both.triangles << first.triangles, (second.triangles.array() + static_cast<int>(first.vertices_m.rows())).matrix();
  return both;
}

} // namespace fsi::geometry
