// A torus placed off a tilted rotation axis: at several times the indicator (candidate cells
// only, body-frame tests) equals the brute-force test of every cell against the surface
// moved to that time; the candidate set is a fraction of the mesh; u_rib = omega x (x - p).

#include "TestGrids.hpp"

#include "motion/AxisRotation.hpp"
#include "fluid_adapter/rigid/BodyIndicator.hpp"
#include "geometry/MeshGenerators.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace fsi::fluid::rigid {
namespace {

const Vec3 kAxisPoint_m(0.05, -0.03, 0.0);
const Vec3 kAxisDirection = Vec3(0.2, 0.1, 1.0).normalized();
constexpr double kRate_rad_per_s = 2.0;

std::shared_ptr<motion::AxisRotation> spinning() {
  return std::make_shared<motion::AxisRotation>(
      kAxisPoint_m, kAxisDirection, [](double t) { return 0.1 + kRate_rad_per_s * t; },
      [](double) { return kRate_rad_per_s; });
}

std::unique_ptr<RigidBody> offset_torus() {
  return RigidBody::from_soup(
      "torus", geometry::make_torus(Vec3(0.55, 0.0, 0.1), 0.3, 0.1, 64, 32), spinning());
}

TEST(RotatingBody, IndicatorEqualsBruteForceOfEveryCellAtSeveralTimes) {
  const auto body = offset_torus();
  const PointArray centres = testing::uniform_centres(-1.1, 1.1, 44);
  BodyIndicator indicator(*body, centres);
  const double candidate_fraction =
      static_cast<double>(indicator.candidate_cells().size()) / static_cast<double>(centres.rows());
  std::printf("  %zu candidates of %lld cells (%.1f %%): %s\n", indicator.candidate_cells().size(),
              static_cast<long long>(centres.rows()), 100 * candidate_fraction,
              indicator.swept_region().describe().c_str());
  EXPECT_LT(candidate_fraction, 0.4);
  for (const double time_s : {0.0, 0.37, 1.1, 2.9}) {
    indicator.update(time_s);
    const std::vector<int> expected =
        testing::brute_force_inside(body->soup(), body->motion().pose_at(time_s), centres);
    int n_inside = 0;
    for (Eigen::Index c = 0; c < centres.rows(); ++c) {
      ASSERT_EQ(indicator.chi()(c), expected[static_cast<std::size_t>(c)]) << "cell " << c << " t " << time_s;
      n_inside += expected[static_cast<std::size_t>(c)];
    }
    ASSERT_GT(n_inside, 300); // the torus holds about 474 cells
    EXPECT_EQ(indicator.inside_cells().size(), static_cast<std::size_t>(n_inside));
  }
}

TEST(RotatingBody, BodyVelocityIsOmegaCrossArmToRoundOff) {
  const auto body = offset_torus();
  const PointArray centres = testing::uniform_centres(-1.1, 1.1, 30);
  BodyIndicator indicator(*body, centres);
  indicator.update(0.8);
  const Vec3 omega = kRate_rad_per_s * kAxisDirection;
  EXPECT_LT((indicator.rigid_velocity().angular_velocity_rad_per_s - omega).norm(), 1e-14);
  double worst_m_per_s = 0.0;
  for (const std::int32_t cell : indicator.candidate_cells()) {
    const Vec3 x = centres.row(cell).transpose();
    const Vec3 expected = omega.cross(x - kAxisPoint_m);
    worst_m_per_s = std::max(worst_m_per_s, (indicator.body_velocity_m_per_s().row(cell).transpose() - expected).norm());
  }
  EXPECT_LT(worst_m_per_s, 1e-14);
}

TEST(StaticBody, CandidatesAreTheBoundingBoxAndVelocityIsZero) {
  const auto body = RigidBody::from_soup(
      "ball", geometry::make_icosphere(Vec3(0.3, 0.2, -0.1), 0.25, 3),
      std::make_shared<motion::StaticPose>());
  const PointArray centres = testing::uniform_centres(-1.0, 1.0, 40);
  BodyIndicator indicator(*body, centres);
  indicator.update(0.0);
  indicator.update(5.0); // static: not re-evaluated
  EXPECT_EQ(indicator.swept_region().kind(), SweptRegion::Kind::static_box);
  // bounding box of side 0.5 in a cube of side 2: about 1/64 of the cells.
  EXPECT_LT(indicator.candidate_cells().size(), centres.rows() / 40);
  EXPECT_EQ(indicator.body_velocity_m_per_s().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_FALSE(indicator.inside_cells().empty());
}

} // namespace
} // namespace fsi::fluid::rigid
