// CollisionSet (Eq. 11): parameters are validated, the correction matches the closed form on
// a plane, and after correct() no point of a random cloud (deep-inside points included) is
// inside or closer than the threshold to a static or a rotating mesh, checked with the
// brute-force oracle in the body frame.

#include "BruteForceMesh.hpp"
#include "TestGeometry.hpp"

#include "geometry/BoxSurface.hpp"
#include "structure_solver/collision/CollisionSet.hpp"
#include "geometry/CylinderSurface.hpp"
#include "geometry/MeshGenerators.hpp"
#include "geometry/PlaneSurface.hpp"
#include "geometry/TriangleMeshSurface.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <omp.h>

namespace fsi::structure::collision {
namespace {

using namespace fsi::geometry;

using FluidSide = TriangleMeshSurface::FluidSide;
using testing::BruteForceMesh;

/// Rotation at a constant rate about an axis through a point (test-local RigidMotion).
class ConstantRotation final : public motion::RigidMotion {
public:
  ConstantRotation(const Vec3 &centre_m, const Vec3 &axis, double rate_rad_per_s)
      : centre_m_(centre_m), axis_(axis.normalized()), rate_rad_per_s_(rate_rad_per_s) {}
  Eigen::Isometry3d pose_at(double time_s) const override {
    return Eigen::Translation3d(centre_m_) * Eigen::AngleAxisd(rate_rad_per_s_ * time_s, axis_) *
           Eigen::Translation3d(-centre_m_);
  }

private:
  Vec3 centre_m_;
  Vec3 axis_;
  double rate_rad_per_s_;
};

std::shared_ptr<const motion::RigidMotion> at_rest() {
  return std::make_shared<motion::StaticPose>();
}

TEST(CollisionSet, RejectsInvalidParametersWithTheirNames) {
  try {
    CollisionSet bad(0.0, 1.0);
    FAIL() << "no error raised";
  } catch (const std::invalid_argument &error) {
    EXPECT_NE(std::string(error.what()).find("threshold_m"), std::string::npos);
  }
  try {
    CollisionSet bad(0.02, 0.01);
    FAIL() << "no error raised";
  } catch (const std::invalid_argument &error) {
    EXPECT_NE(std::string(error.what()).find("target_distance_m"), std::string::npos);
  }
  EXPECT_THROW(CollisionSet(0.01, 0.02, 0), std::invalid_argument);
}

TEST(CollisionSet, WithoutSurfacesLeavesPointsAlone) {
  const CollisionSet empty(0.01, 0.02);
  PointArray points = testing::to_point_array(
      testing::random_points_around(testing::test_icosphere(), 100, 0.1, 1));
  const PointArray before = points;
  const CorrectionStats stats = empty.correct(points, 0.0);
  EXPECT_EQ(stats.n_points_corrected, 0u);
  EXPECT_EQ(points, before);
}

TEST(CollisionSet, PlaneCorrectionFollowsEquation11) {
  CollisionSet set(0.01, 0.015);
  set.add_surface(std::make_unique<PlaneSurface>(Vec3(0, 0, 0), Vec3(0, 0, 1)), at_rest());
  PointArray points(4, 3);
  points << 0.1, 0.2, 0.005, // within d_c: to d_t
      0.3, 0.4, -0.2,        // deep below the wall: to d_t
      0.5, 0.6, 0.012,       // between d_c and d_t: Eq. 11 leaves it
      0.7, 0.8, 1.0;         // far
  const CorrectionStats stats = set.correct(points, 0.0);
  EXPECT_EQ(stats.n_points_corrected, 2u);
  EXPECT_NEAR(stats.min_signed_distance_m, -0.2, 1e-15);
  EXPECT_NEAR(stats.deepest_penetration_m(), 0.2, 1e-15);
  PointArray expected(4, 3);
  expected << 0.1, 0.2, 0.015, 0.3, 0.4, 0.015, 0.5, 0.6, 0.012, 0.7, 0.8, 1.0;
  EXPECT_LT((points - expected).cwiseAbs().maxCoeff(), 1e-15);
}

/// Distance from p to the nearest wall of the unit box [0, 1]^3 after correcting p.
double nearest_wall_after_correction(const Vec3 &p, double threshold_m, double target_m) {
  CollisionSet set(threshold_m, target_m);
  set.add_surface(std::make_unique<BoxSurface>(Vec3(0, 0, 0), Vec3(1, 1, 1)), at_rest());
  PointArray points = p.transpose();
  set.correct(points, 0.0);
  const Vec3 q = points.row(0).transpose();
  return std::min(q.minCoeff(), (Vec3::Ones() - q).minCoeff());
}

TEST(CollisionSet, PointOutsideABoxCornerEndsInsideBeyondThresholdFromEveryWall) {
  // Pushed along the corner diagonal to d_t, it sits d_t / sqrt(3) from each wall: beyond d_c
  // when d_t = 2 d_c (done in one pass), below it when d_t = d_c (later passes finish).
  EXPECT_NEAR(nearest_wall_after_correction(Vec3(1.1, 1.1, 1.1), 0.01, 0.02), 0.02 / std::sqrt(3.0),
              1e-12);
  EXPECT_GE(nearest_wall_after_correction(Vec3(1.1, 1.1, 1.1), 0.02, 0.02), 0.02 - 1e-12);
  EXPECT_GE(nearest_wall_after_correction(Vec3(0.001, 0.003, 0.002), 0.02, 0.02), 0.02 - 1e-12);
}

TEST(CollisionSet, PointsBetweenFloorAndPoleClearBoth) {
  const double threshold_m = 0.01;
  CollisionSet set(threshold_m, threshold_m);
  set.add_surface(std::make_unique<PlaneSurface>(Vec3(0, 0, 0), Vec3(0, 0, 1)), at_rest());
  set.add_surface(std::make_unique<CylinderSurface>(Vec3(0, 0, -1), Vec3(0, 0, 1), 0.1), at_rest());
  const PlaneSurface floor(Vec3(0, 0, 0), Vec3(0, 0, 1));
  const CylinderSurface pole(Vec3(0, 0, -1), Vec3(0, 0, 1), 0.1);
  PointArray points = testing::to_point_array(
      testing::random_points_around(testing::test_icosphere(), 3000, 0.0, 2));
  points.col(2) *= 0.05; // flatten the cloud onto the floor
  points.leftCols(2) *= 0.3;
  set.correct(points, 0.0);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Vec3 p = points.row(i).transpose();
    ASSERT_GE(floor.distance(p).signed_distance_m, threshold_m - 1e-9) << p.transpose();
    ASSERT_GE(pole.distance(p).signed_distance_m, threshold_m - 1e-9) << p.transpose();
  }
}

/// z of a point between a floor at z = 0 and a ceiling at z = gap after correction (d_c = d_t
/// = 4 mm), with the number of pinched corrections.
std::pair<double, std::size_t> corrected_in_gap(double gap_m, double z_m) {
  CollisionSet set(0.004, 0.004);
  set.add_surface(std::make_unique<PlaneSurface>(Vec3(0, 0, 0), Vec3(0, 0, 1)), at_rest());
  set.add_surface(std::make_unique<PlaneSurface>(Vec3(0, 0, gap_m), Vec3(0, 0, -1)), at_rest());
  PointArray points(1, 3);
  points << 0.1, 0.2, z_m;
  const CorrectionStats stats = set.correct(points, 0.0);
  EXPECT_EQ(points(0, 0), 0.1); // along the normal only
  return {points(0, 2), stats.n_pinched};
}

TEST(CollisionSet, APointPinchedInAGapNarrowerThanTwiceTheTargetStaysMidway) {
  // A 5 mm gap (the pump's blade-to-shroud-lip slot is 3.7 mm): d_t = 4 mm from one wall is
  // 1 mm from the other. Without the pinch rule the point was thrown from wall to wall and,
  // after an even number of passes, left inside a solid (measured: 0.23 mm deep in the pump).
  for (const double z : {0.001, -0.0003, 0.0042, 0.0052}) {
    const auto [z_after, pinched] = corrected_in_gap(0.005, z);
    EXPECT_NEAR(z_after, 0.0025, 1e-12) << "from z = " << z;
    EXPECT_GE(pinched, 1u);
  }
  // A gap wider than 2 d_t: Eq. 11 as it is, d_t from the near wall, nothing pinched.
  const auto [z_wide, pinched_wide] = corrected_in_gap(0.010, 0.001);
  EXPECT_NEAR(z_wide, 0.004, 1e-15);
  EXPECT_EQ(pinched_wide, 0u);
}

/// A collision set holding one mesh surface that follows `motion`.
CollisionSet mesh_collision_set(const TriangleSoup &soup, FluidSide side,
                                const std::shared_ptr<const motion::RigidMotion> &motion,
                                double threshold_m, double target_m) {
  CollisionSet set(threshold_m, target_m);
  set.add_surface(TriangleMeshSurface::from_triangles(soup.vertices_m, soup.triangles, side),
                  motion);
  return set;
}

/// Corrects a random cloud (many points deep inside) placed around the mesh at time_s and
/// checks every point with the oracle in the body frame: moved points end at d_t or more,
/// the others at d_c or more, none inside the solid.
void expect_cloud_cleared(const CollisionSet &set, const TriangleSoup &soup, FluidSide side,
                          const motion::RigidMotion &motion, double time_s) {
  const Eigen::Isometry3d pose = motion.pose_at(time_s);
  PointArray points = testing::to_point_array(testing::random_points_around(soup, 3000, 0.1, 21));
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    points.row(i) = (pose * Vec3(points.row(i).transpose())).transpose();
  }
  const PointArray before = points;
  const CorrectionStats stats = set.correct(points, time_s);
  EXPECT_GT(stats.n_points_corrected, 100u);
  const BruteForceMesh oracle(soup);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Vec3 body_m = pose.inverse() * Vec3(points.row(i).transpose());
    const double eps_m = oracle.signed_distance(body_m, side == FluidSide::outside);
    const bool moved = points.row(i) != before.row(i);
    const double floor_m = moved ? set.target_distance_m() : set.threshold_m();
    ASSERT_GE(eps_m, floor_m - 1e-9) << "point " << i << " at t = " << time_s;
  }
}

