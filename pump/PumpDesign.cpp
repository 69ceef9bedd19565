#include "PumpDesign.hpp"

#include "ChannelLayout.hpp"
#include "GeometryChecks.hpp"

#include "common/ConfigDocWriter.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fsi::pump {

PumpDesign PumpDesign::load(const std::filesystem::path &file) {
  auto reader = common::ConfigReader::from_file(file);
  PumpDesign design;
  design.visit(reader);
  reader.finish();
  return design;
}

std::string PumpDesign::schema_markdown() {
  std::ostringstream out;
  common::ConfigDocWriter::header(out);
  PumpDesign defaults;
  common::ConfigDocWriter writer(out);
  defaults.visit(writer);
  return out.str();
}

Vec3 PumpDesign::rotation_axis() const {
  return Vec3(0.0, 0.0, operation.direction == RotationDirection::counterclockwise ? -1.0 : 1.0);
}

BladeCamber PumpDesign::blade_camber() const {
  constexpr double deg = M_PI / 180.0;
  return BladeCamber(0.5 * impeller.blade_inlet_diameter_m, 0.5 * impeller.outer_diameter_m,
                     impeller.inlet_blade_angle_deg * deg, impeller.outlet_blade_angle_deg * deg,
                     impeller.wrap_angle_deg * deg, rotation_sense());
}

double PumpDesign::impeller_bottom_z_m() const {
  if (impeller.single_channel) // the shroud (the neck reaches on below, into the suction pipe)
    return -impeller.disc_thickness_m();
  const double shroud = impeller.closed ? -impeller.blade_thickness_m : 0.0;
  const double nose = impeller.hub_diameter_m > 0.0 ? -hub_nose_depth * impeller.outlet_width_m : 0.0;
  return std::min(shroud, nose);
}

double PumpDesign::impeller_top_z_m() const { return impeller.outlet_width_m + impeller.disc_thickness_m(); }

void PumpDesign::validate(common::ConfigReader &v) const {
  const auto &i = impeller;
  if (i.eye_diameter_m >= i.outer_diameter_m)
    v.fail_value("impeller", "eye_diameter_m = " + std::to_string(i.eye_diameter_m) +
                                 " must be below outer_diameter_m = " + std::to_string(i.outer_diameter_m) + ".");
  if (i.hub_diameter_m >= i.eye_diameter_m)
    v.fail_value("impeller", "hub_diameter_m = " + std::to_string(i.hub_diameter_m) +
                                 " must be below eye_diameter_m = " + std::to_string(i.eye_diameter_m) + ".");
  if (i.single_channel)
    validate_single_channel(v);
  else
    validate_blades(v);
  validate_casing(v);
  if (impeller.front_seal)
    validate_front_seal(v);
}

void PumpDesign::validate_front_seal(common::ConfigReader &v) const {
  const auto &seal = *impeller.front_seal;
  if (!impeller.single_channel && !impeller.closed)
    v.fail_value("impeller", "front_seal: an open impeller (closed: false) has no shroud to seal against the "
                             "suction cover.");
  if (impeller.single_channel && impeller.single_channel->neck_length_m > 0.0)
    v.fail_value("impeller", "front_seal with a wear-ring neck (single_channel.neck_length_m = " +
                                 std::to_string(impeller.single_channel->neck_length_m) +
                                 "): the neck is the seal, meshed; give one or the other.");
  const double r_in = 0.5 * inlet.suction_pipe_diameter_m, r2 = 0.5 * impeller.outer_diameter_m;
  if (r_in + seal.length_m > r2)
    v.fail_value("impeller", "front_seal.length_m = " + std::to_string(seal.length_m) +
                                 " reaches past D2: the front side gap runs from the suction pipe's radius " +
                                 std::to_string(r_in) + " m to " + std::to_string(r2) + " m.");
  const double gap = front_side_gap_m();
  if (seal.clearance_m >= gap)
    v.fail_value("impeller", "front_seal.clearance_m = " + std::to_string(seal.clearance_m) +
                                 " is not below the front side gap it models, " + std::to_string(gap) +
                                 " m (the mesh resolves a clearance that wide: leave front_seal out).");
}

