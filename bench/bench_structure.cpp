// ./fsi bench structure: time per step of the membrane (Eq. 4, one semi-implicit solve) against
// the number of Lagrangian points (10^2 to 10^5), without collisions and with collisions (Eq. 11)
// against a rotating closed mesh of about 100k triangles (a torus spinning at 150 rad/s, the
// single-blade pump's speed). Paper parameters: Delta s = 0.004 m, Delta t = 5e-5 s,
// rho_1 = 0.03 kg/m^2, phi = 10 N/m, zeta = 1e-8 N m (section 4.2). The sheet hangs just above
// the torus (2 mm above the tube's top) so that part of it is within the collision threshold
// (d_c = 4 mm) every step.
// Counters: us_per_point (flat when the cost is linear in the number of points).

#include "case/CaseConfig.hpp"
#include "case/ModuleSetups.hpp"
#include "structure_solver/Scene.hpp"
#include "geometry/MeshGenerators.hpp"
#include "geometry/StlIo.hpp"

#include <benchmark/benchmark.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

using namespace fsi;

std::filesystem::path bench_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "fsi-bench-structure";
  std::filesystem::create_directories(dir);
  return dir;
}

/// A torus of ~100k triangles below a sheet of side `side_m` (written once per size).
std::filesystem::path torus_stl(double side_m) {
  const auto path = bench_dir() / ("torus-" + std::to_string(side_m) + ".stl");
  if (!std::filesystem::exists(path)) {
    const auto soup = geometry::make_torus(Vec3(side_m / 2, side_m / 2, -0.12 * side_m), 0.3 * side_m,
                                                       0.12 * side_m, 250, 200); // tube top at z = 0
    geometry::write_stl(path.string(), soup, geometry::StlFormat::binary);
  }
  return path;
}

std::unique_ptr<structure::Scene> make_scene(int n, bool collisions) {
  const double ds = 0.004, side = ds * (n - 1);
  std::string yaml = "run: {end_time_s: 1, time_step_s: 5.0e-5, output_interval_s: 0.01}\n"
                     "gravity_m_per_s2: [0, 0, -9.81]\n";
  if (collisions)
    yaml += "collisions:\n  threshold_m: 0.004\n  target_distance_m: 0.004\n  surfaces:\n"
            "    - mesh: {file: " + torus_stl(side).string() + "}\n"
            "      motion: {rotation: {axis_point_m: [" + std::to_string(side / 2) + ", " + std::to_string(side / 2) +
            ", 0], axis_direction: [0, 0, 1], rate_rad_per_s: 150.8}}\n";
  yaml += "structures:\n  - name: rag\n    model: membrane\n    size_m: [" + std::to_string(side) + ", " +
          std::to_string(side) + "]\n    n_points: [" + std::to_string(n) + ", " + std::to_string(n) +
          "]\n    origin_m: [0, 0, 0.002]\n    material:\n      mass_per_area_kg_per_m2: 0.03\n"
          "      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-8}\n";
  const auto dir = bench_dir() / ("case-" + std::to_string(n) + (collisions ? "-c" : ""));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "case.yaml") << yaml;
  return std::make_unique<structure::Scene>(case_config::structure_setup(case_config::CaseConfig::load(dir)));
}

void membrane_step(benchmark::State &state) {
  const int n = static_cast<int>(state.range(0));
  const bool collisions = state.range(1) != 0;
  auto scene = make_scene(n, collisions);
  for (int k = 0; k < 5; ++k) // warm-up: the first steps set up the solver
    scene->advance();
  std::size_t corrected = 0, iterations = 0;
  for (auto _ : state) {
    scene->advance();
    corrected += scene->last_corrections();
    iterations += static_cast<std::size_t>(scene->last_solver_iterations());
  }
  state.counters["cg_iterations"] = static_cast<double>(iterations) / static_cast<double>(state.iterations());
  const double points = static_cast<double>(n) * n;
  state.counters["points"] = points;
  state.counters["us_per_point"] = benchmark::Counter(points * static_cast<double>(state.iterations()),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["corrected_per_step"] = static_cast<double>(corrected) / static_cast<double>(state.iterations());
}

} // namespace

BENCHMARK(membrane_step)
    ->ArgsProduct({{10, 32, 100, 316}, {0, 1}})
    ->ArgNames({"n_side", "collisions"})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

int main(int argc, char **argv) {
  spdlog::set_level(spdlog::level::warn);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
