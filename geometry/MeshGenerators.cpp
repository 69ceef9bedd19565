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

} // namespace fsi::geometry
