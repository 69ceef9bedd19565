#include "GeometryReport.hpp"

#include "PumpGeometry.hpp"

#include "common/ConfigEmitter.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <stdexcept>

namespace fsi::pump {
namespace {

void vector(YAML::Emitter &out, const char *key, const Vec3 &v) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << v[0] << v[1] << v[2] << YAML::EndSeq;
}

void part(YAML::Emitter &out, const char *key, const char *file, const BuiltPart &built) {
  const RegionSurface &s = built.surface;
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "file" << YAML::Value << file;
  out << YAML::Key << "volume_m3" << YAML::Value << s.enclosed_volume_m3();
  out << YAML::Key << "cad_volume_m3" << YAML::Value << built.cad_volume_m3;
  out << YAML::Key << "triangles" << YAML::Value << s.triangles.size();
  const auto box = s.bounding_box_m();
  out << YAML::Key << "bounding_box_m" << YAML::Value << YAML::BeginMap;
  vector(out, "min", box[0]);
  vector(out, "max", box[1]);
  out << YAML::EndMap;
  out << YAML::Key << "regions" << YAML::Value << YAML::BeginMap;
  for (std::size_t r = 0; r < s.region_names.size(); ++r) {
    std::size_t n = 0;
    for (const int region : s.triangle_regions)
      n += region == static_cast<int>(r);
    if (n == 0)
      continue;
    out << YAML::Key << s.region_names[r] << YAML::Value << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "area_m2" << YAML::Value << s.region_area_m2(static_cast<int>(r));
    out << YAML::Key << "triangles" << YAML::Value << n << YAML::EndMap;
  }
  out << YAML::EndMap << YAML::EndMap;
}

} // namespace

void write_geometry_report(const std::filesystem::path &file, const PumpDesign &design, const PumpGeometry &geometry) {
  YAML::Emitter out;
  out.SetDoublePrecision(8);
  out << YAML::BeginMap;
  out << YAML::Key << "generator" << YAML::Value << "fsi-pump-design --write (gmsh OpenCASCADE)";
  out << YAML::Key << "units" << YAML::Value << "SI (m, m^2, m^3, rad/s, deg)";
  vector(out, "rotation_axis", design.rotation_axis());
  out << YAML::Key << "rotation_rate_rad_per_s" << YAML::Value << design.operation.rotation_rate_rad_per_s;
  out << YAML::Key << "generation_time_s" << YAML::Value << geometry.seconds;
  part(out, "impeller", "impeller.stl", geometry.impeller);
  part(out, "casing", "casing.stl", geometry.casing);
  out << YAML::Key << "cut_water_nose" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "axis_xy_m" << YAML::Value << YAML::Flow << YAML::BeginSeq << geometry.nose_centre_xy_m[0]
      << geometry.nose_centre_xy_m[1] << YAML::EndSeq;
  out << YAML::Key << "radius_m" << YAML::Value << geometry.nose_radius_m << YAML::EndMap;
  if (geometry.channel) {
    const BuiltChannel &c = *geometry.channel;
    out << YAML::Key << "single_channel" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "channel_volume_m3" << YAML::Value << c.channel_volume_m3;
    out << YAML::Key << "leading_edge" << YAML::Value << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "angle_deg" << YAML::Value << c.leading_edge_angle_deg;
    out << YAML::Key << "inner_radius_m" << YAML::Value << c.leading_edge_inner_radius_m;
    out << YAML::Key << "outer_radius_m" << YAML::Value << c.leading_edge_outer_radius_m;
    out << YAML::Key << "nose_radius_m" << YAML::Value << design.impeller.leading_edge_radius_m << YAML::EndMap;
    out << YAML::Key << "exit_area_m2" << YAML::Value << c.exit_area_m2;
    out << YAML::Key << "smallest_section_side_m" << YAML::Value << c.smallest_section_side_m;
    out << YAML::EndMap;
  } else {
    const BladeCamber camber = design.blade_camber();
    out << YAML::Key << "blade" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "design" << YAML::Value << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "wrap_deg" << YAML::Value << design.impeller.wrap_angle_deg;
    out << YAML::Key << "inlet_angle_deg" << YAML::Value << design.impeller.inlet_blade_angle_deg;
    out << YAML::Key << "outlet_angle_deg" << YAML::Value << design.impeller.outlet_blade_angle_deg;
    out << YAML::Key << "cot_beta_curvature_c" << YAML::Value << camber.curvature_coefficient();
    out << YAML::EndMap;
    out << YAML::Key << "as_built" << YAML::Value << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "wrap_deg" << YAML::Value << geometry.blade.wrap_deg;
    out << YAML::Key << "inlet_angle_deg" << YAML::Value << geometry.blade.inlet_angle_deg;
    out << YAML::Key << "outlet_angle_deg" << YAML::Value << geometry.blade.outlet_angle_deg;
    out << YAML::Key << "wrap_on_mesh_deg" << YAML::Value << geometry.blade.wrap_on_mesh_deg;
    out << YAML::EndMap << YAML::EndMap;
  }
  out << YAML::Key << "design" << YAML::Value << YAML::BeginMap;
  PumpDesign inputs = design;
  common::ConfigEmitter emitter(out);
  inputs.visit(emitter);
  out << YAML::EndMap << YAML::EndMap;
  std::ofstream stream(file);
  stream << "# What fsi-pump-design --write built (docs/pump-design.md).\n" << out.c_str() << "\n";
  if (!stream)
    throw std::runtime_error("cannot write " + file.string());
}

} // namespace fsi::pump
