#include "PumpGeometry.hpp"

#include "CasingSolid.hpp"
#include "ChannelImpellerSolid.hpp"
#include "GeometryReport.hpp"
#include "GmshSession.hpp"
#include "ImpellerSolid.hpp"

#include <gmsh.h>

#include <chrono>
#include <cmath>

namespace fsi::pump {
namespace {

Eigen::Vector3d curve_value(int curve, double u, bool derivative) {
  std::vector<double> out;
  if (derivative)
    gmsh::model::getDerivative(1, curve, {u}, out);
  else
    gmsh::model::getValue(1, curve, {u}, out);
  return {out[0], out[1], out[2]};
}

/// beta of the curve at parameter u: the angle of its tangent from the circumferential direction.
double beta_deg(int curve, double u) {
  const Eigen::Vector3d p = curve_value(curve, u, false), d = curve_value(curve, u, true);
  const Eigen::Vector2d e_r = Eigen::Vector2d(p[0], p[1]).normalized(), e_theta(-e_r[1], e_r[0]);
  const Eigen::Vector2d tangent(d[0], d[1]);
  return std::atan2(std::abs(tangent.dot(e_r)), std::abs(tangent.dot(e_theta))) * 180.0 / M_PI;
}

AsBuiltBlade measure_camber(int curve) {
  AsBuiltBlade blade;
  std::vector<double> lo, hi;
  gmsh::model::getParametrizationBounds(1, curve, lo, hi);
  const int n = 4000;
  double swept = 0.0, previous = 0.0;
  for (int i = 0; i <= n; ++i) { // unwrapped angle along the curve
    const Eigen::Vector3d p = curve_value(curve, lo[0] + (hi[0] - lo[0]) * i / n, false);
    const double angle = std::atan2(p[1], p[0]);
    if (i > 0)
      swept += std::remainder(angle - previous, 2.0 * M_PI);
    previous = angle;
  }
  blade.wrap_deg = std::abs(swept) * 180.0 / M_PI;
  blade.inlet_angle_deg = beta_deg(curve, lo[0]);
  blade.outlet_angle_deg = beta_deg(curve, hi[0]);
  return blade;
}

/// The angle from the leading-edge centre of blade 1 to the centroid of its trailing edge.
double wrap_on_mesh_deg(const RegionSurface &surface, const ImpellerSolid &solid) {
  const int te = surface.region_index("blade_trailing_edge");
  const double leading = solid.blade_angle_rad(0);
  const double expected = leading + solid.camber().theta_rad(solid.camber().outlet_radius_m());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    if (surface.triangle_regions[t] != te)
      continue;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const int v : surface.triangles[t])
      c += surface.vertices_m[v] / 3.0;
    // blade 1's trailing edge is the one nearest the designed angle
    if (std::abs(std::remainder(std::atan2(c[1], c[0]) - expected, 2.0 * M_PI)) > M_PI / solid.n_blades())
      continue;
    sum += c;
    ++count;
  }
  if (count == 0)
    return 0.0;
  const double trailing = std::atan2(sum[1], sum[0]);
  // unwrap with the design's wrap: the measured angle is the design's plus a small difference
  const double difference = std::remainder(trailing - expected, 2.0 * M_PI);
  return std::abs(expected + difference - leading) * 180.0 / M_PI;
}

} // namespace

PumpGeometry PumpGeometry::build(const PumpDesign &design, const GeometryOptions &options) {
  const auto start = std::chrono::steady_clock::now();
  PumpGeometry geometry;
  GmshSession session;
  session.new_model("impeller");
  const auto mesh_impeller = [&](const auto &solid, int volume) {
    geometry.impeller.surface = mesh_solid("impeller", volume, options.impeller, ImpellerSolid::region_names(),
                                           [&](const CadFace &face) { return solid.classify(face); });
    geometry.impeller.cad_volume_m3 = solid.cad_volume_m3();
  };
  if (design.impeller.single_channel) {
    ChannelImpellerSolid solid(design);
    mesh_impeller(solid, solid.build());
    BuiltChannel channel;
    const ChannelLayout &layout = solid.layout();
    channel.channel_volume_m3 = solid.channel_volume_m3();
    channel.leading_edge_angle_deg = solid.angle_rad(layout.leading_edge_phi_rad()) * 180.0 / M_PI;
    channel.leading_edge_inner_radius_m = layout.boss_radius_m();
    channel.leading_edge_outer_radius_m = layout.eye_radius_m();
    channel.exit_area_m2 = layout.exit_area_m2();
    channel.smallest_section_side_m = layout.smallest_section_side_m();
    geometry.channel = channel;
  } else {
    ImpellerSolid solid(design);
    const int volume = solid.build();
    geometry.blade = gmsh_step("impeller", "measuring the camber line", [&] {
      gmsh::model::occ::synchronize();
      return measure_camber(solid.camber_curve_tag());
    });
    mesh_impeller(solid, volume);
    geometry.blade.wrap_on_mesh_deg = wrap_on_mesh_deg(geometry.impeller.surface, solid);
  }
  {
    session.new_model("casing");
    CasingSolid solid(design);
    const int volume = solid.build();
    geometry.casing.surface = mesh_solid("casing", volume, options.casing, CasingSolid::region_names(),
                                         [&](const CadFace &face) { return solid.classify(face); });
    geometry.casing.cad_volume_m3 = solid.cad_volume_m3();
    geometry.nose_centre_xy_m = solid.nose_centre_xy_m();
    geometry.nose_radius_m = solid.cut_water().nose_radius_m;
  }
  geometry.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return geometry;
}

void PumpGeometry::write(const std::filesystem::path &dir, const PumpDesign &design) const {
  std::filesystem::create_directories(dir);
  impeller.surface.write_ascii_stl(dir / "impeller.stl");
  casing.surface.write_ascii_stl(dir / "casing.stl");
  write_geometry_report(dir / "geometry.yaml", design, *this);
}

} // namespace fsi::pump
