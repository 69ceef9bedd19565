// The single channel's layout (pump/ChannelLayout): the sections against the design's keys
// (the mouth open below the shroud plane, the leading edge's ramp at the inlet angle, the inner
// wall reaching D2 at the outlet angle, the width growing to the exit's), and the design file's
// refusals of a channel that cannot be laid out or sealed.

#include "pump/ChannelLayout.hpp"

#include "common/ConfigError.hpp"
#include "tests/support/TempPath.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace fsi::pump {
namespace {

constexpr double deg = M_PI / 180.0;
const std::string shipped = std::string(FSI_SOURCE_DIR) + "/pump/designs/single-channel.yaml";
/// The refusals and the numbers below are checked on a frozen copy of an earlier shipped design,
/// so that they stay put while the shipped one changes; the layout's rules on the shipped one.
const std::string reference = std::string(FSI_SOURCE_DIR) + "/tests/pump/single-channel-reference.yaml";

PumpDesign shipped_design() { return PumpDesign::load(shipped); }
PumpDesign reference_design() { return PumpDesign::load(reference); }
/// The reference design's front seal, as its file writes it.
const std::string seal_keys = "  front_seal:\n    clearance_m: 0.0004\n    length_m: 0.015\n";

/// The error of loading the reference design with each `find` replaced by its `replace` ("" if none).
std::string load_error(const std::vector<std::pair<std::string, std::string>> &edits) {
  std::ifstream in(reference);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  for (const auto &[find, replace] : edits) {
    const auto at = yaml.find(find);
    if (at == std::string::npos)
      return "the test's text '" + find + "' is not in " + reference;
    yaml.replace(at, find.size(), replace);
  }
  const auto file = fsi::test_support::temp_path("fsi-single-channel-", ".yaml");
  std::ofstream(file) << yaml;
  try {
    PumpDesign::load(file);
  } catch (const common::ConfigError &e) {
    return e.what();
  }
  return "";
}

std::string load_error(const std::string &find, const std::string &replace) { return load_error({{find, replace}}); }

/// A design without its mouth's roof (the roof is the hub disc over the whole mouth).
PumpDesign without_roof(PumpDesign d) {
  d.impeller.single_channel->mouth_roof_height_m.reset();
  return d;
}

TEST(ChannelLayout, TheMouthIsOpenToTheEyeFromTheBossOutwards) {
  const PumpDesign d = shipped_design();
  const ChannelLayout layout(d);
  const auto &sc = *d.impeller.single_channel;
  ASSERT_TRUE(sc.mouth_roof_height_m.has_value()); // the shipped mouth has its helical roof
  for (double phi = 0.0; phi <= layout.mouth_end_rad(); phi += 0.05) {
    const ChannelSection s = layout.section(phi);
    EXPECT_DOUBLE_EQ(s.inner_radius_m, 0.5 * d.impeller.hub_diameter_m);
    EXPECT_DOUBLE_EQ(s.outer_radius_m - s.inner_radius_m, sc.inlet_width_m);
    EXPECT_LT(s.floor_z_m, 0.0); // below the shroud plane: open to the eye
    EXPECT_GE(s.top_z_m, *sc.mouth_roof_height_m - 1e-12); // the roof: from its height at the back wall
  }
  const ChannelLayout flat(without_roof(d));
  for (double phi = 0.0; phi <= flat.mouth_end_rad(); phi += 0.05)
    EXPECT_GT(flat.section(phi).top_z_m, d.impeller.outlet_width_m); // without it: the hub disc
}

TEST(ChannelLayout, TheLeadingEdgesRampRisesAtTheInletAngleThroughTheShroudPlane) {
  const PumpDesign d = shipped_design();
  const ChannelLayout layout(d);
  const double r_mean = 0.5 * (layout.boss_radius_m() + layout.eye_radius_m());
  const double phi = 0.5 * (layout.mouth_end_rad() + layout.ramp_end_rad()), h = 1e-4;
  const double slope = (layout.section(phi + h).floor_z_m - layout.section(phi - h).floor_z_m) / (2.0 * h);
  EXPECT_NEAR(std::atan(slope / r_mean) / deg, d.impeller.inlet_blade_angle_deg, 1e-6);
  EXPECT_NEAR(layout.section(layout.leading_edge_phi_rad()).floor_z_m, 0.0, 1e-12);
  EXPECT_NEAR(layout.section(layout.ramp_end_rad()).floor_z_m, d.impeller.single_channel->eye_cover_thickness_m,
              1e-12);
  // Behind the edge the cover holds until the inner wall is past the eye's rim.
  EXPECT_GT(layout.section(layout.cover_end_rad()).inner_radius_m, layout.eye_radius_m());
  EXPECT_LT(layout.cover_end_rad(), layout.wrap_rad());
}

TEST(ChannelLayout, AMouthRoofRisesLinearlyFromTheBackWallToTheHubDisc) {
  PumpDesign d = without_roof(reference_design());
  const ChannelLayout flat(d);
  EXPECT_DOUBLE_EQ(flat.mouth_roof_angle_deg(), 0.0);
  EXPECT_DOUBLE_EQ(flat.section(0.0).top_z_m, flat.section(flat.mouth_end_rad()).top_z_m); // no roof: the disc
  d.impeller.single_channel->mouth_roof_height_m = 0.006;
  const ChannelLayout roof(d);
  const double top = flat.section(0.0).top_z_m, phi_m = roof.mouth_end_rad();
  EXPECT_DOUBLE_EQ(roof.section(0.0).top_z_m, 0.006);
  EXPECT_NEAR(roof.section(0.5 * phi_m).top_z_m, 0.5 * (0.006 + top), 1e-12);
  EXPECT_NEAR(roof.section(phi_m).top_z_m, top, 1e-12);
  EXPECT_DOUBLE_EQ(roof.section(phi_m + 0.1).top_z_m, top);                 // past the mouth: the disc
  EXPECT_DOUBLE_EQ(roof.section(0.3).floor_z_m, flat.section(0.3).floor_z_m); // the floor as without it
  // Its angle at the eye's mean radius: the rise over the mean radius's arc.
  const double r_mean = 0.5 * (roof.boss_radius_m() + roof.eye_radius_m());
  EXPECT_NEAR(std::tan(roof.mouth_roof_angle_deg() * deg), (top - 0.006) / (r_mean * phi_m), 1e-12);
  EXPECT_NEAR(roof.mouth_roof_angle_deg(), 35.8, 0.05); // the reference channel's 6 mm roof (fsi-pump-design)
  EXPECT_NEAR(ChannelLayout(reference_design()).mouth_roof_angle_deg(), 35.8, 0.05);
  EXPECT_NE(load_error("    mouth_roof_height_m: 0.006\n", "    mouth_roof_height_m: 0.08\n")
                .find("mouth_roof_height_m = 0.08 must lie between"),
            std::string::npos);
  EXPECT_NE(load_error("    mouth_roof_height_m: 0.006\n", "    mouth_roof_height_m: 0.002\n")
                .find("mouth_roof_height_m = 0.002 must lie between"),
            std::string::npos);
}

TEST(ChannelLayout, TheInnerWallRisesMonotonicallyToD2AtTheOutletAngle) {
  const PumpDesign d = shipped_design();
  const ChannelLayout layout(d);
  const double r2 = 0.5 * d.impeller.outer_diameter_m, wrap = layout.wrap_rad(), h = 1e-5;
  EXPECT_NEAR(layout.section(wrap).inner_radius_m, r2, 1e-12);
  const double slope = (layout.section(wrap).inner_radius_m - layout.section(wrap - h).inner_radius_m) / h;
  EXPECT_NEAR(std::atan(slope / r2) / deg, d.impeller.outlet_blade_angle_deg, 1e-3);
  EXPECT_NEAR(layout.section(wrap).outer_radius_m - r2, d.impeller.single_channel->exit_width_m, 1e-12);
  double previous = 0.0;
  for (double phi = 0.0; phi <= layout.exit_phi_rad(); phi += 0.01) {
    const double r = layout.section(phi).inner_radius_m;
    EXPECT_GE(r, previous - 1e-12) << "phi " << phi;
    previous = r;
  }
  // The last section lies entirely outside D2 (the channel leaves through the periphery).
  const auto sections = layout.loft_sections(10.0 * deg);
  EXPECT_GT(sections.back().inner_radius_m, r2);
  EXPECT_NEAR(layout.exit_area_m2(),
              d.impeller.single_channel->exit_width_m * d.impeller.outlet_width_m *
                  std::cos(d.impeller.outlet_blade_angle_deg * deg),
              1e-12);
}

TEST(ChannelLayout, TheLoftsSectionsIncludeEveryKinkAndAreAtMostTheStepApart) {
  const ChannelLayout layout(shipped_design());
  const auto sections = layout.loft_sections(10.0 * deg);
  for (std::size_t k = 1; k < sections.size(); ++k) {
    EXPECT_GT(sections[k].phi_rad - sections[k - 1].phi_rad, 1e-6);
    EXPECT_LE(sections[k].phi_rad - sections[k - 1].phi_rad, 10.0 * deg + 1e-12);
  }
  for (const double kink : {layout.mouth_end_rad(), layout.ramp_end_rad(), layout.cover_end_rad(), layout.wrap_rad()}) {
    bool found = false;
    for (const auto &s : sections)
      found = found || std::abs(s.phi_rad - kink) < 1e-9;
    EXPECT_TRUE(found) << kink;
  }
}

TEST(ChannelLayout, ADesignThatCannotBeBuiltIsRefusedNamingItsKeys) {
  EXPECT_NE(load_error("  outlet_blade_angle_deg: 30\n", "  outlet_blade_angle_deg: 80\n")
                .find("outlet_blade_angle_deg = 80 is too steep"),
            std::string::npos);
  EXPECT_NE(load_error("  outlet_blade_angle_deg: 30\n", "  outlet_blade_angle_deg: 35\n")
                .find("reaches the eye's rim too late to let its floor fall back to the shroud before the exit "
                      "(a steeper outlet angle bends the wall's end inwards): lower outlet_blade_angle_deg"),
            std::string::npos);
  EXPECT_NE(load_error("    inlet_width_m: 0.06\n", "    inlet_width_m: 0.03\n")
                .find("inlet_width_m = 0.03 does not reach the eye's rim"),
            std::string::npos);
  EXPECT_NE(load_error("  wrap_angle_deg: 330\n", "  wrap_angle_deg: 200\n").find("for the spiral"), std::string::npos);
  EXPECT_NE(load_error({{"  wrap_angle_deg: 330\n", "  wrap_angle_deg: 500\n"},
                        {"  outlet_blade_angle_deg: 30\n", "  outlet_blade_angle_deg: 15\n"}})
                .find("the channel comes round onto itself"),
            std::string::npos);
  EXPECT_EQ(load_error({{"  wrap_angle_deg: 330\n", "  wrap_angle_deg: 355\n"},
                        {"    inlet_width_m: 0.06\n", "    inlet_width_m: 0.08\n"}}),
            ""); // past its mouth's radii: the end may come round to it
  EXPECT_NE(load_error("    inlet_width_m: 0.06\n", "    inlet_width_m: 0.085\n").find("takes the mouth out to D2"),
            std::string::npos);
  const std::pair<std::string, std::string> pipe{"  suction_pipe_diameter_m: 0.12\n",
                                                 "  suction_pipe_diameter_m: 0.14\n"};
  const std::pair<std::string, std::string> neck{"    neck_length_m: 0\n", "    neck_length_m: 0.02\n"};
  const std::pair<std::string, std::string> no_seal{seal_keys, ""}; // the neck is the seal
  EXPECT_EQ(load_error({neck, pipe, no_seal}), "");
  EXPECT_NE(load_error({neck, {"    wear_ring_clearance_m: 0.002\n", "    wear_ring_clearance_m: 0.0005\n"}, pipe,
                        no_seal})
                .find("below the 0.001000 m running clearance"),
            std::string::npos);
  EXPECT_NE(load_error({{"    neck_length_m: 0\n", "    neck_length_m: 0.005\n"}, pipe, no_seal})
                .find("does not reach past the impeller chamber's floor"),
            std::string::npos);
  EXPECT_NE(load_error({neck, no_seal}).find("the wear-ring neck's wall"),
            std::string::npos); // the pipe no wider than the eye: no room for the neck
  EXPECT_NE(load_error("  hub_diameter_m: 0.024\n", "  hub_diameter_m: 0.024\n  n_blades: 1\n")
                .find("is a key of bladed impellers"),
            std::string::npos);
  EXPECT_EQ(load_error("  wrap_angle_deg: 330\n", "  wrap_angle_deg: 330\n"), "");
}

TEST(ChannelLayout, AFrontSealIsRefusedWhereItCannotSealTheFrontSideGap) {
  const PumpDesign design = reference_design();
  ASSERT_TRUE(design.impeller.front_seal.has_value()); // the reference design's: 0.4 mm, 15 mm long
  EXPECT_DOUBLE_EQ(design.impeller.front_seal->clearance_m, 0.0004);
  EXPECT_DOUBLE_EQ(design.impeller.front_seal->length_m, 0.015);
  EXPECT_EQ(load_error(seal_keys, "  front_seal: {}\n"), ""); // the defaults
  const std::string clearance = "    clearance_m: 0.0004\n", length = "    length_m: 0.015\n";
  // wider than the gap it models (5 mm: the chamber's floor at -0.013 m, the shroud's face at -0.008 m)
  EXPECT_NE(load_error(clearance, "    clearance_m: 0.005\n").find("is not below the front side gap it models"),
            std::string::npos);
  EXPECT_EQ(load_error(clearance, "    clearance_m: 0.0049\n"), "");
  EXPECT_NE(load_error(length, "    length_m: 0.05\n").find("reaches past D2"), std::string::npos);
  EXPECT_NE(load_error(clearance, "    clearance_m: -0.0004\n").find("clearance_m"), std::string::npos);
  EXPECT_NE(load_error(clearance, "    clerance_m: 0.0004\n").find("clerance_m"), std::string::npos);
  EXPECT_NE(load_error({{"    neck_length_m: 0\n", "    neck_length_m: 0.02\n"},
                        {"  suction_pipe_diameter_m: 0.12\n", "  suction_pipe_diameter_m: 0.14\n"}})
                .find("the neck is the seal"),
            std::string::npos);
}

} // namespace
} // namespace fsi::pump
