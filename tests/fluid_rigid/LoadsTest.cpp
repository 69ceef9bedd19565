// Force and torque on a body from the penalization source on the fluid: F = -sum f V,
// T = -sum (x - p) x f V over the body's cells.

#include "TestGrids.hpp"

#include "fluid_adapter/rigid/BodyLoads.hpp"
#include "geometry/MeshGenerators.hpp"

#include <gtest/gtest.h>

namespace fsi::fluid::rigid {
namespace {

constexpr int kCellsPerSide = 40;
constexpr double kHalf_m = 1.0;
constexpr double kCellVolume_m3 = (2 * kHalf_m / kCellsPerSide) * (2 * kHalf_m / kCellsPerSide) *
                                  (2 * kHalf_m / kCellsPerSide);

/// A sphere centred on the grid's centre: the set of inside cells is mirror-symmetric.
struct SymmetricSphere : ::testing::Test {
  std::unique_ptr<RigidBody> body = RigidBody::from_soup(
      "ball", geometry::make_icosphere(Vec3::Zero(), 0.6, 3), std::make_shared<motion::StaticPose>());
  PointArray centres = testing::uniform_centres(-kHalf_m, kHalf_m, kCellsPerSide);
  Eigen::VectorXd volumes = Eigen::VectorXd::Constant(centres.rows(), kCellVolume_m3);
  BodyIndicator indicator{*body, centres};
  void SetUp() override { indicator.update(0.0); }
  double inside_volume_m3() const { return static_cast<double>(indicator.inside_cells().size()) * kCellVolume_m3; }
};

TEST_F(SymmetricSphere, UniformSourceGivesDensityTimesInsideVolume) {
  const Vec3 source(1.5, -2.0, 0.5); // N/m^3 on the fluid, everywhere (outside cells must not count)
  const PointArray on_fluid = source.transpose().replicate(centres.rows(), 1);
  const BodyLoad load = BodyLoads::from_source_on_fluid(indicator, centres, on_fluid, volumes, Vec3::Zero());
  EXPECT_LT((load.force_n + inside_volume_m3() * source).norm(), 1e-12 * source.norm());
  EXPECT_LT(load.torque_n_m.norm(), 1e-12 * load.force_n.norm()); // symmetric about the point
  const Vec3 point_m(0.2, -0.4, 0.7);
  const BodyLoad offset = BodyLoads::from_source_on_fluid(indicator, centres, on_fluid, volumes, point_m);
  const Vec3 arm_m = Vec3::Zero() - point_m; // from the point to the centroid
  EXPECT_LT((offset.torque_n_m - arm_m.cross(offset.force_n)).norm(), 1e-12 * offset.force_n.norm());
}

TEST_F(SymmetricSphere, FluidFasterThanBodyPushesItForward) {
  // Eq. 9 on the fluid: f = -chi rho lambda (u - u_rib) with u = U inside a resting body.
  const double rho_lambda = 1e3 * 1e6;
  const Vec3 u_m_per_s(0.3, 0.0, 0.0);
  PointArray on_fluid = PointArray::Zero(centres.rows(), 3);
  for (const std::int32_t cell : indicator.inside_cells())
    on_fluid.row(cell) = -rho_lambda * indicator.chi()(cell) * u_m_per_s.transpose();
  const BodyLoad load = BodyLoads::from_source_on_fluid(indicator, centres, on_fluid, volumes, Vec3::Zero());
  EXPECT_GT(load.force_n.x(), 0.0);
  EXPECT_NEAR(load.force_n.x(), rho_lambda * 0.3 * inside_volume_m3(), 1e-9 * load.force_n.x());
}

TEST_F(SymmetricSphere, SizeMismatchIsRejected) {
  const PointArray on_fluid = PointArray::Zero(centres.rows() - 1, 3);
  EXPECT_THROW(BodyLoads::from_source_on_fluid(indicator, centres, on_fluid, volumes, Vec3::Zero()),
               std::invalid_argument);
}

} // namespace
} // namespace fsi::fluid::rigid
