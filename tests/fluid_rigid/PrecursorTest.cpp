// fsi::fluid::Precursor (OpenFOAM-free): the precursor's time steps (its own dt, a ramp down to
// the coupled run's dt, 100 steps at that dt) and the fingerprint that decides whether an
// earlier precursor can be reused. The run itself: fluid_penalization.Precursor.

#include "case/CaseConfig.hpp"
#include "case/ModuleSetups.hpp"
#include "fluid_adapter/Precursor.hpp"
#include "tests/support/TempPath.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <numeric>
#include <tuple>

namespace fsi::fluid {
namespace {

std::string case_yaml(double precursor_time_s, double rag_mass) {
  return "run: {end_time_s: 0.6, time_step_s: 1.0e-4, output_interval_s: 0.01}\n"
         "gravity_m_per_s2: [0, 0, -9.81]\n"
         "structures:\n  - name: rag\n    model: membrane\n    size_m: [0.1, 0.05]\n    n_points: [11, 6]\n"
         "    material: {mass_per_area_kg_per_m2: " + std::to_string(rag_mass) + "}\n"
         "fluid:\n  openfoam: {case_directory: openfoam, precursor_time_s: " + std::to_string(precursor_time_s) +
         ", precursor_time_step_s: 2.0e-3}\n"
         "coupling: {law: penalty, stiffness_n_per_m_per_measure: 2.5e5}\n";
}

/// A closed tetrahedron, its apex at height `apex_m`.
std::string tetrahedron_stl(double apex_m) {
  const std::string a = "0 0 0", b = "0.1 0 0", c = "0 0.1 0", d = "0 0 " + std::to_string(apex_m);
  std::string stl = "solid body\n";
  for (const auto &[p, q, r] : {std::tuple{a, c, b}, std::tuple{a, b, d}, std::tuple{b, c, d}, std::tuple{c, a, d}})
    stl += "facet normal 0 0 0\nouter loop\nvertex " + p + "\nvertex " + q + "\nvertex " + r + "\nendloop\nendfacet\n";
  return stl + "endsolid body\n";
}

Precursor precursor_of(const std::string &yaml, double apex_m = 0.1) {
  const auto dir = fsi::test_support::temp_path("fsi-precursor-test-");
  std::filesystem::create_directories(dir / "geometry");
  std::ofstream(dir / "geometry" / "body.stl") << tetrahedron_stl(apex_m);
  std::ofstream(dir / "case.yaml") << yaml;
  return Precursor(case_config::precursor_inputs(case_config::CaseConfig::load(dir)), dir, dir / "output");
}

TEST(Precursor, StepsRampDownToTheCoupledTimeStepAndEndExactly) {
  const auto steps = precursor_of(case_yaml(1.2, 0.08)).step_sizes();
  const double total = std::accumulate(steps.begin(), steps.end(), 0.0);
  EXPECT_NEAR(total, 1.2, 1e-12);
  EXPECT_LE(steps.front(), 2e-3);
  EXPECT_GT(steps.front(), 0.99 * 2e-3);
  ASSERT_GT(steps.size(), static_cast<std::size_t>(Precursor::handover_steps));
  for (std::size_t i = steps.size() - Precursor::handover_steps; i < steps.size(); ++i)
    EXPECT_DOUBLE_EQ(steps[i], 1e-4);
  for (std::size_t i = 1; i < steps.size(); ++i) // no jump: each step at most 1.25 times the next
    EXPECT_LE(steps[i - 1], 1.25 * steps[i] * (1 + 1e-12)) << "step " << i;
}

TEST(Precursor, FingerprintFollowsTheFlowNotTheStructure) {
  const auto reference = precursor_of(case_yaml(1.2, 0.08));
  EXPECT_TRUE(reference.wanted());
  EXPECT_EQ(reference.fingerprint(), precursor_of(case_yaml(1.2, 0.03)).fingerprint()); // another rag
  EXPECT_NE(reference.fingerprint(), precursor_of(case_yaml(1.0, 0.08)).fingerprint()); // another precursor
  EXPECT_EQ(reference.fingerprint().size(), 16u);
}

// A copy of the case in another folder (a pump-curve point, a rag-ensemble member: each case
// folder above is a new temporary one) keeps the precursor of its rigid bodies; another body does not.
TEST(Precursor, FingerprintFollowsTheBodysFileContentsNotItsFolder) {
  const std::string with_body =
      case_yaml(1.2, 0.08) + "collisions:\n  surfaces:\n    - mesh: {file: geometry/body.stl}\n";
  const auto reference = precursor_of(with_body);
  EXPECT_EQ(reference.fingerprint(), precursor_of(with_body).fingerprint());
  EXPECT_NE(reference.fingerprint(), precursor_of(with_body, 0.2).fingerprint());
  // The structure's collision settings do not touch the flow.
  const std::string other_settings = case_yaml(1.2, 0.08) +
                                     "collisions:\n  threshold_m: 0.002\n  self_collision: true\n  surfaces:\n"
                                     "    - mesh: {file: geometry/body.stl}\n";
  EXPECT_EQ(reference.fingerprint(), precursor_of(other_settings).fingerprint());
}

} // namespace
} // namespace fsi::fluid
