// Analytic verification of the structure solver through the real case parser.
// Each test states the theory, why its assumptions hold for the chosen parameters, and the
// tolerance. All quantities SI.

#include "CaseFixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace fsi::structure {
namespace {

using testing::load_case;
using testing::mean_period;
using testing::sheet;
using testing::upward_crossings;

constexpr double g = 9.81;

/// Runs `steps` steps, sampling `probe(scene)` every `every` steps.
template <class Probe>
void run_sampled(Scene &scene, long steps, long every, std::vector<double> &t, std::vector<double> &y, Probe probe) {
  for (long k = 1; k <= steps; ++k) {
    scene.advance();
    if (k % every == 0) {
      t.push_back(scene.time_s());
      y.push_back(probe(scene));
    }
  }
}

std::string filament_case(const std::string &keys, double dt, const std::string &gravity) {
  return "run: {end_time_s: 10, time_step_s: " + std::to_string(dt) + ", output_interval_s: 0.01}\n"
         "gravity_m_per_s2: " + gravity + "\nstructures:\n  - name: f\n    model: filament\n" + keys;
}

// Hanging chain (filament pinned at the top, free at the bottom, negligible bending):
// small lateral oscillations have omega_n = (j_0,n / 2) sqrt(g / L) with mode shapes
// J0(j_0,n sqrt(z / L)), z measured up from the free end. Assumptions: inextensible
// (max strain rho g L / (2 phi) = 0.5 %), bending-free (zeta / (rho g L^3) = 1e-7), small
// amplitude (1 cm on 1 m). Tolerance 1 % on the period (discretisation O(ds^2) ~ 0.1 %).
TEST(AnalyticCases, HangingChainOscillatesAtTheBesselFrequency) {
  const double length = 1.0, rho = 0.1, phi = 100.0, j01 = 2.404825557695773;
  const int n = 81;
  auto config = load_case(filament_case("    length_m: 1.0\n    n_points: 81\n    direction: [0, 0, -1]\n"
                                        "    linear_density_kg_per_m: 0.1\n    tension_coefficient_n: 100\n"
                                        "    bending_rigidity_n_m2: 1.0e-7\n    ends: {start: pinned, end: free}\n",
                                        1e-4, "[0, 0, -9.81]"));
  Scene scene(config);
  auto &chain = sheet(scene);
  // Start from the discrete static equilibrium (each edge carries the weight below it:
  // phi (lambda^2 - 1) lambda = W) displaced laterally by the first mode shape.
  const Eigen::VectorXd measure = chain.point_measures();
  PointArray x(n, 3);
  x.row(0).setZero();
  double weight_below = rho * g * measure.sum() - rho * g * measure[0];
  const double ds = length / (n - 1);
  for (int i = 1; i < n; ++i) {
    double lambda = 1.0;
    for (int it = 0; it < 30; ++it)
      lambda -= (phi * (lambda * lambda - 1) * lambda - weight_below) / (phi * (3 * lambda * lambda - 1));
    x.row(i) = x.row(i - 1) - Eigen::RowVector3d(0, 0, lambda * ds);
    weight_below -= rho * g * measure[i];
  }
  for (int i = 0; i < n; ++i)
    x(i, 0) = 0.01 * std::cyl_bessel_j(0.0, j01 * std::sqrt((length - i * ds) / length));
  chain.set_state(x, x);
  std::vector<double> t, tip;
  run_sampled(scene, 52000, 5, t, tip, [&](const Scene &) { return chain.positions_m()(n - 1, 0); });
  const auto crossings = upward_crossings(t, tip);
  ASSERT_GE(crossings.size(), 3u);
  const double period = mean_period(crossings), expected = 4.0 * M_PI / (j01 * std::sqrt(g / length));
  std::printf("hanging chain: period %.5f s, theory %.5f s, error %.3f %%\n", period, expected,
              100 * (period / expected - 1));
  EXPECT_NEAR(period / expected, 1.0, 0.01);
}

// Cantilever (clamped at s = 0, free tip) under its own weight: Euler-Bernoulli tip deflection
// q L^4 / (8 EI). delta / L = 1.2e-3, so linear theory holds; the filament is nearly
// inextensible (phi = 1000 N). Damping drives the run to the static state; the static
// solution of Eq. (4) does not depend on the damping. Tolerance 1 % (O(ds^2) ~ 0.1 %).
TEST(AnalyticCases, CantileverStaticDeflectionMatchesEulerBernoulli) {
  auto config = load_case(filament_case("    length_m: 1.0\n    n_points: 41\n    direction: [1, 0, 0]\n"
                                        "    bend_direction: [0, 0, 1]\n    linear_density_kg_per_m: 0.1\n"
                                        "    tension_coefficient_n: 1000\n    bending_rigidity_n_m2: 100\n"
                                        "    damping_kg_per_m_s: 20\n    ends: {start: clamped, end: free}\n",
                                        1e-4, "[0, 0, -9.81]"));
  Scene scene(config);
  for (int k = 0; k < 4000; ++k)
    scene.advance();
  const double deflection = -sheet(scene).positions_m()(40, 2);
  const double expected = 0.1 * g / (8.0 * 100.0);
  std::printf("cantilever: tip deflection %.6e m, theory %.6e m, error %.3f %%\n", deflection, expected,
              100 * (deflection / expected - 1));
  EXPECT_NEAR(deflection / expected, 1.0, 0.01);
}

// Cantilever first natural frequency: omega_1 = (1.8751)^2 sqrt(EI / (rho L^4)), released
// from its first mode shape (amplitude 1 mm on 1 m, no gravity). Tolerance 1 %.
TEST(AnalyticCases, CantileverFirstFrequencyMatchesEulerBernoulli) {
  auto config = load_case(filament_case("    length_m: 1.0\n    n_points: 41\n    direction: [1, 0, 0]\n"
                                        "    bend_direction: [0, 0, 1]\n    linear_density_kg_per_m: 0.1\n"
                                        "    tension_coefficient_n: 1000\n    bending_rigidity_n_m2: 100\n"
                                        "    ends: {start: clamped, end: free}\n"
                                        "    solver: {time_scheme: energy_conserving}\n",
                                        1e-4, "[0, 0, 0]"));
  Scene scene(config);
  auto &beam = sheet(scene);
  const double beta = 1.875104068711961, sigma = (std::cosh(beta) + std::cos(beta)) / (std::sinh(beta) + std::sin(beta));
  const auto mode = [&](double s) {
    return std::cosh(beta * s) - std::cos(beta * s) - sigma * (std::sinh(beta * s) - std::sin(beta * s));
  };
  PointArray x = beam.positions_m();
  for (int i = 0; i < 41; ++i)
    x(i, 2) = 1e-3 * mode(i / 40.0) / mode(1.0);
  beam.set_state(x, x);
  std::vector<double> t, tip;
  run_sampled(scene, 3000, 1, t, tip, [&](const Scene &) { return beam.positions_m()(40, 2); });
  const double period = mean_period(upward_crossings(t, tip));
  const double expected = 2 * M_PI / (beta * beta * std::sqrt(100.0 / 0.1));
  std::printf("cantilever: period %.6f s, theory %.6f s, error %.3f %%\n", period, expected,
              100 * (period / expected - 1));
  EXPECT_NEAR(period / expected, 1.0, 0.01);
}

/// Central deflection of a square plate a = 1 m, D = zeta = 1 N m, uniform load q = rho g.
double plate_center_deflection(int n, const std::string &edge) {
  const std::string yaml =
      "run: {end_time_s: 10, time_step_s: 1.0e-3, output_interval_s: 0.01}\n"
      "gravity_m_per_s2: [0, 0, -1.0e-3]\n"
      "structures:\n  - name: plate\n    model: membrane\n    size_m: [1, 1]\n    n_points: [" +
      std::to_string(n) + ", " + std::to_string(n) +
      "]\n    material:\n      mass_per_area_kg_per_m2: 1.0\n      damping_kg_per_m2_s: 40\n"
      "      coefficients: {tension_coefficient_n_per_m: 100, bending_rigidity_n_m: 1.0}\n"
      "    edges: {s1_min: " + edge + ", s1_max: " + edge + ", s2_min: " + edge + ", s2_max: " + edge + "}\n";
  Scene scene(load_case(yaml));
  for (int k = 0; k < 1500; ++k)
    scene.advance();
  return -sheet(scene).positions_m()((n / 2) * n + n / 2, 2);
}

// Kirchhoff plate, uniform load q = 1e-3 N/m^2 (w / a ~ 4e-6: linear; membrane stiffening
// sigma a^2 / D ~ 1e-9: negligible). Simply supported (the paper's "fixed"/pinned edges):
// w = 0.00406235 q a^4 / D (Navier series). Clamped: w = 0.00126532 q a^4 / D (Timoshenko &
// Woinowsky-Krieger, Table 35). Tolerance 1 % at n = 41 and observed order > 1.8.
TEST(AnalyticCases, SimplySupportedPlateDeflectionMatchesKirchhoff) {
  const double expected = 0.00406235e-3;
  const double e11 = std::abs(plate_center_deflection(11, "pinned") / expected - 1);
  const double e21 = std::abs(plate_center_deflection(21, "pinned") / expected - 1);
  const double e41 = std::abs(plate_center_deflection(41, "pinned") / expected - 1);
  std::printf("simply supported plate: errors %.4f %.4f %.4f %%, order %.2f\n", 100 * e11, 100 * e21, 100 * e41,
              std::log2(e21 / e41));
  EXPECT_LT(e41, 0.01);
  EXPECT_GT(std::log2(e11 / e21), 1.8);
}

TEST(AnalyticCases, ClampedPlateDeflectionMatchesKirchhoff) {
  const double expected = 0.00126532e-3;
  const double e11 = std::abs(plate_center_deflection(11, "clamped") / expected - 1);
  const double e21 = std::abs(plate_center_deflection(21, "clamped") / expected - 1);
  const double e41 = std::abs(plate_center_deflection(41, "clamped") / expected - 1);
  std::printf("clamped plate: errors %.4f %.4f %.4f %%, order %.2f\n", 100 * e11, 100 * e21, 100 * e41,
              std::log2(e21 / e41));
  EXPECT_LT(e41, 0.01);
  EXPECT_GT(std::log2(e11 / e21), 1.8);
}

} // namespace
} // namespace fsi::structure
