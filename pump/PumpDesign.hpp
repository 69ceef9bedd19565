#pragma once
// The design file of a generated centrifugal pump (pump.yaml): the impeller, the spiral volute,
// the inlet and the operating point, typed and strict like case.yaml (units in the names,
// ranges, one line of documentation per key, unknown keys refused with a spelling hint). The
// defaults are the single-blade waste-water pump sized to the paper's duty (section 4.1:
// 1440 rpm, n_s = 56.4, cell size 0.002 m = D2 / 100).

#include "BladeCamber.hpp"

#include "common/ConfigReader.hpp"
#include "common/Types.hpp"

#include <filesystem>
#include <optional>
#include <type_traits>
#include <string>

namespace fsi::pump {

/// A single-channel impeller (pump/ChannelImpellerSolid.hpp): one enclosed channel from the eye
/// to D2, the vane the solid between the discs around it. The channel's meridional section at
/// each angle of its wrap is a rectangle: radial width and the height between its floor and the
/// hub disc. Keys of `impeller` that still apply: outer_diameter_m, outlet_width_m (the channel's
/// height where it leaves D2), eye_diameter_m, hub_diameter_m (the boss), wrap_angle_deg (from
/// the channel's back wall in the eye to its exit), inlet_blade_angle_deg (the leading edge's
/// floor angle at the eye's mean radius), outlet_blade_angle_deg (the channel's inner wall at
/// D2) and leading_edge_radius_m (the nose).
struct SingleChannelDesign {
  double mouth_angle_deg = 90.0;
  double inlet_width_m = 0.06;
  double exit_width_m = 0.07;
  double eye_cover_thickness_m = 0.012;
  std::optional<double> mouth_roof_height_m;
  double disc_thickness_m = 0.008;
  double neck_length_m = 0.0;
  double wear_ring_clearance_m = 0.002;

  template <class V> void visit(V &v) {
    v.number("mouth_angle_deg", mouth_angle_deg, common::Range::between(20.0, 240.0, "deg"),
             "Wrap over which the channel stands open to the eye below it, from its back wall to where its floor "
             "starts to rise towards the leading edge.");
    v.number("inlet_width_m", inlet_width_m, common::Range::positive("m"),
             "Radial width of the channel's section in the mouth, from the boss outwards (over the eye and beyond "
             "it above the shroud).");
    v.number("exit_width_m", exit_width_m, common::Range::positive("m"),
             "Radial width of the channel's section where its outer wall reaches D2 (the width grows linearly "
             "along the wrap from inlet_width_m).");
    v.number("eye_cover_thickness_m", eye_cover_thickness_m, common::Range::positive("m"),
             "Thickness of the vane's floor over the eye behind the leading edge (the channel's floor there is this "
             "high above the shroud plane).");
    v.optional_number("mouth_roof_height_m", mouth_roof_height_m, common::Range::positive("m"),
                      "Height above the shroud plane of the channel's roof at its back wall: the roof then rises "
                      "linearly along the mouth to the hub disc, a helical inlet whose cross-section grows as the "
                      "eye's water enters it, so that the water keeps its relative speed instead of meeting a "
                      "channel that carries little yet (fsi-pump-design states the roof's angle at the eye's mean "
                      "radius and the flow rate it matches). Absent: the roof is the hub disc over the whole mouth.");
    v.number("disc_thickness_m", disc_thickness_m, common::Range::positive("m"),
             "Thickness of the hub and shroud discs.");
    v.number("neck_length_m", neck_length_m, common::Range::non_negative("m"),
             "Length of the wear-ring neck: a tube of the eye's inner diameter below the shroud, reaching into the "
             "suction pipe (0: no neck; a suction pipe of the eye's diameter then keeps the side space from the eye). "
             "Its clearance wants a mesh that resolves it: on 8 mm cells a neck drags the eye's water round.");
    v.number("wear_ring_clearance_m", wear_ring_clearance_m, common::Range::positive("m"),
             "Radial clearance between the neck and the suction pipe (the neck's outer radius is the suction "
             "pipe's radius less this).");
  }
};

/// The seal between the shroud and the suction cover at the eye (a wear ring, or an axial wear
/// plate as in waste-water pumps), whose clearance (tenths of a millimetre) no affordable mesh
/// resolves: the flow sees it as a porous ring across the front side gap at the eye, in the
/// penalized runs and the body-fitted reference alike, whose resistance is the seal's leakage law
/// (python/fsi/front_seal.py; docs/pump-design.md, "The front seal").
struct FrontSealDesign {
  double clearance_m = 0.0004;
  double length_m = 0.015;

