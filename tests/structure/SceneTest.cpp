// Standalone scenes through the case parser: collisions keep a falling rag outside a pole and
// inside channel walls (Eq. 11; also with the correction spread over the grid), two rags in
// contact rest on each other, a clamped edge follows its prescribed pendulum motion, and
// several structures advance together.

#include "CaseFixture.hpp"
#include "common/ConfigError.hpp"
#include "motion/PendulumHistory.hpp"
#include "structure_solver/ModelFactory.hpp"
#include "structure_solver/ModelRegistry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace fsi::structure {
namespace {

const char *rag_over_pole = R"(run: {end_time_s: 1, time_step_s: 5.0e-5, output_interval_s: 0.01}
gravity_m_per_s2: [0, 0, -9.81]
collisions:
  threshold_m: 0.004
  target_distance_m: 0.004
  surfaces:
    - cylinder: {axis_start_m: [0.05, -0.1, 0.0], axis_end_m: [0.05, 0.1, 0.0], radius_m: 0.008}
    - box: {min_m: [-0.2, -0.1, -0.03], max_m: [0.3, 0.1, 0.075]}
structures:
  - name: rag
    model: membrane
    size_m: [0.1, 0.06]
    n_points: [26, 16]
    origin_m: [0.0, -0.03, 0.02]
    material:
      mass_per_area_kg_per_m2: 0.03
      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
)";

// Distance of x to the pole (radius 8 mm, axis along y through (0.05, *, 0)) and to the floor.
double pole_distance(const Eigen::RowVector3d &x) { return std::hypot(x(0) - 0.05, x(2)) - 0.008; }

TEST(ModelRegistry, EveryModelTheConfigurationOffersIsBuiltByTheSolverAndNoOther) {
  // The configuration's names (linked by the case alone) and the solver's builders are two
  // lists: a model added to one only would be refused at run time, or never offered.
  EXPECT_EQ(ModelFactory::builtin().names(), ModelRegistry::builtin().names());
  for (const auto &name : ModelRegistry::builtin().names()) {
    const auto config = ModelRegistry::builtin().make_config(name);
    const auto model = ModelFactory::builtin().build(name, *config, {name, Vec3(0.0, 0.0, -9.81), 1e-4});
    EXPECT_EQ(model->grid_shape(), config->grid_shape()) << name;
  }
}

TEST(Scene, CollisionsKeepAFallingRagOffThePoleAndAboveTheFloor) {
  Scene scene(testing::load_case(rag_over_pole));
  const auto &rag = *scene.structures().front();
  double closest_pole = 1.0, closest_floor = 1.0;
  std::size_t corrections = 0;
  for (int k = 0; k < 4000; ++k) { // 0.2 s: falls 2 cm onto the pole, drapes, reaches the floor
    scene.advance();
    corrections += scene.last_corrections();
    for (int p = 0; p < rag.n_points(); ++p) {
      closest_pole = std::min(closest_pole, pole_distance(rag.positions_m().row(p)));
      closest_floor = std::min(closest_floor, rag.positions_m()(p, 2) + 0.03);
    }
  }
  EXPECT_GT(corrections, 0u) << "the rag never touched anything: the test would prove nothing";
  // Every point is corrected to d_t = 4 mm; tolerance 1e-9 m for round-off.
  EXPECT_GE(closest_pole, 0.004 - 1e-9);
  EXPECT_GE(closest_floor, 0.004 - 1e-9);
  EXPECT_TRUE(rag.positions_m().allFinite());
}

TEST(Scene, SpreadCorrectionsStillKeepEveryPointAtTheTargetDistance) {
  // collisions.spread_points moves the corrected points' neighbours too; those it brings
  // within d_c of a wall are corrected again, so the guarantee of Eq. 11 holds.
  std::string yaml = rag_over_pole;
  yaml.replace(yaml.find("  target_distance_m: 0.004\n"), 26, "  target_distance_m: 0.004\n  spread_points: 3\n");
  Scene scene(testing::load_case(yaml));
  const auto &rag = *scene.structures().front();
  double closest_pole = 1.0, closest_floor = 1.0;
  std::size_t corrections = 0;
  for (int k = 0; k < 4000; ++k) {
    scene.advance();
    corrections += scene.last_corrections();
    for (int p = 0; p < rag.n_points(); ++p) {
      closest_pole = std::min(closest_pole, pole_distance(rag.positions_m().row(p)));
      closest_floor = std::min(closest_floor, rag.positions_m()(p, 2) + 0.03);
    }
  }
  EXPECT_GT(corrections, 0u);
  EXPECT_GE(closest_pole, 0.004 - 1e-9);
  EXPECT_GE(closest_floor, 0.004 - 1e-9);
  EXPECT_TRUE(rag.positions_m().allFinite());
}

TEST(Scene, ASpreadWithoutSurfacesIsRefusedNamingTheKey) {
  const std::string yaml = R"(run: {end_time_s: 1, time_step_s: 5.0e-5, output_interval_s: 0.01}
collisions: {spread_points: 2, self_collision: true}
structures:
  - name: rag
    model: membrane
    size_m: [0.1, 0.06]
    n_points: [26, 16]
)";
  try {
    testing::load_case(yaml);
    ADD_FAILURE() << "a spread with nothing to spread was accepted";
  } catch (const common::ConfigError &error) {
    EXPECT_NE(std::string(error.what()).find("spread_points"), std::string::npos) << error.what();
  }
}

