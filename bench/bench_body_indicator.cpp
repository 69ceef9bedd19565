// Hand-run timing of the per-step indicator update (not a test): a 102,400-triangle torus
// (make_torus 320 x 160) spinning about its own symmetry axis, like an impeller, in a unit
// cube of 10^5 and 3 x 10^5 uniform cells; then the same torus off-axis. Prints the one-off
// costs (body, candidates) and the mean per-step update, sharp and cell fraction, on 1 and
// on all threads.
//   ./fsi bench body_indicator [n_steps]

#include "motion/AxisRotation.hpp"
#include "fluid_adapter/rigid/BodyIndicator.hpp"
#include "geometry/MeshGenerators.hpp"
#include "TestGrids.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

using namespace fsi;
using namespace fsi::fluid::rigid;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::shared_ptr<motion::AxisRotation> spin_about_z(double rate_rad_per_s) {
  return std::make_shared<motion::AxisRotation>(
      Vec3::Zero(), Vec3::UnitZ(), [rate_rad_per_s](double t) { return rate_rad_per_s * t; },
      [rate_rad_per_s](double) { return rate_rad_per_s; });
}

void time_updates(const RigidBody &body, const PointArray &centres, IndicatorOptions options,
                  int n_steps, const char *label) {
  const double h = 1.0 / std::cbrt(static_cast<double>(centres.rows()));
  auto start = std::chrono::steady_clock::now();
  BodyIndicator indicator(body, centres, options, Eigen::VectorXd::Constant(centres.rows(), h));
  const double setup_s = seconds_since(start);
  indicator.update(0.0);
  start = std::chrono::steady_clock::now();
  for (int step = 1; step <= n_steps; ++step)
    indicator.update(step * 1e-4); // 150 rad/s x 1e-4 s: 0.86 degrees a step
  const double step_s = seconds_since(start) / n_steps;
  std::printf("  %-34s threads %zu: candidates %7zu (%4.1f %%), inside %6zu, setup %6.1f ms, "
              "update %7.2f ms/step (%.0f ns/candidate)\n",
              label, options.n_threads, indicator.candidate_cells().size(),
              100.0 * indicator.candidate_cells().size() / centres.rows(), indicator.inside_cells().size(),
              1e3 * setup_s, 1e3 * step_s, 1e9 * step_s / indicator.candidate_cells().size());
}

} // namespace

int main(int argc, char **argv) {
  const int n_steps = argc > 1 ? std::atoi(argv[1]) : 20;
  const std::size_t all_threads = std::max(1u, std::thread::hardware_concurrency());
  for (const bool on_axis : {true, false}) {
    const Vec3 centre_m = on_axis ? Vec3::Zero() : Vec3(0.2, 0.0, 0.0);
    auto start = std::chrono::steady_clock::now();
    const auto body = RigidBody::from_soup(
        "torus", geometry::make_torus(centre_m, 0.22, 0.07, 320, 160), spin_about_z(150.0));
    std::printf("torus %s the rotation axis, %zu triangles: body built in %.2f s\n",
                on_axis ? "about" : "off", body->surface().n_triangles(), seconds_since(start));
    for (const int n : {47, 67}) {
      const PointArray centres = fluid::rigid::testing::uniform_centres(-0.5, 0.5, n);
      std::printf(" %lld cells\n", static_cast<long long>(centres.rows()));
      for (const std::size_t threads : {std::size_t{1}, all_threads}) {
        IndicatorOptions options;
        options.n_threads = threads;
        time_updates(*body, centres, options, n_steps, "sharp");
        options.sampling = IndicatorOptions::Sampling::cell_fraction;
        time_updates(*body, centres, options, n_steps / 4 + 1, "cell fraction 4^3");
      }
    }
  }
}
