// Timing of geometry::find_free_passage on the size: a 0.2 m x 0.2 m x 0.1 m box at
// h = 1.5 mm (1.2 million grid points) around a torus of 102,400 triangles (major radius
// 0.06 m, tube 0.02 m) with a disc of radius 0.03 m in its hole, from the box's bottom to its
// top: once with the whole box allowed (the sphere goes round the torus), once confined to
// r < 0.085 m (it squeezes through the 10 mm gaps). Prints the passage, the number of distance
// queries the lazy bounds left and the time. Not a test: `./fsi bench free_passage`.

#include "geometry/FreePassage.hpp"
#include "geometry/MeshGenerators.hpp"
#include "geometry/TriangleMeshSurface.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

int main() {
  using namespace fsi;
  using namespace fsi::geometry;
  const TriangleSoup soup =
      append_soup(make_torus(Vec3::Zero(), 0.06, 0.02, 320, 160), make_ring(Vec3(0, 0, -0.005), 0.0, 0.03, 0.01, 256));
  const auto solid = TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles,
                                                         TriangleMeshSurface::FluidSide::outside, "torus and disc");
  const Eigen::AlignedBox3d box(Vec3(-0.1, -0.1, -0.05), Vec3(0.1, 0.1, 0.05));
  const PointPredicate start = [](const Vec3 &p) { return p.z() <= -0.049; };
  const PointPredicate end = [](const Vec3 &p) { return p.z() >= 0.049; };
  const PointPredicate confined = [](const Vec3 &p) { return std::hypot(p.x(), p.y()) < 0.085; };
  for (const auto &[name, allowed] :
       {std::pair{"whole box", inside_any_box({box})}, std::pair{"r < 0.085 m", confined}}) {
    const auto t0 = std::chrono::steady_clock::now();
    const FreePassage passage = find_free_passage(*solid, {box, allowed, start, end}, 0.0015);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-12s %s: %.2f mm (+-%.2f) stuck at (%.4f, %.4f, %.4f) m; %zu distance queries for %zu points; "
                "%.2f s\n",
                name, FreePassage::status_name(passage.status).c_str(), 1e3 * passage.diameter_m,
                1e3 * passage.error_bound_m, passage.bottleneck_m.x(), passage.bottleneck_m.y(),
                passage.bottleneck_m.z(), passage.n_distance_queries, passage.n_allowed_points, seconds);
  }
  return 0;
}