  template <class V> void visit(V &v) {
    v.number("clearance_m", clearance_m, common::Range::positive("m"),
             "The seal's running clearance s: the leak through it is mu pi D_s s sqrt(2 g H_s), "
             "mu = (1.5 + lambda length_m / (2 s))^-1/2 with lambda = 0.04 (0.3-0.5 mm in waste-water pumps).");
    v.number("length_m", length_m, common::Range::positive("m"),
             "The seal's radial length from the suction pipe's radius outwards: the ring of cells that models it "
             "spans this band of the front side gap.");
  }
};

struct ImpellerDesign {
  double outer_diameter_m = 0.2;
  double outlet_width_m = 0.05;
  double eye_diameter_m = 0.1;
  double hub_diameter_m = 0.03;
  double blade_inlet_diameter_m = 0.05;
  int n_blades = 1;
  double wrap_angle_deg = 360.0;
  double inlet_blade_angle_deg = 15.0;
  double outlet_blade_angle_deg = 25.0;
  double blade_thickness_m = 0.008;
  double leading_edge_radius_m = 0.004;
  bool closed = true;
  std::optional<SingleChannelDesign> single_channel;
  std::optional<FrontSealDesign> front_seal;

  /// Thickness of the hub and shroud discs: the channel's own key, or the blades' thickness.
  double disc_thickness_m() const { return single_channel ? single_channel->disc_thickness_m : blade_thickness_m; }

  template <class V> void visit(V &v) {
    v.number("outer_diameter_m", outer_diameter_m, common::Range::positive("m"), "Impeller outer diameter D2.");
    v.number("outlet_width_m", outlet_width_m, common::Range::positive("m"), "Blade height at the outlet b2.");
    v.number("eye_diameter_m", eye_diameter_m, common::Range::positive("m"), "Impeller eye (inlet) diameter D1.");
    v.number("hub_diameter_m", hub_diameter_m, common::Range::non_negative("m"), "Hub diameter at the eye.");
    v.number("blade_inlet_diameter_m", blade_inlet_diameter_m, common::Range::positive("m"),
             "Diameter D1B of the blade leading edge's camber point (the camber line runs from there to D2).");
    v.integer("n_blades", n_blades, common::Range::between(1, 12, "1"),
              "Number of blades (1: the paper's single-blade pump; 2: its two-blade pump).");
    v.number("wrap_angle_deg", wrap_angle_deg, common::Range::between(30.0, 720.0, "deg"),
             "Blade wrap angle from leading to trailing edge, about the axis.");
    v.number("inlet_blade_angle_deg", inlet_blade_angle_deg, common::Range::between(5.0, 60.0, "deg"),
             "Blade angle beta_1B at the leading edge, from the circumferential direction.");
    v.number("outlet_blade_angle_deg", outlet_blade_angle_deg, common::Range::between(5.0, 90.0, "deg"),
             "Blade angle beta_2B at the trailing edge, from the circumferential direction.");
    v.number("blade_thickness_m", blade_thickness_m, common::Range::positive("m"), "Blade thickness.");
    v.number("leading_edge_radius_m", leading_edge_radius_m, common::Range::positive("m"),
             "Radius of the rounded leading edge (the high-curvature surface a rag wraps around): half the "
             "blade thickness (a semicircle) or more (a circular bulb).");
    v.flag("closed", closed, "Closed impeller: hub and shroud discs (false: open, hub disc only).");
    v.optional_section("single_channel", single_channel,
                       "A single-channel impeller instead of blades: one enclosed channel from the eye to D2 "
                       "(n_blades, blade_inlet_diameter_m, blade_thickness_m and closed do not apply and are refused).");
    v.optional_section("front_seal", front_seal,
                       "A seal of sub-millimetre clearance between the shroud and the suction cover at the eye, "
                       "modelled as a porous ring across the front side gap (absent: the gap leaks as it is meshed).");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (v.has("single_channel"))
        for (const char *key : {"n_blades", "blade_inlet_diameter_m", "blade_thickness_m", "closed"})
          if (v.has(key))
            v.fail_value(key, "is a key of bladed impellers; a single_channel impeller has none (its discs: "
                              "single_channel.disc_thickness_m; it is always closed).");
  }
};

enum class VoluteSection { rectangular, trapezoidal };

struct VoluteDesign {
  VoluteSection section = VoluteSection::rectangular;
  double base_radius_m = 0.105;
  double base_width_m = 0.076;
  double flank_angle_deg = 0.0;
  double cut_water_nose_radius_m = 0.005;
  double discharge_diameter_m = 0.1;
  double discharge_length_m = 0.3;

