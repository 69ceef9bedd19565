// Timing of TriangleMeshSurface queries and of CollisionSet::correct() against a torus of
// 102,400 triangles (tube radius 48 mm, triangles about 2 mm) with d_c = d_t = 4 mm: per-call
// cost of distance() for far, near and deep-inside points, and of one correction of 10^4
// points of which 2 %, 30 % or 100 % lie on the torus (a sheet draped over the tube's top,
// 2 mm into it to 3.5 mm above it, off the mesh's planes of symmetry, where two triangles
// would tie); the other points are far above. The checksums let two versions be compared.
// Uses only the public API, so the same file times any version of the module. Not a test:
// run it with `./fsi bench mesh_surface [repeats]`; BENCH_ONLY=near times
// only the distance() cases whose name holds "near".

#include "structure_solver/collision/CollisionSet.hpp"
#include "geometry/MeshGenerators.hpp"
#include "geometry/TriangleMeshSurface.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace fsi;
using namespace fsi::geometry;
using namespace fsi::structure::collision;
using Clock = std::chrono::steady_clock;

constexpr double kMajor_m = 0.12, kMinor_m = 0.048, kThreshold_m = 0.004;

/// Results of the timed loops end here, so that the compiler keeps the loops.
volatile double g_sink = 0.0;

/// Point at angles (theta around the axis, psi around the tube), `offset_m` along the normal.
Vec3 on_torus(double theta, double psi, double offset_m) {
  const Vec3 normal(std::cos(psi) * std::cos(theta), std::cos(psi) * std::sin(theta),
                    std::sin(psi));
  const Vec3 centre_line(kMajor_m * std::cos(theta), kMajor_m * std::sin(theta), 0.0);
  return centre_line + (kMinor_m + offset_m) * normal;
}

/// Deterministic value in [0, 1) for point k.
double unit_hash(int k) {
  return std::fmod(std::abs(std::sin(12.9898 * k + 78.233)) * 43758.5453, 1.0);
}

/// A 100 x 100 sheet: the first n_contact points draped over the tube, the others far above.
PointArray sheet(int n_contact) {
  PointArray points(10000, 3);
  for (int k = 0; k < 10000; ++k) {
    const int i = k % 100, j = k / 100;
    Vec3 p;
    if (k < n_contact) {
      const double offset_m = -0.002 + 0.0055 * unit_hash(k);
      p = on_torus(0.004 / kMajor_m * (j + 0.37), M_PI / 2 + 0.024 * (i - 50), offset_m);
    } else {
      p = Vec3(-0.2 + 0.004 * i, -0.2 + 0.004 * j, kMinor_m + 0.06);
    }
    points.row(k) = p.transpose();
  }
  return points;
}

/// Seconds per call of f, the median of `repeats` timings of about 0.2 s each.
double seconds_per_call(const std::function<void()> &f, int repeats) {
  int n_calls = 1;
  for (;; n_calls *= 2) { // calibrate: enough calls for about 0.2 s
    const auto start = Clock::now();
    for (int c = 0; c < n_calls; ++c)
      f();
    if (std::chrono::duration<double>(Clock::now() - start).count() > 0.2)
      break;
  }
  std::vector<double> samples;
  for (int r = 0; r < repeats; ++r) {
    const auto start = Clock::now();
    for (int c = 0; c < n_calls; ++c)
      f();
    samples.push_back(std::chrono::duration<double>(Clock::now() - start).count() / n_calls);
  }
  std::sort(samples.begin(), samples.end());
  return samples[samples.size() / 2];
}

void time_distance(const TriangleMeshSurface &surface, const char *name,
                   const std::function<Vec3(int)> &point, int repeats) {
  if (std::getenv("BENCH_ONLY") &&
      std::string(name).find(std::getenv("BENCH_ONLY")) == std::string::npos)
    return;
  std::vector<Vec3> points;
  for (int k = 0; k < 1000; ++k)
    points.push_back(point(k));
  double checksum = 0.0;
  for (const Vec3 &p : points)
    checksum +=
        surface.may_be_within(p, kThreshold_m) ? surface.distance(p).signed_distance_m : 0.0;
  const double s = seconds_per_call(
      [&] {
        double sum = 0.0;
        for (const Vec3 &p : points) {
          if (surface.may_be_within(p, kThreshold_m))
            sum += surface.distance(p).signed_distance_m;
        }
        g_sink = sum;
      },
      repeats);
  std::printf("  %-30s %8.3f us per point (checksum %.12g)\n", name, s / 1000 * 1e6, checksum);
}

} // namespace

int main(int argc, char **argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 5;
  const auto build_start = Clock::now();
  const TriangleSoup torus = make_torus(Vec3::Zero(), kMajor_m, kMinor_m, 320, 160);
  auto surface = TriangleMeshSurface::from_triangles(torus.vertices_m, torus.triangles,
                                                     TriangleMeshSurface::FluidSide::outside);
  const double built_s = std::chrono::duration<double>(Clock::now() - build_start).count();
  surface->prepare_culling(kThreshold_m);
  const double culling_s =
      std::chrono::duration<double>(Clock::now() - build_start).count() - built_s;
  std::printf("torus: %zu triangles, built in %.2f s, culling data in %.2f s\n",
              surface->n_triangles(), built_s, culling_s);

  std::printf("distance() after may_be_within(d_c), 1000 points each:\n");
  const auto angle = [](int k, int salt) { return 2 * M_PI * unit_hash(7 * k + salt); };
  time_distance(
      *surface, "far (60 mm above)",
      [&](int k) { return on_torus(angle(k, 1), angle(k, 2), 0.06); }, repeats);
  time_distance(
      *surface, "near, outside (0.1-4 mm)",
      [&](int k) { return on_torus(angle(k, 1), angle(k, 2), 0.0001 + 0.0039 * unit_hash(k)); },
      repeats);
  time_distance(
      *surface, "near, band edge (4-5.5 mm)",
      [&](int k) { return on_torus(angle(k, 1), angle(k, 2), 0.004 + 0.0015 * unit_hash(k)); },
      repeats);
  time_distance(
      *surface, "near, inside (0.1-4 mm deep)",
      [&](int k) { return on_torus(angle(k, 1), angle(k, 2), -0.0001 - 0.0039 * unit_hash(k)); },
      repeats);
  time_distance(
      *surface, "deep inside (10-40 mm deep)",
      [&](int k) { return on_torus(angle(k, 1), angle(k, 2), -0.01 - 0.03 * unit_hash(k)); },
      repeats);

  auto set = std::make_unique<CollisionSet>(kThreshold_m, kThreshold_m);
  set->add_surface(std::move(surface), std::make_shared<motion::StaticPose>());
  std::printf("CollisionSet::correct(), 10^4 points:\n");
  for (const int n_contact : {200, 3000, 10000}) {
    const PointArray original = sheet(n_contact);
    PointArray positions = original;
    const CorrectionStats stats = set->correct(positions, 0.0);
    const double s = seconds_per_call(
        [&] {
          positions = original;
          set->correct(positions, 0.0);
        },
        repeats);
    std::printf("  contact %5.1f %%: %8.3f ms per call (%zu points corrected, %zu passes, "
                "checksum %.12g)\n",
                n_contact / 100.0, s * 1e3, stats.n_points_corrected, stats.n_passes,
                (positions - original).sum());
  }
  return 0;
}
