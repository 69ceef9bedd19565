// The geometry checks of a generated pump on synthetic solids with known answers: each check
// refuses its defect with the advice the user needs (open, inverted, in millimetres, sticking
// out of the casing, touching it) and measures what is known exactly (the volumes, the throat
// section of a rectangular volute, the free passage of the channel between two discs, a
// sphere's volume between its inscribed and circumscribed spheres).

#include "SyntheticPump.hpp"

#include "geometry/MeshGenerators.hpp"
#include "geometry/StlIo.hpp"
#include "pump/GeometryChecks.hpp"
#include "pump/VoluteSizing.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>

namespace fsi::pump {
namespace {

using namespace fsi::pump::testing;

GeometryCheckReport run(const geometry::RegionSoup &impeller_mesh, const geometry::RegionSoup &casing_mesh,
                        const GeometryCheckLimits &l = limits()) {
  return GeometryChecks(frame(), l).run(impeller_mesh, "impeller.stl", casing_mesh, "casing.stl");
}

/// The check of that name (the report must outlive the reference).
const CheckResult &check(const GeometryCheckReport &report, const std::string &name) {
  for (const CheckResult &c : report.checks)
    if (c.name == name)
      return c;
  throw std::logic_error("no check named " + name);
}

void expect_message_holds(const CheckResult &c, const std::string &part) {
  EXPECT_NE(c.message.find(part), std::string::npos) << c.message;
}

TEST(GeometryChecks, TheSyntheticPumpPassesEveryCheckWithItsKnownMeasures) {
  const GeometryCheckReport report = run(impeller(), casing());
  ASSERT_TRUE(report.passed()) << report.table();
  const double polygon = 0.5 * n_around * std::sin(2.0 * M_PI / n_around); // unit n-gon's area
  EXPECT_NEAR(report.casing_volume_m3, polygon * casing_radius * casing_radius * (casing_top - casing_bottom), 1e-12);
  const double blades = 2 * 0.068 * 0.008 * (b2 - 0.001);
  EXPECT_NEAR(report.impeller_volume_m3, polygon * t * (2 * r2 * r2 - eye * eye) + blades, 1e-12);
  // The throat: the rectangle beyond r3 in the half-plane at angle 0, exactly.
  EXPECT_NEAR(report.throat_area_m2, (casing_radius - r3) * (casing_top - casing_bottom), 1e-14);
  // The channel between the discs is a slot of width b2: the passage is b2 within h (4 mm).
  EXPECT_NEAR(report.free_passage_m, b2, 0.004);
  EXPECT_LE(report.free_passage_m, b2 + 1e-7);
  EXPECT_GT(report.bottleneck_m.z(), 0.0);
  EXPECT_LT(report.bottleneck_m.z(), b2);
  // Smallest gap: the shroud's bottom (z = -t) above the casing's (z = -0.06).
  EXPECT_NEAR(report.min_clearance_m, -t - casing_bottom, 1e-9);
}

TEST(GeometryChecks, AnOpenSurfaceIsRefusedWithItsOpenEdgesLocated) {
  geometry::RegionSoup open = impeller();
  open.soup.triangles.conservativeResize(open.soup.triangles.rows() - 1, 3);
  open.region_of_triangle.pop_back();
  const GeometryCheckReport report = run(open, casing());
  const CheckResult &closed = check(report, "impeller closed");
  EXPECT_EQ(closed.status, CheckStatus::fail);
  EXPECT_EQ(closed.value, "3 open edges");
  expect_message_holds(closed, "impeller.stl");
  expect_message_holds(closed, "one at (");
  expect_message_holds(closed, "region 'hub'");
  EXPECT_EQ(check(report, "free passage").status, CheckStatus::skipped);
  EXPECT_EQ(report.first_failure(), &closed);
}

TEST(GeometryChecks, AnInvertedSurfaceIsRefusedWithTheFlipAdvice) {
  geometry::RegionSoup inverted = casing();
  inverted.soup.triangles.col(1).swap(inverted.soup.triangles.col(2));
  const GeometryCheckReport report = run(impeller(), inverted);
  const CheckResult &orientation = check(report, "casing orientation");
  EXPECT_EQ(orientation.status, CheckStatus::fail);
  expect_message_holds(orientation, "casing.stl");
  expect_message_holds(orientation, "normals point inward");
  expect_message_holds(orientation, "flip the facets");
  geometry::RegionSoup mixed = casing();
  std::swap(mixed.soup.triangles(0, 1), mixed.soup.triangles(0, 2));
  const GeometryCheckReport mixed_report = run(impeller(), mixed);
  expect_message_holds(check(mixed_report, "casing orientation"), "not consistently oriented");
}

TEST(GeometryChecks, AMillimetreFileIsRefusedWithTheUnitAdvice) {
  geometry::RegionSoup mm_impeller = impeller(), mm_casing = casing();
  mm_impeller.soup.vertices_m *= 1000.0;
  mm_casing.soup.vertices_m *= 1000.0;
  const GeometryCheckReport report = run(mm_impeller, mm_casing);
  const CheckResult &units = check(report, "units");
  EXPECT_EQ(units.status, CheckStatus::fail);
  expect_message_holds(units, "impeller.stl");
  expect_message_holds(units, "looks like millimetres: set unit scale 0.001");
  EXPECT_TRUE(run(mm_impeller, mm_casing, limits(0.001)).passed());
}

TEST(GeometryChecks, AnImpellerStickingOutOfTheCasingIsRefusedNamingAVertex) {
  const GeometryCheckReport report = run(impeller(), casing(0.095));
  const CheckResult &inside = check(report, "impeller inside casing");
  EXPECT_EQ(inside.status, CheckStatus::fail);
  expect_message_holds(inside, "impeller.stl");
  expect_message_holds(inside, "outside the casing 'casing.stl'");
  expect_message_holds(inside, "at (");
}

TEST(GeometryChecks, AnImpellerTouchingTheCasingIsRefusedSayingWhereAndHowClose) {
  const GeometryCheckReport report = run(impeller(), casing(casing_radius, -t - 0.0005));
  const CheckResult &gap = check(report, "impeller-casing gap");
  EXPECT_EQ(gap.status, CheckStatus::fail);
  EXPECT_NEAR(report.min_clearance_m, 0.0005, 1e-9);
  EXPECT_NEAR(report.closest_point_m.z(), -t, 0.0005 + 1e-9);
  expect_message_holds(gap, "touches the casing");
  expect_message_holds(gap, "0.5 mm apart at (");
}

TEST(GeometryChecks, AThroatOutsideTheDesignBandIsRefusedWithTheRulesValue) {
  const GeometryCheckReport report = run(impeller(), casing(0.13)); // throat 0.025 x 0.18 m = 45 cm^2
  const CheckResult &throat = check(report, "volute throat");
  EXPECT_EQ(throat.status, CheckStatus::fail);
  expect_message_holds(throat, "45 cm^2, outside the design rules' 80-115 cm^2");
  expect_message_holds(throat, "rule gives 100 cm^2");
}

TEST(GeometryChecks, ASphereEnclosesBetweenItsInscribedAndCircumscribedBalls) {
  const double radius = 0.1;
  geometry::TriangleSoup sphere = geometry::make_icosphere(Vec3(0, 0, 0.03), radius, 4);
  double inradius = radius; // the smallest distance of a face's plane from the centre
  for (Eigen::Index f = 0; f < sphere.triangles.rows(); ++f) {
    const Vec3 a = sphere.vertices_m.row(sphere.triangles(f, 0)).transpose() - Vec3(0, 0, 0.03);
    const Vec3 b = sphere.vertices_m.row(sphere.triangles(f, 1)).transpose() - Vec3(0, 0, 0.03);
    const Vec3 c = sphere.vertices_m.row(sphere.triangles(f, 2)).transpose() - Vec3(0, 0, 0.03);
    inradius = std::min(inradius, std::abs(a.dot((b - a).cross(c - a).normalized())));
  }
  const GeometryCheckReport report = run(one_region(sphere, "ball"), casing(0.2, -0.1));
  const double ball = 4.0 / 3.0 * M_PI * std::pow(radius, 3);
  EXPECT_LT(report.impeller_volume_m3, ball);
  EXPECT_GT(report.impeller_volume_m3, ball * std::pow(inradius / radius, 3));
  EXPECT_NEAR(report.impeller_volume_m3, ball, 0.01 * ball); // 5120 faces: within 1 %
}

TEST(GeometryChecks, FilesAreReadWithTheirRegionsAndTheReportIsYaml) {
  const auto folder = std::filesystem::temp_directory_path() / "fsi_pump_geometry_checks";
  std::filesystem::create_directories(folder);
  const std::string impeller_file = (folder / "impeller.stl").string(), casing_file = (folder / "casing.stl").string();
  geometry::write_stl_regions(impeller_file, impeller());
  geometry::write_stl_regions(casing_file, casing());
  const GeometryCheckReport report = GeometryChecks(frame(), limits()).run(impeller_file, casing_file);
  std::filesystem::remove_all(folder);
  EXPECT_TRUE(report.passed()) << report.table();
  const YAML::Node yaml = YAML::Load(report.to_yaml());
  EXPECT_EQ(yaml["impeller_file"].as<std::string>(), impeller_file);
  EXPECT_TRUE(yaml["passed"].as<bool>());
  EXPECT_EQ(yaml["checks"].size(), report.checks.size());
  EXPECT_NEAR(yaml["measures"]["throat_area_m2"].as<double>(), report.throat_area_m2, 1e-15);
  EXPECT_EQ(yaml["measures"]["bottleneck_m"].size(), 3u);
  EXPECT_NE(report.table().find("free passage"), std::string::npos);
}

TEST(GeometryChecks, TheFrameOfTheDefaultDesignHasTheRulesThroat) {
  const PumpGeometryFrame f = PumpGeometryFrame::from_design(PumpDesign{});
  EXPECT_DOUBLE_EQ(f.impeller_radius_m, 0.1);
  EXPECT_DOUBLE_EQ(f.eye_radius_m, 0.05);
  EXPECT_GT(f.design_throat_area_m2, 80e-4); // 111 cm^2 (DesignRulesTest)
  EXPECT_LT(f.design_throat_area_m2, 115e-4);
  const ThroatBand band = throat_band(PumpDesign{}); // the checks' band is the duty's
  EXPECT_DOUBLE_EQ(f.throat_band_min_m2, band.min_area_m2);
  EXPECT_DOUBLE_EQ(f.throat_band_max_m2, band.max_area_m2);
}

} // namespace
} // namespace fsi::pump
