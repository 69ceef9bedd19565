// The blade's camber line against its defining integral and end angles, and the design file's
// refusals of blades and chambers that cannot be built.

#include "pump/BladeCamber.hpp"
#include "pump/PumpDesign.hpp"
#include "tests/support/TempPath.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fsi::pump {
namespace {

constexpr double deg = M_PI / 180.0;

/// int_{r1}^{r2} cot beta / r dr by the composite Simpson rule.
double simpson_wrap(const BladeCamber &camber) {
  const int n = 20000;
  const double r1 = camber.inlet_radius_m(), h = (camber.outlet_radius_m() - r1) / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double r = r1 + i * h;
    sum += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * camber.cot_beta(r) / r;
  }
  return sum * h / 3.0;
}

TEST(BladeCamber, SweepsTheWrapAngleAndMeetsBothBladeAngles) {
  for (const double sense : {-1.0, 1.0})
    for (const double wrap_deg : {260.0, 360.0, 540.0, 720.0}) {
      const BladeCamber camber(0.025, 0.1, 15.0 * deg, 25.0 * deg, wrap_deg * deg, sense);
      EXPECT_NEAR(simpson_wrap(camber), wrap_deg * deg, 1e-9) << wrap_deg;
      // the closed form of theta(r): backward-swept, against the rotation
      EXPECT_NEAR(camber.theta_rad(0.1), -sense * wrap_deg * deg, 1e-12) << wrap_deg;
      EXPECT_NEAR(camber.beta_rad(0.025), 15.0 * deg, 1e-12);
      EXPECT_NEAR(camber.beta_rad(0.1), 25.0 * deg, 1e-12);
      for (int i = 0; i <= 100; ++i) {
        const double beta = camber.beta_rad(0.025 + 0.075 * i / 100.0);
        EXPECT_GT(beta, 0.0);
        EXPECT_LT(beta, 0.5 * M_PI);
      }
    }
}

TEST(BladeCamber, RefusesAWrapThatNeedsABladeAngleOutsideZeroToNinety) {
  // 30 deg of wrap from 15 to 25 deg: the blade would have to turn radial and beyond.
  try {
    BladeCamber(0.025, 0.1, 15.0 * deg, 25.0 * deg, 30.0 * deg, -1.0);
    FAIL() << "accepted";
  } catch (const std::invalid_argument &e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("impeller.wrap_angle_deg"), std::string::npos) << message;
    EXPECT_NE(message.find("impeller.inlet_blade_angle_deg"), std::string::npos) << message;
    EXPECT_NE(message.find("impeller.outlet_blade_angle_deg"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(BladeCamber(0.025, 0.1, 15.0 * deg, 90.0 * deg, 260.0 * deg, -1.0)); // a radial outlet
}

std::string load_error(const std::string &yaml) {
  const auto path = fsi::test_support::temp_path("fsi-pump-", ".yaml");
  std::ofstream(path) << yaml;
  try {
    PumpDesign::load(path);
  } catch (const common::ConfigError &e) {
    return e.what();
  }
  return "";
}

TEST(PumpDesign, RefusesBladesAndChambersThatCannotBeBuilt) {
  EXPECT_NE(load_error("impeller: {wrap_angle_deg: 30}\n").find("impeller.wrap_angle_deg"), std::string::npos);
  EXPECT_NE(load_error("impeller: {blade_inlet_diameter_m: 0.035}\n")
                .find("blade_inlet_diameter_m = 0.035000 must exceed hub_diameter_m + 2 leading_edge_radius_m"),
            std::string::npos);
  EXPECT_NE(load_error("impeller: {blade_inlet_diameter_m: 0.2}\n").find("must be below outer_diameter_m"),
            std::string::npos);
  EXPECT_NE(load_error("impeller: {leading_edge_radius_m: 0.003}\n").find("at least half of blade_thickness_m"),
            std::string::npos);
  EXPECT_NE(load_error("volute: {base_width_m: 0.07}\n").find("does not hold the impeller"), std::string::npos);
  EXPECT_NE(load_error("inlet: {suction_pipe_diameter_m: 0.22}\n").find("opens into the impeller chamber"),
            std::string::npos);
  EXPECT_NE(load_error("inlet: {sump_diameter_m: 0.2}\n").find("a sump needs both above 0"), std::string::npos);
  EXPECT_NE(load_error("inlet: {sump_diameter_m: 0.08, sump_height_m: 0.1}\n").find("a sump is wider than its pipe"),
            std::string::npos);
  EXPECT_EQ(load_error("inlet: {sump_diameter_m: 0.2, sump_height_m: 0.12}\n"), "");
  EXPECT_EQ(load_error("impeller: {leading_edge_radius_m: 0.006}\n"), ""); // a bulb
}

TEST(PumpDesign, CounterclockwiseSeenFromTheInletIsRotationAboutMinusZ) {
  PumpDesign design;
  EXPECT_EQ(design.rotation_axis(), Vec3(0, 0, -1));
  design.operation.direction = RotationDirection::clockwise;
  EXPECT_EQ(design.rotation_axis(), Vec3(0, 0, 1));
}

} // namespace
} // namespace fsi::pump
