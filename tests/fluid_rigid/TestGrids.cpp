#include "TestGrids.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>

namespace fsi::fluid::rigid::testing {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
} // namespace

PointArray uniform_centres(double lo_m, double hi_m, int n) {
  const double h = (hi_m - lo_m) / n;
  PointArray centres(static_cast<Eigen::Index>(n) * n * n, 3);
  Eigen::Index row = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        centres.row(row++) << lo_m + (i + 0.5) * h, lo_m + (j + 0.5) * h, lo_m + (k + 0.5) * h;
  return centres;
}

std::vector<int> brute_force_inside(const geometry::TriangleSoup &body_soup,
                                    const Eigen::Isometry3d &pose, const PointArray &points_m) {
  std::vector<Point> vertices;
  for (Eigen::Index v = 0; v < body_soup.vertices_m.rows(); ++v) {
    const Vec3 x = pose * Vec3(body_soup.vertices_m.row(v).transpose());
    vertices.emplace_back(x.x(), x.y(), x.z());
  }
  std::vector<std::array<std::size_t, 3>> faces;
  for (Eigen::Index t = 0; t < body_soup.triangles.rows(); ++t)
    faces.push_back({static_cast<std::size_t>(body_soup.triangles(t, 0)),
                     static_cast<std::size_t>(body_soup.triangles(t, 1)),
                     static_cast<std::size_t>(body_soup.triangles(t, 2))});
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(vertices, faces, mesh);
  const CGAL::Side_of_triangle_mesh<Mesh, Kernel> side_of(mesh);
  std::vector<int> inside(static_cast<std::size_t>(points_m.rows()));
  for (Eigen::Index p = 0; p < points_m.rows(); ++p)
    inside[static_cast<std::size_t>(p)] =
        side_of(Point(points_m(p, 0), points_m(p, 1), points_m(p, 2))) == CGAL::ON_BOUNDED_SIDE;
  return inside;
}

double enclosed_volume(const geometry::TriangleSoup &soup) {
  double six_volume = 0.0;
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    const Vec3 a = soup.vertices_m.row(soup.triangles(t, 0)).transpose();
    const Vec3 b = soup.vertices_m.row(soup.triangles(t, 1)).transpose();
    const Vec3 c = soup.vertices_m.row(soup.triangles(t, 2)).transpose();
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6.0;
}

} // namespace fsi::fluid::rigid::testing