// A small rag dropped onto a larger one lying on a floor, its points over the gaps between the
// lower one's (offset 3 and 7 mm on a 1 cm grid; d_c = 4 mm): the smallest height of an upper
// point over the lower rag's points within 1.1 cm of it, over the last 0.1 s (resting).
double rest_gap_of_two_rags(bool contact) {
  std::string yaml = R"(run: {end_time_s: 1, time_step_s: 5.0e-5, output_interval_s: 0.01}
gravity_m_per_s2: [0, 0, -9.81]
collisions:
  threshold_m: 0.004
  target_distance_m: 0.004
  structure_contact: CONTACT
  surfaces:
    - box: {min_m: [-0.2, -0.2, 0.0], max_m: [0.3, 0.3, 0.1]}
structures:
  - name: under
    model: membrane
    size_m: [0.1, 0.1]
    n_points: [11, 11]
    origin_m: [0.0, 0.0, 0.005]
    material:
      mass_per_area_kg_per_m2: 0.03
      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
  - name: over
    model: membrane
    size_m: [0.06, 0.06]
    n_points: [7, 7]
    origin_m: [0.023, 0.027, 0.02]
    material:
      mass_per_area_kg_per_m2: 0.03
      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
)";
  yaml.replace(yaml.find("CONTACT"), 7, contact ? "true" : "false");
  Scene scene(testing::load_case(yaml));
  const auto &under = scene.structures()[0]->positions_m();
  const auto &over = scene.structures()[1]->positions_m();
  double gap = 1.0;
  for (int k = 0; k < 4000; ++k) { // 0.2 s: the upper rag lands at about 0.055 s
    scene.advance();
    if (k < 2000)
      continue;
    for (Eigen::Index i = 0; i < over.rows(); ++i)
      for (Eigen::Index j = 0; j < under.rows(); ++j)
        if ((over.row(i).head<2>() - under.row(j).head<2>()).norm() < 0.011)
          gap = std::min(gap, over(i, 2) - under(j, 2));
  }
  EXPECT_TRUE(over.allFinite() && under.allFinite());
  return gap;
}

TEST(Scene, RagsInContactRestOnEachOtherInsteadOfPassingThrough) {
  // Without contact the upper rag falls through the lower one to the floor's d_t: both rest at
  // z = 4 mm. With it, it rests on the lower rag, d_t = 4 mm over it (less the round-off of a
  // wall pass after the contact pass: 1 % of d_c allowed).
  const double without = rest_gap_of_two_rags(false), with = rest_gap_of_two_rags(true);
  std::printf("the upper rag over the lower, at rest: %.3f mm without contact, %.3f mm with\n", 1e3 * without,
              1e3 * with);
  EXPECT_LT(without, 0.0005);
  EXPECT_GT(with, 0.004 * 0.99);
}

TEST(Scene, ClampedEdgeFollowsThePendulumExactly) {
  Scene scene(testing::load_case(R"(run: {end_time_s: 1, time_step_s: 5.0e-5, output_interval_s: 0.01}
gravity_m_per_s2: [0, 0, -9.81]
structures:
  - name: flag
    model: membrane
    size_m: [0.05, 0.1]
    n_points: [13, 26]
    origin_m: [0, -0.05, -0.1]
    s1_direction: [0, 0, -1]
    s2_direction: [0, 1, 0]
    edges: {s1_min: clamped}
    clamp_motion:
      pendulum: {axis_point_m: [0, 0, 0], axis_direction: [0, 1, 0], length_m: 0.15, initial_angle_deg: 30}
)"));
  const motion::PendulumHistory pendulum(9.81, 0.15, M_PI / 6.0);
  const auto &flag = *scene.structures().front();
  for (int k = 0; k < 3000; ++k)
    scene.advance();
  const double theta = pendulum.angle_rad(scene.time_s());
  for (int i2 = 0; i2 < 26; ++i2) { // edge s1 = 0: points (0, i2), hanging 0.1 m below the axis
    const Eigen::RowVector3d x = flag.positions_m().row(i2);
    EXPECT_NEAR(x(0), -0.1 * std::sin(theta), 1e-12); // rotation about +y takes -z toward -x
    EXPECT_NEAR(x(2), -0.1 * std::cos(theta), 1e-12);
  }
  // The rest of the flag swings with the bar (no air): its far edge trails the clamp by a
  // bending deflection much smaller than the flag (5 cm).
  const Eigen::RowVector3d far = flag.positions_m().row(12 * 26 + 13);
  EXPECT_NEAR(std::atan2(-far(0), -far(2)), theta, 0.05);
}

TEST(Scene, SeveralStructuresAdvanceTogether) {
  std::string yaml = rag_over_pole;
  yaml += R"(  - name: chain
    model: filament
    length_m: 0.1
    n_points: 11
    origin_m: [0.2, 0, 0.05]
    direction: [1, 0, 0]
    linear_density_kg_per_m: 0.01
    tension_coefficient_n: 1
)";
  Scene scene(testing::load_case(yaml));
  ASSERT_EQ(scene.structures().size(), 2u);
  for (int k = 0; k < 200; ++k)
    scene.advance();
  // The pinned start of the chain stays put, its free end falls under gravity.
  EXPECT_NEAR(scene.structures()[1]->positions_m()(0, 2), 0.05, 1e-15);
  EXPECT_LT(scene.structures()[1]->positions_m()(10, 2), 0.05 - 1e-4);
  EXPECT_NEAR(scene.structures()[0]->time_s(), scene.structures()[1]->time_s(), 1e-15);
}

} // namespace
} // namespace fsi::structure