  template <class V> void visit(V &v) {
    v.choice("section", section,
             {{"rectangular", VoluteSection::rectangular}, {"trapezoidal", VoluteSection::trapezoidal}},
             "Cross-section of the spiral: rectangular, or trapezoidal (flanks opening outwards).");
    v.number("base_radius_m", base_radius_m, common::Range::positive("m"),
             "Base circle of the spiral r3 (the cut-water radius); above D2 / 2. The body-fitted reference "
             "puts its sliding interface halfway between D2 / 2 and r3: at 2 mm cells a 5 mm gap leaves 1.25 "
             "cells on each side, where the impeller's rims (and a single channel's drum) stay stepped "
             "(snap_quality.yaml of the AMI run); a 10 mm gap (d3/d2 = 1.10) snaps them.");
    v.number("base_width_m", base_width_m, common::Range::positive("m"),
             "Axial width of the section at r3, and of the impeller chamber: the side gaps between the "
             "impeller's discs and the casing are (base_width_m - outlet_width_m) / 2 - blade_thickness_m.");
    v.number("flank_angle_deg", flank_angle_deg, common::Range::between(0.0, 45.0, "deg"),
             "Trapezoidal section: angle of each flank from the radial direction (0: rectangular).");
    v.number("cut_water_nose_radius_m", cut_water_nose_radius_m, common::Range::positive("m"),
             "Radius of the cut-water (volute tongue) nose.");
    v.number("discharge_diameter_m", discharge_diameter_m, common::Range::positive("m"),
             "Diameter of the discharge pipe.");
    v.number("discharge_length_m", discharge_length_m, common::Range::positive("m"),
             "Length of the straight discharge pipe after the volute.");
  }
};

struct InletDesign {
  double suction_pipe_diameter_m = 0.1;
  double suction_pipe_length_m = 0.3;
  double sump_diameter_m = 0.0;
  double sump_height_m = 0.0;

  bool has_sump() const { return sump_diameter_m > 0.0; }
  /// Diameter of the inlet patch: the sump's floor, or the suction pipe's bottom.
  double inlet_diameter_m() const { return has_sump() ? sump_diameter_m : suction_pipe_diameter_m; }

  template <class V> void visit(V &v) {
    v.number("suction_pipe_diameter_m", suction_pipe_diameter_m, common::Range::positive("m"),
             "Diameter of the suction pipe below the eye: at most the eye diameter for a closed impeller (a wider "
             "pipe opens the side space under the shroud to the suction, a leak from the volute back to the eye).");
    v.number("suction_pipe_length_m", suction_pipe_length_m, common::Range::positive("m"),
             "Length of the suction pipe from the sump (or the inlet) up to the impeller chamber.");
    v.number("sump_diameter_m", sump_diameter_m, common::Range::non_negative("m"),
             "Inlet sump: a wider cylinder below the suction pipe, its floor the inlet, where a rag too wide for the "
             "pipe is released (the paper's section 4.2). 0: no sump, the inlet is the suction pipe's bottom.");
    v.number("sump_height_m", sump_height_m, common::Range::non_negative("m"),
             "Height of the inlet sump (> 0 with a sump).");
  }
};

enum class RotationDirection { counterclockwise, clockwise };

struct OperationDesign {
  double rotation_rate_rad_per_s = 150.8;
  RotationDirection direction = RotationDirection::counterclockwise;
  double design_flow_rate_m3_per_s = 0.045;
  double hydraulic_efficiency = 0.85;
  double design_swirl_m2_per_s = 0.0;

