// Prescribed rigid motions: the free pendulum against the exact large-amplitude period
// T = 4 sqrt(L/g) K(sin(theta0/2)) (complete elliptic integral of the first kind), the
// axis rotation's pose and velocity against closed forms, and the angle-table reader.

#include "motion/AxisRotation.hpp"
#include "motion/CoupledMotion.hpp"
#include "common/ConfigError.hpp"
#include "motion/MotionFactory.hpp"
#include "motion/PendulumHistory.hpp"
#include "tests/support/TempPath.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>


namespace fsi::motion {
namespace {

TEST(Pendulum, LargeAmplitudePeriodMatchesTheEllipticIntegral) {
  const double g = 9.81, length = 0.15, theta0 = 30.0 * M_PI / 180.0;
  const PendulumHistory pendulum(g, length, theta0);
  // The angle returns to theta0 (a maximum) after one period: find it by bisection on the rate.
  const double exact = 4.0 * std::sqrt(length / g) * std::comp_ellint_1(std::sin(theta0 / 2.0));
  double lo = 0.9 * exact, hi = 1.1 * exact; // the rate is > 0 just before the period, < 0 after
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (pendulum.rate_rad_per_s(mid) > 0.0 ? lo : hi) = mid;
  }
  EXPECT_NEAR(0.5 * (lo + hi), exact, 1e-6 * exact); // RK4 with 4000 steps per period
  EXPECT_NEAR(pendulum.angle_rad(exact), theta0, 1e-8);
  EXPECT_NEAR(pendulum.angle_rad(exact / 2.0), -theta0, 1e-8);
}

TEST(AxisRotation, PoseAndVelocityMatchTheClosedForm) {
  const Vec3 point(1.0, 2.0, 0.0), axis(0.0, 0.0, 2.0);
  const double rate = 3.0;
  AxisRotation rotation(point, axis, [=](double t) { return rate * t; }, [=](double) { return rate; });
  const double t = 0.25;
  const Vec3 body(2.0, 2.0, 5.0); // 1 m from the axis along x, at height 5
  const Vec3 world = rotation.pose_at(t) * body;
  EXPECT_NEAR((world - Vec3(1.0 + std::cos(rate * t), 2.0 + std::sin(rate * t), 5.0)).norm(), 0.0, 1e-14);
  const Vec3 velocity = rotation.velocity_at(world, t);
  EXPECT_NEAR((velocity - rate * Vec3(-std::sin(rate * t), std::cos(rate * t), 0.0)).norm(), 0.0, 1e-13);
  // The generic finite-difference velocity of the base class agrees.
  EXPECT_NEAR((rotation.RigidMotion::velocity_at(world, t) - velocity).norm(), 0.0, 1e-6);
}

std::filesystem::path write_table(const std::string &text) {
  // Unique per process and call: ctest runs the tests of this file in parallel processes
  // (an unseeded std::rand() gave them all the same name, and they overwrote each other).
  const auto path = fsi::test_support::temp_path("fsi-motion-", ".csv");
  std::ofstream(path) << text;
  return path;
}

TEST(AngleTable, InterpolatesLinearlyAndHoldsOutside) {
  MotionConfig config;
  config.table.emplace();
  config.table->file = write_table("time_s,angle_rad\n0,0\n1,0.5\n2,0.5\n");
  config.table->axis_direction = Vec3::UnitZ();
  const auto motion = make_motion(config, 9.81);
  const Vec3 x = motion->pose_at(0.5) * Vec3::UnitX();
  EXPECT_NEAR(std::atan2(x.y(), x.x()), 0.25, 1e-14);
  const Vec3 after = motion->pose_at(5.0) * Vec3::UnitX();
  EXPECT_NEAR(std::atan2(after.y(), after.x()), 0.5, 1e-14);
}

TEST(AngleTable, MalformedFilesNameTheFileAndLine) {
  const auto header = write_table("t,angle\n0,0\n");
  EXPECT_THROW(read_angle_table(header), common::ConfigError);
  const auto bad_row = write_table("time_s,angle_rad\n0,0\n1;2\n");
  try {
    read_angle_table(bad_row);
    FAIL() << "expected a common::ConfigError";
  } catch (const common::ConfigError &e) {
    EXPECT_NE(std::string(e.what()).find(bad_row.string() + ":3"), std::string::npos) << e.what();
  }
  const auto not_increasing = write_table("time_s,angle_rad\n0,0\n0,1\n");
  EXPECT_THROW(read_angle_table(not_increasing), common::ConfigError);
}

TEST(CoupledMotion, ReproducesTheRigidVelocityFieldOfTheMotionItWasSentFrom) {
  // The coupler sends the pose and (v_o, omega) of an axis rotation; the participant's
  // CoupledMotion gives back the same pose and the same velocity at any point.
  AxisRotation rotation(Vec3(0.1, -0.2, 0.0), Vec3(0.0, 0.3, 1.0), [](double t) { return 150.8 * t; },
                        [](double) { return 150.8; });
  const double t = 0.0123;
  const Eigen::Isometry3d pose = rotation.pose_at(t);
  const Vec3 o = pose.translation();
  const Vec3 v_o = rotation.velocity_at(o, t);
  Vec3 omega = Vec3::Zero();
  for (int k = 0; k < 3; ++k)
    omega += 0.5 * pose.linear().col(k).cross(rotation.velocity_at(o + pose.linear().col(k), t) - v_o);
  CoupledMotion coupled("impeller");
  coupled.set(t, pose, v_o, omega);
  EXPECT_TRUE(coupled.pose_at(t).isApprox(pose, 1e-15));
  for (const Vec3 &x : {Vec3(0.3, 0.1, -0.2), Vec3(-1.0, 2.0, 0.5), Vec3(0.0, 0.0, 0.0)})
    EXPECT_LT((coupled.velocity_at(x, t) - rotation.velocity_at(x, t)).norm(), 1e-12 * 150.8) << x.transpose();
}

TEST(CoupledMotion, RefusesATimeTheCouplerDidNotSendNamingBoth) {
  CoupledMotion coupled("surface0");
  EXPECT_THROW(coupled.pose_at(0.0), std::logic_error); // nothing sent yet
  coupled.set(0.5, Eigen::Isometry3d::Identity(), Vec3::Zero(), Vec3::Zero());
  EXPECT_NO_THROW(coupled.pose_at(0.5 * (1.0 + 1e-14))); // the same step, computed another way
  try {
    coupled.velocity_at(Vec3::Zero(), 0.5001);
    FAIL() << "expected a std::logic_error";
  } catch (const std::logic_error &e) {
    EXPECT_NE(std::string(e.what()).find("'surface0' is used at t = 0.500100 s, but the coupler sent its pose for "
                                         "t = 0.500000 s"),
              std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace fsi::motion
