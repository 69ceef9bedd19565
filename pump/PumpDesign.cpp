#include "PumpDesign.hpp"

#include "common/ConfigDocWriter.hpp"

#include <sstream>

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

void PumpDesign::validate(common::ConfigReader &v) const {
  const auto &i = impeller;
  if (i.eye_diameter_m >= i.outer_diameter_m)
    v.fail_value("impeller", "eye_diameter_m = " + std::to_string(i.eye_diameter_m) +
                                 " must be below outer_diameter_m = " + std::to_string(i.outer_diameter_m) + ".");
  if (i.hub_diameter_m >= i.eye_diameter_m)
    v.fail_value("impeller", "hub_diameter_m = " + std::to_string(i.hub_diameter_m) +
                                 " must be below eye_diameter_m = " + std::to_string(i.eye_diameter_m) + ".");
  if (2.0 * i.leading_edge_radius_m > i.blade_thickness_m)
    v.fail_value("impeller", "leading_edge_radius_m must be at most half of blade_thickness_m (the nose is "
                             "the blade's rounded end).");
  if (volute.base_radius_m <= 0.5 * i.outer_diameter_m)
    v.fail_value("volute", "base_radius_m = " + std::to_string(volute.base_radius_m) +
                               " must exceed the impeller radius outer_diameter_m / 2 = " +
                               std::to_string(0.5 * i.outer_diameter_m) + " (the cut-water gap).");
  if (volute.base_width_m < i.outlet_width_m)
    v.fail_value("volute", "base_width_m must be at least the impeller's outlet_width_m.");
  if (volute.section == VoluteSection::rectangular && volute.flank_angle_deg != 0.0)
    v.fail_value("volute", "flank_angle_deg is for a trapezoidal section; a rectangular one has none.");
}

} // namespace fsi::pump
