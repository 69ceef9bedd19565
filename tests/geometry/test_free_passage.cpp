// The free passage (widest path of a sphere's centre) against known answers: a slot between
// two slabs, a pipe with a rod across it, a channel closed by a slab, missing start or end
// points; and the lazily queried search against an oracle that queries every grid point and
// joins them in decreasing clearance (union-find: an independent algorithm).

#include "geometry/FreePassage.hpp"
#include "geometry/MeshGenerators.hpp"
#include "geometry/TriangleMeshSurface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

namespace fsi::geometry {
namespace {

using Box = Eigen::AlignedBox3d;
using FluidSide = TriangleMeshSurface::FluidSide;

std::unique_ptr<TriangleMeshSurface> solid(const TriangleSoup &soup) {
  return TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, FluidSide::outside, "test solid");
}

PointPredicate below_z(double z) {
  return [z](const Vec3 &p) { return p.z() <= z; };
}
PointPredicate above_z(double z) {
  return [z](const Vec3 &p) { return p.z() >= z; };
}

TEST(FreePassage, SlotBetweenTwoSlabsPassesItsWidth) {
  const double w = 0.0307, h = 0.002;
  const auto slabs = solid(append_soup(make_box(Vec3(-0.1, -0.1, -0.02), Vec3(0.1, 0.1, 0.0)),
                                       make_box(Vec3(-0.1, -0.1, w), Vec3(0.1, 0.1, w + 0.02))));
  const Box box(Vec3(-0.08, -0.05, -0.01), Vec3(0.08, 0.05, w + 0.01));
  const PassageRegion region{box, inside_any_box({box}), [](const Vec3 &p) { return p.x() <= -0.079; },
                             [](const Vec3 &p) { return p.x() >= 0.079; }};
  const FreePassage passage = find_free_passage(*slabs, region, h);
  ASSERT_EQ(passage.status, FreePassage::Status::passes);
  EXPECT_LE(passage.diameter_m, w + 1e-7);
  EXPECT_GE(passage.diameter_m, w - h); // the grid's nearest plane to the mid-plane is within h / 2
  EXPECT_NEAR(passage.bottleneck_m.z(), 0.5 * w, h);
  EXPECT_NEAR(passage.error_bound_m, std::sqrt(3.0) * h, 1e-15);
  EXPECT_LT(passage.path_m.front().x(), -0.078);
  EXPECT_GT(passage.path_m.back().x(), 0.078);
}

/// A pipe of inner diameter d = 0.1 m along z (96 corners, one on +y) with a rod of square
/// section 2a = 0.02 m across it along x, ending 5 mm short of the wall: the widest way past
/// is beside the rod, a sphere of diameter d / 2 - a = 0.04 m centred at y = 0.03 m.
std::unique_ptr<TriangleMeshSurface> pipe_with_rod() {
  return solid(append_soup(make_ring(Vec3(0, 0, -0.1), 0.05, 0.06, 0.2, 96),
                           make_box(Vec3(-0.045, -0.01, -0.01), Vec3(0.045, 0.01, 0.01))));
}

PassageRegion pipe_region() {
  return {Box(Vec3(-0.05, -0.05, -0.08), Vec3(0.05, 0.05, 0.08)),
          [](const Vec3 &p) { return std::hypot(p.x(), p.y()) < 0.05; }, below_z(-0.075), above_z(0.075)};
}

TEST(FreePassage, PipeBlockedByARodPassesBesideIt) {
  const double h = 0.002;
  const FreePassage passage = find_free_passage(*pipe_with_rod(), pipe_region(), h);
  ASSERT_EQ(passage.status, FreePassage::Status::passes);
  EXPECT_NEAR(passage.diameter_m, 0.04, passage.error_bound_m);
  // The best centre is a grid point; the 96-gon wall lies inside the circle by up to
  // r (1 - cos(pi / 96)) = 2.7e-5 m (measured: 0.039979 m).
  EXPECT_NEAR(passage.diameter_m, 0.04, 6e-5);
  EXPECT_NEAR(std::abs(passage.bottleneck_m.y()), 0.03, h); // beside the rod, against the wall
  EXPECT_LE(std::abs(passage.bottleneck_m.z()), 0.02 + h);
  EXPECT_LT(passage.n_distance_queries, passage.n_allowed_points);
}

TEST(FreePassage, ASlabAcrossTheWholeChannelBlocksIt) {
  const auto slab = solid(make_box(Vec3(-0.05, -0.05, 0.04), Vec3(0.15, 0.15, 0.06)));
  const Box box(Vec3(0, 0, 0), Vec3(0.1, 0.1, 0.1));
  const FreePassage passage =
      find_free_passage(*slab, {box, inside_any_box({box}), below_z(0.001), above_z(0.099)}, 0.004);
  EXPECT_EQ(passage.status, FreePassage::Status::blocked);
  EXPECT_EQ(passage.diameter_m, 0.0);
  EXPECT_TRUE(passage.path_m.empty());
}

TEST(FreePassage, MissingStartOrEndPointsAreReported) {
  const auto slab = solid(make_box(Vec3(0, 0, 0.04), Vec3(0.1, 0.1, 0.06)));
  const Box box(Vec3(0, 0, 0), Vec3(0.1, 0.1, 0.1));
  const PointPredicate nowhere = [](const Vec3 &) { return false; };
  EXPECT_EQ(find_free_passage(*slab, {box, inside_any_box({box}), nowhere, above_z(0.099)}, 0.01).status,
            FreePassage::Status::no_start);
  EXPECT_EQ(find_free_passage(*slab, {box, inside_any_box({box}), below_z(0.001), nowhere}, 0.01).status,
            FreePassage::Status::no_end);
  EXPECT_EQ(FreePassage::status_name(FreePassage::Status::no_end), "no end point");
  EXPECT_THROW(find_free_passage(*slab, {box, inside_any_box({box}), nowhere, nowhere}, 0.0), std::invalid_argument);
}

/// The widest-path bottleneck by brute force: every grid point's clearance, then points
/// joined in decreasing clearance until the start and the end are connected.
double oracle_bottleneck(const RigidSurface &surface, const PassageRegion &region, double h) {
  const Vec3 size = region.bounds_m.sizes();
  const int nx = static_cast<int>(std::floor(size.x() / h * (1 + 1e-12))) + 1;
  const int ny = static_cast<int>(std::floor(size.y() / h * (1 + 1e-12))) + 1;
  const int nz = static_cast<int>(std::floor(size.z() / h * (1 + 1e-12))) + 1;
  const int n = nx * ny * nz, start = n, end = n + 1;
  std::vector<double> clearance(n, -1.0);
  std::vector<int> parent(n + 2);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  std::vector<int> order;
  for (int index = 0; index < n; ++index) {
    const Vec3 p = region.bounds_m.min() + h * Vec3(index % nx, index / nx % ny, index / nx / ny);
    if (region.allowed(p)) {
      clearance[index] = std::max(0.0, surface.distance(p).signed_distance_m);
      order.push_back(index);
    }
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) { return clearance[a] > clearance[b]; });
  std::vector<bool> added(n, false);
  for (const int index : order) {
    if (clearance[index] <= 0.0)
      break;
    added[index] = true;
    const int i = index % nx, j = index / nx % ny, k = index / nx / ny;
    const Vec3 p = region.bounds_m.min() + h * Vec3(i, j, k);
    if (region.start(p))
      parent[find(index)] = find(start);
    if (region.end(p))
      parent[find(index)] = find(end);
    for (int dk = -1; dk <= 1; ++dk)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj, c = k + dk;
          if (a >= 0 && b >= 0 && c >= 0 && a < nx && b < ny && c < nz && added[(c * ny + b) * nx + a])
            parent[find((c * ny + b) * nx + a)] = find(index);
        }
    if (find(start) == find(end))
      return clearance[index];
  }
  return 0.0;
}

TEST(FreePassage, LazyQueriesGiveTheAnswerOfQueryingEveryPoint) {
  // The pipe with its rod, plus a ball off the axis above the rod: the widest way winds.
  const TriangleSoup soup = append_soup(append_soup(make_ring(Vec3(0, 0, -0.1), 0.05, 0.06, 0.2, 96),
                                                    make_box(Vec3(-0.045, -0.013, -0.01), Vec3(0.03, 0.01, 0.01))),
                                        make_icosphere(Vec3(0.012, 0.021, 0.04), 0.018, 3));
  const auto surface = solid(soup);
  for (const double h : {0.0025, 0.0031}) {
    const FreePassage passage = find_free_passage(*surface, pipe_region(), h);
    ASSERT_EQ(passage.status, FreePassage::Status::passes);
    EXPECT_NEAR(passage.diameter_m, 2.0 * oracle_bottleneck(*surface, pipe_region(), h), 1e-7) << "h = " << h;
    EXPECT_NEAR(std::max(0.0, surface->distance(passage.bottleneck_m).signed_distance_m), 0.5 * passage.diameter_m,
                1e-7);
  }
}

} // namespace
} // namespace fsi::geometry