void PumpDesign::validate_single_channel(common::ConfigReader &v) const {
  const auto &sc = *impeller.single_channel;
  try {
    ChannelLayout layout(*this);
  } catch (const std::invalid_argument &e) {
    v.fail_value("impeller", std::string("the single channel cannot be laid out: ") + e.what() + ".");
  }
  if (sc.neck_length_m > 0.0 && sc.wear_ring_clearance_m < GeometryCheckLimits{}.min_clearance_m)
    v.fail_value("impeller", "single_channel.wear_ring_clearance_m = " + std::to_string(sc.wear_ring_clearance_m) +
                                 " is below the " + std::to_string(GeometryCheckLimits{}.min_clearance_m) +
                                 " m running clearance the geometry checks ask of every gap.");
  const double neck_outer = 0.5 * inlet.suction_pipe_diameter_m - sc.wear_ring_clearance_m;
  if (sc.neck_length_m > 0.0 && neck_outer < 0.5 * impeller.eye_diameter_m + 0.5 * sc.disc_thickness_m)
    v.fail_value("impeller", "the wear-ring neck's wall, from the eye's radius " +
                                 std::to_string(0.5 * impeller.eye_diameter_m) + " m out to the suction pipe's radius less "
                                 "single_channel.wear_ring_clearance_m, " + std::to_string(neck_outer) +
                                 " m, is thinner than half a disc: widen inlet.suction_pipe_diameter_m (or set "
                                 "single_channel.neck_length_m: 0 for no neck).");
  const double chamber_low = chamber_floor_z_m();
  if (sc.neck_length_m > 0.0 && -sc.disc_thickness_m - sc.neck_length_m > chamber_low - min_axial_clearance_m)
    v.fail_value("impeller", "single_channel.neck_length_m = " + std::to_string(sc.neck_length_m) +
                                 " does not reach past the impeller chamber's floor (z = " + std::to_string(chamber_low) +
                                 " m) into the suction pipe: the neck would not seal the side space.");
}

void PumpDesign::validate_blades(common::ConfigReader &v) const {
  const auto &i = impeller;
  if (2.0 * i.leading_edge_radius_m < i.blade_thickness_m * (1.0 - 1e-12))
    v.fail_value("impeller",
                 "leading_edge_radius_m = " + std::to_string(i.leading_edge_radius_m) +
                     " must be at least half of blade_thickness_m = " + std::to_string(i.blade_thickness_m) +
                     " (the nose is a semicircle across the blade, or a larger circular bulb).");
  if (i.blade_inlet_diameter_m <= i.hub_diameter_m + 2.0 * i.leading_edge_radius_m)
    v.fail_value("impeller", "blade_inlet_diameter_m = " + std::to_string(i.blade_inlet_diameter_m) +
                                 " must exceed hub_diameter_m + 2 leading_edge_radius_m = " +
                                 std::to_string(i.hub_diameter_m + 2.0 * i.leading_edge_radius_m) +
                                 " (the rounded leading edge must clear the hub).");
  if (i.blade_inlet_diameter_m >= i.outer_diameter_m)
    v.fail_value("impeller", "blade_inlet_diameter_m = " + std::to_string(i.blade_inlet_diameter_m) +
                                 " must be below outer_diameter_m = " + std::to_string(i.outer_diameter_m) + ".");
  try {
    blade_camber();
  } catch (const std::invalid_argument &e) {
    v.fail_value("impeller", e.what() + std::string("."));
  }
}

void PumpDesign::validate_casing(common::ConfigReader &v) const {
  const auto &i = impeller;
  if (volute.base_radius_m <= 0.5 * i.outer_diameter_m)
    v.fail_value("volute", "base_radius_m = " + std::to_string(volute.base_radius_m) +
                               " must exceed the impeller radius outer_diameter_m / 2 = " +
                               std::to_string(0.5 * i.outer_diameter_m) + " (the cut-water gap).");
  const double chamber_low = chamber_floor_z_m(), chamber_high = chamber_roof_z_m();
  if (chamber_low > impeller_bottom_z_m() - min_axial_clearance_m ||
      chamber_high < impeller_top_z_m() + min_axial_clearance_m)
    v.fail_value("volute", "base_width_m = " + std::to_string(volute.base_width_m) +
                               " gives an impeller chamber z in [" + std::to_string(chamber_low) + ", " +
                               std::to_string(chamber_high) + "] m that does not hold the impeller, z in [" +
                               std::to_string(impeller_bottom_z_m()) + ", " + std::to_string(impeller_top_z_m()) +
                               "] m (shroud, hub disc and the hub's nose, from impeller.outlet_width_m, "
                               "the discs' thickness and hub_diameter_m), with " +
                               std::to_string(min_axial_clearance_m) + " m clearance on each side.");
  if (0.5 * inlet.suction_pipe_diameter_m >= volute.base_radius_m)
    v.fail_value("inlet", "suction_pipe_diameter_m = " + std::to_string(inlet.suction_pipe_diameter_m) +
                              " must be below 2 volute.base_radius_m = " + std::to_string(2.0 * volute.base_radius_m) +
                              " (the suction pipe opens into the impeller chamber).");
  if (inlet.has_sump() != (inlet.sump_height_m > 0.0))
    v.fail_value("inlet", "sump_diameter_m = " + std::to_string(inlet.sump_diameter_m) + " and sump_height_m = " +
                              std::to_string(inlet.sump_height_m) +
                              ": a sump needs both above 0 (or leave both out for none).");
  if (inlet.has_sump() && inlet.sump_diameter_m <= inlet.suction_pipe_diameter_m)
    v.fail_value("inlet", "sump_diameter_m = " + std::to_string(inlet.sump_diameter_m) +
                              " must be above suction_pipe_diameter_m = " +
                              std::to_string(inlet.suction_pipe_diameter_m) + " (a sump is wider than its pipe).");
  if (volute.section == VoluteSection::rectangular && volute.flank_angle_deg != 0.0)
    v.fail_value("volute", "flank_angle_deg is for a trapezoidal section; a rectangular one has none.");
}

} // namespace fsi::pump
