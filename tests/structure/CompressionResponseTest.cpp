// material.compression (CompressionResponse.hpp): a slack sheet carries no stretching tension in
// compression and keeps the elastic one in extension, its force stays the exact gradient of its
// energy, and a stiff rag crumpled to 90 % of its length stays stable under the linearized
// tension step where the paper's elastic compression diverges (the hub's nose of the pump,
// cases/rag-in-pump with phi = 100 N/m).

#include "CaseFixture.hpp"
#include "common/ConfigError.hpp"
#include "structure_solver/ElasticTerms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace fsi::structure {
namespace {

constexpr int n = 9;
constexpr double ds = 0.1;

PointArray flat_grid(const LagrangianGrid &grid, double stretch_1, double stretch_2) {
  PointArray x(grid.n_points(), 3);
  for (int i1 = 0; i1 < grid.n1(); ++i1)
    for (int i2 = 0; i2 < grid.n2(); ++i2)
      x.row(grid.index(i1, i2)) << stretch_1 * i1 * grid.ds1(), stretch_2 * i2 * grid.ds2(), 0.0;
  return x;
}

PointArray forces_of(const ElasticTerms &terms, const PointArray &x) {
  PointArray f = PointArray::Zero(x.rows(), 3);
  terms.add_forces(x, Eigen::Matrix3d::Identity(), f);
  return f;
}

TEST(CompressionResponse, ASlackSheetCarriesNoTensionAlongItsCompressedDirection) {
  // Compressed to 0.9 along s1 and stretched to 1.1 along s2 (no shear, no bending): the slack
  // sheet's force and energy are exactly those of the elastic sheet stretched along s2 alone.
  const LagrangianGrid grid(n, n, (n - 1) * ds, (n - 1) * ds);
  const PointArray rest = flat_grid(grid, 1.0, 1.0);
  const ElasticTerms slack(grid, EdgeConditions{}, rest, 100.0, 1e-4, false, CompressionResponse::slack);
  const ElasticTerms elastic(grid, EdgeConditions{}, rest, 100.0, 1e-4, false, CompressionResponse::elastic);
  const PointArray both = flat_grid(grid, 0.9, 1.1), s2_only = flat_grid(grid, 1.0, 1.1);
  const PointArray f_slack = forces_of(slack, both), f_reference = forces_of(elastic, s2_only);
  const double scale = f_reference.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 1.0); // the s2 stretch does load the edges
  EXPECT_LT((f_slack - f_reference).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_NEAR(slack.energy(both, Eigen::Matrix3d::Identity()).tension_j,
              elastic.energy(s2_only, Eigen::Matrix3d::Identity()).tension_j, 1e-14);
  // The elastic sheet pushes back along s1: its forces differ by the compressive tension.
  EXPECT_GT((forces_of(elastic, both) - f_reference).cwiseAbs().maxCoeff(), 0.1 * scale);
  // Purely stretched, slack and elastic are the same sheet.
  EXPECT_EQ((forces_of(slack, s2_only) - f_reference).cwiseAbs().maxCoeff(), 0.0);
}

TEST(CompressionResponse, SlackForceIsTheGradientOfItsEnergy) {
  // A crumpled shape with edges in compression and in extension: -dE/dX by central differences
  // (step 1e-7 m) matches the force to 1e-6 of its largest component.
  const LagrangianGrid grid(n, n, (n - 1) * ds, (n - 1) * ds);
  const PointArray rest = flat_grid(grid, 1.0, 1.0);
  const ElasticTerms slack(grid, EdgeConditions{}, rest, 100.0, 1e-4, false, CompressionResponse::slack);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-0.02, 0.02);
  PointArray x = rest;
  for (int i = 0; i < x.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      x(i, c) += noise(rng);
  int compressed = 0, stretched = 0;
  for (const auto &t : slack.tension())
    ((x.row(t.b) - x.row(t.a)).squaredNorm() * t.inv_ds_squared < t.rest_value ? compressed : stretched)++;
  ASSERT_GT(compressed, 10);
  ASSERT_GT(stretched, 10);
  const PointArray f = forces_of(slack, x);
  const double h = 1e-7;
  double worst = 0.0;
  for (int i = 0; i < x.rows(); ++i)
    for (int c = 0; c < 3; ++c) {
      PointArray plus = x, minus = x;
      plus(i, c) += h, minus(i, c) -= h;
      const double gradient = (slack.energy(plus, Eigen::Matrix3d::Identity()).total() -
                               slack.energy(minus, Eigen::Matrix3d::Identity()).total()) /
                              (2.0 * h);
      worst = std::max(worst, std::abs(f(i, c) + gradient));
    }
  std::printf("max |f + dE/dX| = %.3e N (largest force %.3e N)\n", worst, f.cwiseAbs().maxCoeff());
  EXPECT_LT(worst, 1e-6 * f.cwiseAbs().maxCoeff());
}

std::string stiff_rag_yaml(const std::string &compression, double dt = 2.5e-4) {
  // The pump's long rag at phi = 100 N/m: 15 x 5 cm, 16 x 6 points (ds = 1 cm), rho_1 0.03,
  // dt 2.5e-4 s: dt^2 4 |sigma| / (rho_1 ds^2) = 1.6 at 90 % of the rest length.
  return "run: {end_time_s: 1, time_step_s: " + std::to_string(dt) + ", output_interval_s: 0.01}\n"
         "gravity_m_per_s2: [0, 0, 0]\n"
         "structures:\n  - name: rag\n    model: membrane\n    size_m: [0.15, 0.05]\n    n_points: [16, 6]\n"
         "    material:\n      mass_per_area_kg_per_m2: 0.03\n      compression: " + compression + "\n"
         "      coefficients: {tension_coefficient_n_per_m: 100, bending_rigidity_n_m: 1.0e-8}\n"
         "    solver: {tension: linearized, linear_solver: direct}\n";
}

struct Crumple {
  bool finite = true;
  double max_stretch = 0.0;
  double max_speed_m_per_s = 0.0;
};

/// Starts the rag at rest, crumpled to 90 % of its length along s1 with a 1 mm out-of-plane
/// ripple, and runs 0.1 s with no load.
Crumple crumple(const std::string &compression, double dt = 2.5e-4) {
  Scene scene(testing::load_case(stiff_rag_yaml(compression, dt)));
  LagrangianSheet &rag = testing::sheet(scene);
  PointArray x = rag.positions_m();
  for (int i = 0; i < x.rows(); ++i) {
    x(i, 0) *= 0.9;
    x(i, 2) += 1e-3 * std::sin(40.0 * x(i, 0)) * std::cos(60.0 * x(i, 1));
  }
  rag.restore_state(x, PointArray::Zero(x.rows(), 3), 0.0);
  Crumple out;
  const long steps = std::lround(0.1 / dt);
  for (long k = 0; k < steps && out.finite; ++k) {
    scene.advance();
    out.finite = rag.positions_m().allFinite();
    out.max_stretch = std::max(out.max_stretch, rag.max_stretch_ratio());
    out.max_speed_m_per_s = std::max(out.max_speed_m_per_s, rag.velocities_m_per_s().rowwise().norm().maxCoeff());
    if (out.max_stretch > 3.0)
      break; // blown up
  }
  std::printf("%s, dt %.3g s: finite %d, max stretch %.4f, max speed %.3g m/s\n", compression.c_str(), dt, out.finite,
              out.max_stretch, out.max_speed_m_per_s);
  return out;
}

TEST(CompressionResponse, AStiffRagCrumpledByTheFlowStaysStableWhenSlack) {
  const Crumple slack = crumple("slack");
  ASSERT_TRUE(slack.finite);
  EXPECT_LT(slack.max_stretch, 1.01);        // nothing pulls it apart: it stays crumpled
  EXPECT_LT(slack.max_speed_m_per_s, 0.5);   // shear and bending only: slow relaxation
  // The negative control: the paper's elastic compression springs back, to at most 1.10 of the
  // rest length at dt / 2, dt / 4 and dt / 8 (measured 1.083, 1.088, 1.100); at the pump's step
  // it overshoots to 1.54 at 24 m/s, the start of the divergence seen at the hub's nose.
  const Crumple elastic = crumple("elastic");
  const Crumple resolved = crumple("elastic", 6.25e-5);
  ASSERT_TRUE(resolved.finite);
  EXPECT_LT(resolved.max_stretch, 1.15);
  EXPECT_TRUE(!elastic.finite || elastic.max_stretch > 1.3);
}

TEST(CompressionResponse, TheCaseFileNamesTheAllowedResponses) {
  try {
    testing::load_case(stiff_rag_yaml("slak"));
    FAIL() << "a misspelt compression response was accepted";
  } catch (const common::ConfigError &e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("compression"), std::string::npos) << message;
    EXPECT_NE(message.find("elastic, slack"), std::string::npos) << message;
    EXPECT_NE(message.find("slack"), std::string::npos) << message;
  }
}

} // namespace
} // namespace fsi::structure
