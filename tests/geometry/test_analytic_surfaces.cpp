// Plane, box and cylinder against closed-form signed distances and normals (tol 1e-12), and
// the contract every RigidSurface must keep: may_be_within() never culls a point that needs
// a correction.

#include "geometry/BoxSurface.hpp"
#include "geometry/CylinderSurface.hpp"
#include "geometry/PlaneSurface.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace fsi::geometry {
namespace {

constexpr double kTol = 1e-12;

void expect_distance(const RigidSurface &surface, const Vec3 &point, double expected_m,
                     const Vec3 &expected_normal) {
  const SurfaceDistance d = surface.distance(point);
  EXPECT_NEAR(d.signed_distance_m, expected_m, kTol) << "at " << point.transpose();
  EXPECT_NEAR((d.normal_into_fluid - expected_normal).norm(), 0.0, kTol)
      << "at " << point.transpose() << ": normal " << d.normal_into_fluid.transpose();
}

TEST(PlaneSurface, SignedDistanceAndNormalMatchClosedForm) {
  const PlaneSurface floor(Vec3(0, 0, 1), Vec3(0, 0, 2));
  expect_distance(floor, Vec3(3, -2, 4), 3.0, Vec3::UnitZ());
  expect_distance(floor, Vec3(0.2, 0.1, -0.5), -1.5, Vec3::UnitZ());
  const PlaneSurface slanted(Vec3::Zero(), Vec3(1, 1, 0));
  expect_distance(slanted, Vec3(1, 0, 7), 1.0 / std::sqrt(2.0), Vec3(1, 1, 0).normalized());
  expect_distance(slanted, Vec3(-2, 0, 0), -std::sqrt(2.0), Vec3(1, 1, 0).normalized());
}

TEST(PlaneSurface, RejectsZeroNormal) {
  EXPECT_THROW(PlaneSurface(Vec3::Zero(), Vec3::Zero()), std::invalid_argument);
}

TEST(BoxSurface, InsidePointsMeasureToNearestWall) {
  const BoxSurface channel(Vec3(0, 0, 0), Vec3(2, 1, 3));
  expect_distance(channel, Vec3(0.1, 0.5, 1.5), 0.1, Vec3::UnitX());
  expect_distance(channel, Vec3(1.9, 0.5, 1.5), 0.1, -Vec3::UnitX());
  expect_distance(channel, Vec3(1.0, 0.95, 2.9), 0.05, -Vec3::UnitY());
  expect_distance(channel, Vec3(1.0, 0.5, 0.02), 0.02, Vec3::UnitZ());
}

TEST(BoxSurface, OutsidePointsAreNegativeAndPointBackIn) {
  const BoxSurface channel(Vec3(0, 0, 0), Vec3(2, 1, 3));
  expect_distance(channel, Vec3(-0.3, 0.5, 1.0), -0.3, Vec3::UnitX());         // beyond a face
  expect_distance(channel, Vec3(-0.3, -0.4, 1.0), -0.5, Vec3(0.6, 0.8, 0.0));  // beyond an edge
  expect_distance(channel, Vec3(2.1, 1.2, 3.2), -0.3, Vec3(-1, -2, -2) / 3.0); // beyond a corner
}

TEST(BoxSurface, RejectsInvertedCorners) {
  EXPECT_THROW(BoxSurface(Vec3(0, 0, 0), Vec3(1, 0, 1)), std::invalid_argument);
}

TEST(CylinderSurface, MantleCapsAndRimsMatchClosedForm) {
  const CylinderSurface pole(Vec3(0, 0, 0), Vec3(0, 0, 2), 0.5);
  expect_distance(pole, Vec3(1.0, 0, 1), 0.5, Vec3::UnitX());           // outside the mantle
  expect_distance(pole, Vec3(0.4, 0, 1), -0.1, Vec3::UnitX());          // inside near the mantle
  expect_distance(pole, Vec3(0, 0.1, 1.95), -0.05, Vec3::UnitZ());      // inside near a cap
  expect_distance(pole, Vec3(0.3, 0, 2.7), 0.7, Vec3::UnitZ());         // above the top cap
  expect_distance(pole, Vec3(0, 0.2, -0.25), 0.25, -Vec3::UnitZ());     // below the bottom cap
  expect_distance(pole, Vec3(0.8, 0, 2.4), 0.5, Vec3(0.6, 0, 0.8));     // beyond the top rim
  expect_distance(pole, Vec3(0, -0.8, -0.4), 0.5, Vec3(0, -0.6, -0.8)); // beyond the bottom rim
}

TEST(CylinderSurface, PointOnAxisGetsAUnitRadialNormal) {
  const CylinderSurface pole(Vec3(0, 0, 0), Vec3(0, 0, 2), 0.5);
  const SurfaceDistance d = pole.distance(Vec3(0, 0, 1));
  EXPECT_NEAR(d.signed_distance_m, -0.5, kTol);
  EXPECT_NEAR(d.normal_into_fluid.norm(), 1.0, kTol);
  EXPECT_NEAR(d.normal_into_fluid.z(), 0.0, kTol);
}

TEST(CylinderSurface, TiltedCylinderEqualsRotatedAxisAlignedOne) {
  const Eigen::Isometry3d placement =
      Eigen::Translation3d(0.3, -1.0, 2.0) * Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized());
  const CylinderSurface upright(Vec3(0, 0, 0), Vec3(0, 0, 2), 0.5);
  const CylinderSurface tilted(placement * Vec3(0, 0, 0), placement * Vec3(0, 0, 2), 0.5);
  for (const Vec3 &p :
       {Vec3(1.0, 0, 1), Vec3(0.8, 0, 2.4), Vec3(0, 0.1, 1.95), Vec3(0.1, 0.2, -3)}) {
    const SurfaceDistance reference = upright.distance(p);
    expect_distance(tilted, placement * p, reference.signed_distance_m,
                    placement.linear() * reference.normal_into_fluid);
  }
}

TEST(CylinderSurface, RejectsZeroAxisAndRadius) {
  EXPECT_THROW(CylinderSurface(Vec3::Zero(), Vec3::Zero(), 1.0), std::invalid_argument);
  EXPECT_THROW(CylinderSurface(Vec3::Zero(), Vec3::UnitZ(), 0.0), std::invalid_argument);
}

TEST(RigidSurfaceContract, CullingNeverHidesAPointThatNeedsCorrection) {
  std::vector<std::unique_ptr<RigidSurface>> surfaces;
  surfaces.push_back(std::make_unique<PlaneSurface>(Vec3(0, 0, -0.5), Vec3(0.2, 0.1, 1)));
  surfaces.push_back(std::make_unique<BoxSurface>(Vec3(-1, -1, -1), Vec3(1, 0.8, 0.9)));
  surfaces.push_back(std::make_unique<CylinderSurface>(Vec3(0, 0, -0.5), Vec3(0.2, 0.1, 0.5), 0.3));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  const double radius_m = 0.1;
  for (const auto &surface : surfaces) {
    for (int n = 0; n < 20000; ++n) {
      const Vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
      const SurfaceDistance d = surface->distance(p);
      EXPECT_NEAR(d.normal_into_fluid.norm(), 1.0, kTol);
      if (!surface->may_be_within(p, radius_m)) {
        ASSERT_GE(d.signed_distance_m, radius_m) << surface->describe() << " at " << p.transpose();
      }
    }
  }
}

} // namespace
} // namespace fsi::geometry
