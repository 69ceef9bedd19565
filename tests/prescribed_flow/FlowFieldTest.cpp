// Prescribed flows against their closed forms; the tabulated field reproduces linear fields
// exactly (trilinear interpolation), clamps outside, and rejects malformed tables by file/line.

#include "common/ConfigError.hpp"
#include "prescribed_flow/AnalyticFlows.hpp"
#include "prescribed_flow/TabulatedFlow.hpp"
#include "tests/support/TempPath.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace fsi::prescribed_flow {
namespace {

TEST(AnalyticFlows, MatchTheirClosedForms) {
  const Vec3 x(0.3, -0.2, 0.5);
  EXPECT_EQ(QuiescentFlow().velocity_m_per_s(x, 1.0), Vec3::Zero());
  EXPECT_EQ(UniformFlow(Vec3(1, 2, 3)).velocity_m_per_s(x, 1.0), Vec3(1, 2, 3));
  Eigen::Matrix3d shear = Eigen::Matrix3d::Zero();
  shear(0, 1) = 4.0; // du/dy
  const LinearFlow linear(Vec3(1, 0, 0), Vec3(0, 0.1, 0), shear);
  EXPECT_NEAR((linear.velocity_m_per_s(x, 0.0) - Vec3(1 + 4.0 * (-0.3), 0, 0)).norm(), 0.0, 1e-15);
  const SolidBodyRotation rotation(Vec3(0, 0, 0), Vec3(0, 0, 2), 3.0);
  EXPECT_NEAR((rotation.velocity_m_per_s(Vec3(1, 0, 7), 0.0) - Vec3(0, 3, 0)).norm(), 0.0, 1e-15);
  Eigen::Matrix3d compressing = Eigen::Matrix3d::Identity();
  EXPECT_THROW(LinearFlow(Vec3::Zero(), Vec3::Zero(), compressing), std::invalid_argument);
}

std::filesystem::path write(const std::string &text) {
  // A random name (ctest runs each test in its own process, two at a time, and equal names let
  // one test overwrite the other's table), removed at the end.
  const auto path = fsi::test_support::temp_path("fsi-flow-", ".csv");
  std::ofstream(path) << text;
  return path;
}

TEST(TabulatedFlow, ReproducesALinearFieldAndClampsOutside) {
  // u = (1 + 2y - z, x, 0.5) on a 3 x 4 x 2 grid, rows shuffled.
  std::vector<std::string> rows;
  for (double x : {0.0, 0.5, 2.0})
    for (double y : {-1.0, 0.0, 0.25, 1.0})
      for (double z : {0.0, 0.3}) {
        std::ostringstream row;
        row << x << "," << y << "," << z << "," << 1 + 2 * y - z << "," << x << ",0.5";
        rows.push_back(row.str());
      }
  std::shuffle(rows.begin(), rows.end(), std::mt19937(7));
  std::string text = "x_m,y_m,z_m,u_m_per_s,v_m_per_s,w_m_per_s\n";
  for (const auto &r : rows)
    text += r + "\n";
  const TabulatedFlow flow = TabulatedFlow::from_csv(write(text));
  const Vec3 inside(1.3, 0.1, 0.17);
  EXPECT_NEAR((flow.velocity_m_per_s(inside, 0.0) - Vec3(1 + 0.2 - 0.17, 1.3, 0.5)).norm(), 0.0, 1e-14);
  const Vec3 outside(5.0, 0.1, 0.17); // x clamped to 2
  EXPECT_NEAR((flow.velocity_m_per_s(outside, 0.0) - Vec3(1 + 0.2 - 0.17, 2.0, 0.5)).norm(), 0.0, 1e-14);
}

TEST(TabulatedFlow, RejectsMalformedTablesNamingTheFile) {
  const auto header = write("x,y,z,u,v,w\n");
  EXPECT_THROW(TabulatedFlow::from_csv(header), common::ConfigError);
  const auto holes = write("x_m,y_m,z_m,u_m_per_s,v_m_per_s,w_m_per_s\n0,0,0,1,1,1\n1,0,0,1,1,1\n0,1,0,1,1,1\n");
  try {
    TabulatedFlow::from_csv(holes);
    FAIL() << "expected a ConfigError";
  } catch (const common::ConfigError &e) {
    EXPECT_NE(std::string(e.what()).find("do not form a full regular grid"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(holes.string()), std::string::npos) << e.what();
  }
  const auto text_value = write("x_m,y_m,z_m,u_m_per_s,v_m_per_s,w_m_per_s\n0,0,0,a,1,1\n");
  EXPECT_THROW(TabulatedFlow::from_csv(text_value), common::ConfigError);
}

} // namespace
} // namespace fsi::prescribed_flow
