// The loads of a body split among the parts of its surface (BodyPartLoads): each penalized
// cell counts for the part of its closest surface triangle, in the body frame.

#include "TestGrids.hpp"

#include "fluid_adapter/rigid/BodyPartLoads.hpp"
#include "geometry/MeshGenerators.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fsi::fluid::rigid {
namespace {

constexpr int kCellsPerSide = 40;
constexpr double kHalf_m = 1.0;
constexpr double kCell_m = 2 * kHalf_m / kCellsPerSide;

/// A sphere of radius 0.6 whose upper half (triangle centroids at z > 0) is the part "cap"
/// and lower half "base", in the body frame.
geometry::RegionSoup two_halves() {
  geometry::RegionSoup regions;
  regions.soup = geometry::make_icosphere(Vec3::Zero(), 0.6, 3);
  regions.region_names = {"base", "cap"};
  for (Eigen::Index t = 0; t < regions.soup.triangles.rows(); ++t) {
    double z = 0;
    for (int k = 0; k < 3; ++k)
      z += regions.soup.vertices_m(regions.soup.triangles(t, k), 2) / 3;
    regions.region_of_triangle.push_back(z > 0 ? 1 : 0);
  }
  return regions;
}

struct HalvedSphere : ::testing::Test {
  PointArray centres = testing::uniform_centres(-kHalf_m, kHalf_m, kCellsPerSide);
  Eigen::VectorXd volumes = Eigen::VectorXd::Constant(centres.rows(), kCell_m * kCell_m * kCell_m);

  /// A source of 1 N/m^3 along x on the fluid in the cells with world z beyond 0.15 (upper
  /// side if `upper`), 0 elsewhere: the cells far from the parts' seam at the equator.
  PointArray source_on_side(bool upper) const {
    PointArray on_fluid = PointArray::Zero(centres.rows(), 3);
    for (Eigen::Index c = 0; c < centres.rows(); ++c)
      if (upper ? centres(c, 2) > 0.15 : centres(c, 2) < -0.15)
        on_fluid(c, 0) = 1.0;
    return on_fluid;
  }
};

TEST_F(HalvedSphere, PartsSumToTheBodyAndTakeTheirOwnCells) {
  const auto body = RigidBody::from_region_soup("ball", two_halves(), std::make_shared<motion::StaticPose>());
  ASSERT_EQ(body->part_names(), (std::vector<std::string>{"base", "cap"}));
  BodyIndicator indicator{*body, centres};
  indicator.update(0.0);
  BodyPartLoads split(*body);
  const Vec3 point_m(0.1, -0.2, 0.3);
  PointArray everywhere = PointArray::Zero(centres.rows(), 3);
  for (Eigen::Index c = 0; c < centres.rows(); ++c) // a swirl: every cell a different load
    everywhere.row(c) << -centres(c, 1), centres(c, 0), 0.5 * centres(c, 2);
  const auto parts = split.from_source_on_fluid(indicator, centres, everywhere, volumes, point_m, 0.0);
  const BodyLoad total = BodyLoads::from_source_on_fluid(indicator, centres, everywhere, volumes, point_m);
  ASSERT_EQ(parts.size(), 2u);
  // (the total force is zero by symmetry: each half's is not)
  const double scale_n = parts[0].force_n.norm() + parts[1].force_n.norm();
  EXPECT_GT(scale_n, 1e-3);
  EXPECT_LT((parts[0].force_n + parts[1].force_n - total.force_n).norm(), 1e-12 * scale_n);
  EXPECT_LT((parts[0].torque_n_m + parts[1].torque_n_m - total.torque_n_m).norm(), 1e-12 * total.torque_n_m.norm());
  EXPECT_GT(std::abs(parts[0].torque_n_m.z()), 0.3 * std::abs(total.torque_n_m.z())); // both halves take a share
  EXPECT_GT(std::abs(parts[1].torque_n_m.z()), 0.3 * std::abs(total.torque_n_m.z()));

  const auto upper = split.from_source_on_fluid(indicator, centres, source_on_side(true), volumes, point_m, 0.0);
  EXPECT_LT(upper[1].force_n.x(), 0.0); // the reaction of a source along +x on the fluid
  EXPECT_EQ(upper[0].force_n.norm(), 0.0);
}

TEST_F(HalvedSphere, ACoupleOnTheFluidTurnsItsPartTheOtherWay) {
  const auto body = RigidBody::from_region_soup("ball", two_halves(), std::make_shared<motion::StaticPose>());
  BodyIndicator indicator{*body, centres};
  indicator.update(0.0);
  BodyPartLoads split(*body);
  const PointArray no_force = PointArray::Zero(centres.rows(), 3);
  PointArray couple = PointArray::Zero(centres.rows(), 3);
  double upper_volume_m3 = 0;
  for (const std::int32_t cell : indicator.inside_cells())
    if (centres(cell, 2) > 0.15) {
      couple(cell, 2) = 2.0; // N m / m^3 on the fluid, about z
      upper_volume_m3 += volumes(cell);
    }
  const auto parts = split.from_source_on_fluid(indicator, centres, no_force, volumes, Vec3::Zero(), 0.0, couple);
  EXPECT_NEAR(parts[1].torque_n_m.z(), -2.0 * upper_volume_m3, 1e-12);
  EXPECT_EQ(parts[0].torque_n_m.norm(), 0.0);
  EXPECT_EQ(parts[1].force_n.norm(), 0.0);
  EXPECT_THROW(split.from_source_on_fluid(indicator, centres, no_force, volumes, Vec3::Zero(), 0.0,
                                          PointArray::Zero(3, 3)),
               std::invalid_argument);
}

TEST_F(HalvedSphere, CellsGoToThePartsOfTheBodyFrame) {
  // Turned upside down (half a turn about x), the cap is below the equator in the world.
  Eigen::Isometry3d flipped = Eigen::Isometry3d::Identity();
  flipped.rotate(Eigen::AngleAxisd(M_PI, Vec3::UnitX()));
  const auto body = RigidBody::from_region_soup("ball", two_halves(), std::make_shared<motion::StaticPose>(flipped));
  BodyIndicator indicator{*body, centres};
  indicator.update(0.0);
  BodyPartLoads split(*body);
  const auto lower = split.from_source_on_fluid(indicator, centres, source_on_side(false), volumes, Vec3::Zero(), 0.0);
  EXPECT_LT(lower[1].force_n.x(), 0.0);
  EXPECT_EQ(lower[0].force_n.norm(), 0.0);
}

TEST(BodyParts, AnStlsSolidBlocksAreTheParts) {
  const auto body = RigidBody::from_region_soup("ball", two_halves(), std::make_shared<motion::StaticPose>());
  geometry::RegionSoup wrong = two_halves();
  wrong.region_of_triangle.back() = 2; // no third name
  EXPECT_THROW(RigidBody::from_region_soup("ball", wrong, std::make_shared<motion::StaticPose>()),
               std::invalid_argument);
  const auto plain = RigidBody::from_soup("ball", two_halves().soup, std::make_shared<motion::StaticPose>());
  EXPECT_EQ(plain->part_names(), std::vector<std::string>{""});
  EXPECT_EQ(plain->part_of_triangle().size(), static_cast<std::size_t>(plain->soup().triangles.rows()));
}

} // namespace
} // namespace fsi::fluid::rigid