  template <class V> void visit(V &v) {
    v.number("rotation_rate_rad_per_s", rotation_rate_rad_per_s, common::Range::positive("rad/s"),
             "Rotation rate omega (150.8 rad/s = 1440 rpm, the paper's).");
    v.choice("direction", direction,
             {{"counterclockwise", RotationDirection::counterclockwise}, {"clockwise", RotationDirection::clockwise}},
             "Sense of rotation seen from the inlet, looking downstream into the eye.");
    v.number("design_flow_rate_m3_per_s", design_flow_rate_m3_per_s, common::Range::positive("m^3/s"),
             "Flow rate the volute is sized for (the best efficiency point).");
    v.number("hydraulic_efficiency", hydraulic_efficiency, common::Range::between(0.3, 1.0, "1"),
             "eta_h of the Euler equation gH = eta_h u2 c_u2, for the swirl the volute is sized to carry.");
    v.number("design_swirl_m2_per_s", design_swirl_m2_per_s, common::Range::non_negative("m^2/s"),
             "The swirl c_u2 r2 the impeller leaves at design_flow_rate_m3_per_s, measured (./fsi pump-curve prints "
             "it at the best point: T / (rho Q)); the volute is sized to carry it. 0: from the design rules' head "
             "and hydraulic_efficiency.");
  }
};

struct PumpDesign {
  ImpellerDesign impeller;
  VoluteDesign volute;
  InletDesign inlet;
  OperationDesign operation;

  template <class V> void visit(V &v) {
    v.section("impeller", impeller, "The rotating part: blades between hub and shroud.");
    v.section("volute", volute, "The spiral casing around the impeller and its discharge.");
    v.section("inlet", inlet, "The suction pipe below the eye, and an optional inlet sump below it.");
    v.section("operation", operation, "Rotation and design flow rate.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      validate(v);
  }

  /// The rotation axis (right-hand rule): counterclockwise seen from the inlet, looking along +z
  /// into the eye, is rotation about -z, i.e. (0, 0, -1); clockwise is (0, 0, 1).
  Vec3 rotation_axis() const;
  /// +1 for rotation about +z, -1 about -z (the z component of rotation_axis()).
  double rotation_sense() const { return rotation_axis()[2]; }

  /// The camber line of the blades (throws std::invalid_argument when the angles cannot be met).
  BladeCamber blade_camber() const;
  /// The axial extent of the impeller: the shroud's (or the channel's) bottom or the hub's nose,
  /// and the hub disc's top (m; the channel spans z in [0, outlet_width_m]).
  double impeller_bottom_z_m() const;
  double impeller_top_z_m() const;
  /// The impeller chamber's flat floor and roof (m): the volute's base width centred on the channel.
  double chamber_floor_z_m() const { return 0.5 * (impeller.outlet_width_m - volute.base_width_m); }
  double chamber_roof_z_m() const { return 0.5 * (impeller.outlet_width_m + volute.base_width_m); }
  /// The front side gap's height (m): from the chamber's floor to the shroud's face.
  double front_side_gap_m() const { return -impeller.disc_thickness_m() - chamber_floor_z_m(); }
  /// The hub's nose reaches hub_nose_depth outlet widths below the channel, into the eye.
  static constexpr double hub_nose_depth = 0.2;
  /// The smallest axial gap between the impeller and the chamber's flat walls.
  static constexpr double min_axial_clearance_m = 0.002;

  /// Reads and validates a design file; throws common::ConfigError naming the file and key.
  static PumpDesign load(const std::filesystem::path &file);
  /// The reference of the design file (Markdown, one table; docs/pump-design.md holds it).
  static std::string schema_markdown();

private:
  void validate(common::ConfigReader &v) const;
  void validate_blades(common::ConfigReader &v) const;
  void validate_single_channel(common::ConfigReader &v) const;
  void validate_casing(common::ConfigReader &v) const;
  void validate_front_seal(common::ConfigReader &v) const;
};

} // namespace fsi::pump