TEST(CollisionSet, ASlotInOneMeshHoldsAPinchedPointMidway) {
  // Two boxes 3.7 mm apart in one closed mesh (one surface): the slot between a blade and a
  // shroud lip. A point 0.23 mm inside one box ends in the slot, 1.85 mm from both faces.
  TriangleSoup soup = make_box(Vec3(-0.02, -0.02, -0.02), Vec3(0.02, 0.02, 0.0));
  const TriangleSoup upper = make_box(Vec3(-0.02, -0.02, 0.0037), Vec3(0.02, 0.02, 0.02));
  const auto n_vertices = soup.vertices_m.rows();
  soup.vertices_m.conservativeResize(n_vertices + upper.vertices_m.rows(), 3);
  soup.vertices_m.bottomRows(upper.vertices_m.rows()) = upper.vertices_m;
  const auto n_triangles = soup.triangles.rows();
  soup.triangles.conservativeResize(n_triangles + upper.triangles.rows(), 3);
  soup.triangles.bottomRows(upper.triangles.rows()) = upper.triangles.array() + static_cast<int>(n_vertices);
  const CollisionSet set = mesh_collision_set(soup, FluidSide::outside, at_rest(), 0.004, 0.004);
  PointArray points(1, 3);
  points << 0.001, 0.002, -0.00023;
  const CorrectionStats stats = set.correct(points, 0.0);
  EXPECT_NEAR(points(0, 2), 0.00185, 1e-9);
  EXPECT_GE(stats.n_pinched, 1u);
}

TEST(CollisionSet, StaticSphereCloudEndsOutsideAtTargetDistance) {
  const TriangleSoup soup = testing::test_icosphere();
  const auto motion = at_rest();
  const CollisionSet set = mesh_collision_set(soup, FluidSide::outside, motion, 0.02, 0.03);
  expect_cloud_cleared(set, soup, FluidSide::outside, *motion, 0.0);
}

TEST(CollisionSet, StaticTorusCloudEndsOutsideAtThreshold) {
  const TriangleSoup soup = testing::test_torus();
  const auto motion = at_rest();
  const CollisionSet set = mesh_collision_set(soup, FluidSide::outside, motion, 0.02, 0.02);
  expect_cloud_cleared(set, soup, FluidSide::outside, *motion, 0.0);
}

TEST(CollisionSet, CasingCloudEndsInsideTheCasing) {
  const TriangleSoup soup = testing::test_icosphere();
  const auto motion = at_rest();
  const CollisionSet set = mesh_collision_set(soup, FluidSide::inside, motion, 0.02, 0.02);
  expect_cloud_cleared(set, soup, FluidSide::inside, *motion, 0.0);
}

TEST(CollisionSet, RotatingTorusCloudIsClearedAtSeveralTimes) {
  const TriangleSoup soup = testing::test_torus();
  const auto spin = std::make_shared<ConstantRotation>(Vec3(0.2, 0.0, 0.1), Vec3(1, 0.3, 0.2), 2.5);
  const CollisionSet set = mesh_collision_set(soup, FluidSide::outside, spin, 0.015, 0.015);
  for (double time_s : {0.0, 0.37, 1.1, 2.9}) {
    expect_cloud_cleared(set, soup, FluidSide::outside, *spin, time_s);
  }
}

TEST(CollisionSet, ThreadsSplitThePointsWithoutChangingTheResult) {
  // A pass of 3000 points runs on several threads; every point's correction and the reduced
  // statistics must be bit for bit those of one thread (restarts and comparisons rely on it).
  const TriangleSoup soup = testing::test_torus();
  const auto spin = std::make_shared<ConstantRotation>(Vec3(0.2, 0.0, 0.1), Vec3(1, 0.3, 0.2), 2.5);
  const CollisionSet set = mesh_collision_set(soup, FluidSide::outside, spin, 0.015, 0.015);
  const PointArray cloud =
      testing::to_point_array(testing::random_points_around(soup, 3000, 0.1, 5));
  const int threads_before = omp_get_max_threads();
  std::vector<PointArray> results;
  std::vector<CorrectionStats> stats;
  for (int n_threads : {1, 2, 3}) {
    omp_set_num_threads(n_threads);
    PointArray points = cloud;
    stats.push_back(set.correct(points, 0.37));
    results.push_back(points);
  }
  omp_set_num_threads(threads_before);
  ASSERT_GT(stats[0].n_points_corrected, 100u);
  for (std::size_t r = 1; r < results.size(); ++r) {
    EXPECT_TRUE((results[r].array() == results[0].array()).all()) << "threads " << r + 1;
    EXPECT_EQ(stats[r].n_points_corrected, stats[0].n_points_corrected);
    EXPECT_EQ(stats[r].n_corrections, stats[0].n_corrections);
    EXPECT_EQ(stats[r].n_passes, stats[0].n_passes);
    EXPECT_EQ(stats[r].min_signed_distance_m, stats[0].min_signed_distance_m);
  }
}

TEST(CollisionSet, DescribeListsEverySurface) {
  CollisionSet set(0.01, 0.02);
  set.add_surface(std::make_unique<PlaneSurface>(Vec3(0, 0, 0), Vec3(0, 0, 1)), at_rest());
  set.add_surface(std::make_unique<BoxSurface>(Vec3(-1, -1, -1), Vec3(1, 1, 1)), at_rest());
  EXPECT_EQ(set.n_surfaces(), 2u);
  EXPECT_NE(set.describe().find("plane"), std::string::npos);
  EXPECT_NE(set.describe().find("box"), std::string::npos);
}

} // namespace
} // namespace fsi::structure::collision
