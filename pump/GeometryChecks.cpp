#include "pump/GeometryChecks.hpp"

#include "pump/DutyEstimate.hpp"
#include "pump/VoluteSizing.hpp"
#include "geometry/FreePassage.hpp"
#include "geometry/MeshErrors.hpp"
#include "geometry/PlaneSection.hpp"
#include "geometry/StlIo.hpp"
#include "geometry/TriangleMeshSurface.hpp"
#include "geometry/TriangleSoupChecks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>

namespace fsi::pump {
namespace {

using geometry::RegionSoup;
using geometry::TriangleMeshSurface;
using FluidSide = TriangleMeshSurface::FluidSide;

/// One of the two files being checked.
struct Part {
  std::string what; ///< "impeller" or "casing"
  std::string file;
  RegionSoup mesh; ///< in metres
};

std::string point_text(const Vec3 &p) { return fmt::format("({:.4g}, {:.4g}, {:.4g}) m", p.x(), p.y(), p.z()); }

Vec3 vertex(const Part &part, Eigen::Index v) { return part.mesh.soup.vertices_m.row(v).transpose(); }

/// The region of the first triangle using both vertices (for the messages).
std::string region_near(const Part &part, int a, int b) {
  const auto &triangles = part.mesh.soup.triangles;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const auto row = triangles.row(t);
    if ((row.array() == a).any() && (row.array() == b).any())
      return part.mesh.region_name_of(t).empty() ? "" : " (region '" + part.mesh.region_name_of(t) + "')";
  }
  return "";
}

bool check_closed(GeometryCheckReport &report, const Part &part) {
  const auto open = geometry::border_edges(part.mesh.soup.triangles);
  if (open.empty()) {
    report.add(part.what + " closed", CheckStatus::pass, "0 open edges");
    return true;
  }
  const Vec3 at = 0.5 * (vertex(part, open[0][0]) + vertex(part, open[0][1]));
  report.add(part.what + " closed", CheckStatus::fail, fmt::format("{} open edges", open.size()),
             fmt::format("{}: the {} surface is not closed: {} open edge(s), one at {}{}; close the holes (in the "
                         "generator, or in MeshLab) so that the surface encloses a volume.",
                         part.file, part.what, open.size(), point_text(at), region_near(part, open[0][0], open[0][1])));
  return false;
}

bool check_orientation(GeometryCheckReport &report, const Part &part) {
  const std::string name = part.what + " orientation";
  const std::size_t n_misoriented = geometry::count_misoriented_edges(part.mesh.soup.triangles);
  if (n_misoriented > 0) {
    report.add(name, CheckStatus::fail, fmt::format("{} misoriented edges", n_misoriented),
               fmt::format("{}: the {} facets are not consistently oriented: at {} edge(s) neighbouring facets "
                           "disagree on which side is outside; orient them coherently (MeshLab: 'Re-Orient all "
                           "faces coherently') so every facet's normal points out of the solid.",
                           part.file, part.what, n_misoriented));
    return false;
  }
  const double volume_m3 = geometry::signed_volume_m3(part.mesh.soup);
  if (volume_m3 < 0.0) {
    report.add(name, CheckStatus::fail, fmt::format("inward (volume {:.4g} m^3)", volume_m3),
               fmt::format("{}: the {} normals point inward (enclosed volume {:.4g} m^3 < 0): flip the facets "
                           "(reverse the vertex order of every facet) so the normals point out of the solid.",
                           part.file, part.what, volume_m3));
    return false;
  }
  report.add(name, CheckStatus::pass, "outward");
  return true;
}

/// Advice on the unit a file seems to be in, from the unit scale that would make it fit.
std::string unit_advice(double suggested_scale) {
  struct Unit {
    double scale;
    const char *name;
  };
  static const Unit units[] = {{1.0, "metres"}, {1e-3, "millimetres"}, {1e-2, "centimetres"}, {0.0254, "inches"}};
  for (const Unit &unit : units) {
    if (std::abs(std::log(suggested_scale / unit.scale)) < std::log(1.15))
      return fmt::format("it looks like {}: set unit scale {:g} (--unit-scale {:g})", unit.name, unit.scale,
                         unit.scale);
  }
  return fmt::format("no common unit fits (a unit scale of {:.3g} would): check the file against the design",
                     suggested_scale);
}

bool check_units(GeometryCheckReport &report, const Part &impeller, const PumpGeometryFrame &frame,
                 const GeometryCheckLimits &limits) {
  const auto &v = impeller.mesh.soup.vertices_m;
  const double radius_m = v.leftCols<2>().rowwise().norm().maxCoeff();
  const double ratio = radius_m / frame.impeller_radius_m;
  const std::string value = fmt::format("radius {:.4g} m, D2/2 {:.4g} m", radius_m, frame.impeller_radius_m);
  if (std::abs(ratio - 1.0) <= limits.radius_tolerance) {
    report.add("units", CheckStatus::pass, value);
    return true;
  }
  report.add("units", CheckStatus::fail, value,
             fmt::format("{}: the impeller's outer radius is {:.4g} m with unit scale {:g}, but the design's D2 / 2 "
                         "is {:.4g} m (a factor {:.4g}); {}.",
                         impeller.file, radius_m, report.unit_scale, frame.impeller_radius_m, ratio,
                         unit_advice(report.unit_scale / ratio)));
  return false;
}

std::unique_ptr<TriangleMeshSurface> build_surface(GeometryCheckReport &report, const Part &part, FluidSide side) {
  try {
    auto surface =
        TriangleMeshSurface::from_triangles(part.mesh.soup.vertices_m, part.mesh.soup.triangles, side, part.file);
    const double volume_m3 = surface->enclosed_volume_m3();
    (part.what == "impeller" ? report.impeller_volume_m3 : report.casing_volume_m3) = volume_m3;
    report.add(part.what + " volume", CheckStatus::pass, fmt::format("{:.5g} m^3", volume_m3));
    return surface;
  } catch (const geometry::MeshError &error) {
    report.add(part.what + " volume", CheckStatus::fail, "unusable mesh", error.what());
    return nullptr;
  }
}

/// The impeller inside the casing, then the smallest gap between them: every impeller vertex
/// against the casing, and the casing's vertices near the impeller against the impeller.
void check_inside_and_gap(GeometryCheckReport &report, const Part &impeller,
                          const TriangleMeshSurface &impeller_surface, const Part &casing,
                          const TriangleMeshSurface &casing_surface, const GeometryCheckLimits &limits) {
  std::size_t n_outside = 0;
  double worst_m = std::numeric_limits<double>::infinity();
  Vec3 worst_point = Vec3::Zero();
  Eigen::AlignedBox3d impeller_box;
  for (Eigen::Index v = 0; v < impeller.mesh.soup.vertices_m.rows(); ++v) {
    const Vec3 p = vertex(impeller, v);
    impeller_box.extend(p);
    const double gap_m = casing_surface.distance(p).signed_distance_m; // > 0 inside the fluid domain
    n_outside += gap_m < 0.0 ? 1 : 0;
    if (gap_m < worst_m)
      std::tie(worst_m, worst_point) = std::make_pair(gap_m, p);
  }
  if (n_outside > 0) {
    report.add("impeller inside casing", CheckStatus::fail, fmt::format("{} vertices outside", n_outside),
               fmt::format("{}: {} impeller vertices lie outside the casing '{}', the farthest {:.3g} mm out at {}; "
                           "move or shrink the impeller, or widen the casing.",
                           impeller.file, n_outside, casing.file, -1e3 * worst_m, point_text(worst_point)));
    report.add("impeller-casing gap", CheckStatus::skipped, "needs the impeller inside");
    return;
  }
  report.add("impeller inside casing", CheckStatus::pass, "all vertices inside");
  for (Eigen::Index v = 0; v < casing.mesh.soup.vertices_m.rows(); ++v) {
    const Vec3 p = vertex(casing, v);
    if (impeller_box.exteriorDistance(p) >= worst_m)
      continue;
    const double gap_m = impeller_surface.distance(p).signed_distance_m;
    if (gap_m < worst_m)
      std::tie(worst_m, worst_point) = std::make_pair(gap_m, p);
  }
  report.min_clearance_m = worst_m;
  report.closest_point_m = worst_point;
  const std::string value = fmt::format("{:.3g} mm at {}", 1e3 * worst_m, point_text(worst_point));
  if (worst_m >= limits.min_clearance_m) {
    report.add("impeller-casing gap", CheckStatus::pass, value);
    return;
  }
  report.add("impeller-casing gap", CheckStatus::fail, value,
             fmt::format("{}: the impeller touches the casing '{}': the surfaces are {:.3g} mm apart at {}, below "
                         "the {:.3g} mm a running clearance needs; open the gap there.",
                         impeller.file, casing.file, 1e3 * worst_m, point_text(worst_point),
                         1e3 * limits.min_clearance_m));
}

void measure_throat(GeometryCheckReport &report, const Part &casing, const PumpGeometryFrame &frame) {
  const Vec3 radial(std::cos(frame.cut_water_angle_rad), std::sin(frame.cut_water_angle_rad), 0.0);
  const geometry::PlaneSection section =
      geometry::plane_section(casing.mesh.soup, {Vec3::Zero(), Vec3::UnitZ().cross(radial)},
                              geometry::HalfPlaneLimit{frame.volute_base_radius_m * radial, radial});
  report.throat_area_m2 = section.area_m2;
  report.design_throat_area_m2 = frame.design_throat_area_m2;
  report.throat_band_min_m2 = frame.throat_band_min_m2;
  report.throat_band_max_m2 = frame.throat_band_max_m2;
  const double angle_deg = frame.cut_water_angle_rad * 180.0 / M_PI;
  const std::string value =
      fmt::format("{:.4g} cm^2 (band {:.4g}-{:.4g}, design rule {:.4g})", 1e4 * section.area_m2,
                  1e4 * frame.throat_band_min_m2, 1e4 * frame.throat_band_max_m2, 1e4 * frame.design_throat_area_m2);
  if (!(section.area_m2 > 0.0)) {
    report.add("volute throat", CheckStatus::fail, value,
               fmt::format("{}: the half-plane at the cut-water angle {:g} deg does not cut the casing beyond r3 = "
                           "{:.4g} m; check the cut-water angle and the volute's base radius.",
                           casing.file, angle_deg, frame.volute_base_radius_m));
    return;
  }
  if (section.area_m2 < frame.throat_band_min_m2 || section.area_m2 > frame.throat_band_max_m2) {
    report.add("volute throat", CheckStatus::fail, value,
               fmt::format("{}: the volute's throat (the section at the cut-water angle {:g} deg beyond r3 = {:.4g} "
                           "m) is {:.4g} cm^2, outside the design rules' {:.4g}-{:.4g} cm^2 for this duty (the "
                           "constant-angular-momentum rule gives {:.4g} cm^2); check the spiral's outer radius.",
                           casing.file, angle_deg, frame.volute_base_radius_m, 1e4 * section.area_m2,
                           1e4 * frame.throat_band_min_m2, 1e4 * frame.throat_band_max_m2,
                           1e4 * frame.design_throat_area_m2));
    return;
  }
  report.add("volute throat", CheckStatus::pass, value);
}

/// Where the largest sphere's centre may go: the channel 0 <= z <= b2 out to just past R2,
/// and the eye r < R_eye below it down to t + R_eye under the shroud's top; it starts at
/// the eye's bottom and ends at r >= R2.
geometry::PassageRegion channel_region(const PumpGeometryFrame &frame, double h) {
  const double r2 = frame.impeller_radius_m, eye = frame.eye_radius_m, b2 = frame.outlet_width_m;
  const double bottom = -(frame.disc_thickness_m + eye);
  const auto r = [](const Vec3 &p) { return std::hypot(p.x(), p.y()); };
  return {Eigen::AlignedBox3d(Vec3(-r2 - 2 * h, -r2 - 2 * h, bottom), Vec3(r2 + 2 * h, r2 + 2 * h, b2)),
          [=](const Vec3 &p) { return (p.z() >= 0.0 && r(p) <= r2 + 1.5 * h) || (p.z() < 0.0 && r(p) < eye); },
          [=](const Vec3 &p) { return p.z() < bottom + 0.5 * h; }, [=](const Vec3 &p) { return r(p) >= r2; }};
}

void measure_free_passage(GeometryCheckReport &report, const Part &impeller, const TriangleMeshSurface &surface,
                          const PumpGeometryFrame &frame, const GeometryCheckLimits &limits) {
  const geometry::FreePassage passage =
      geometry::find_free_passage(surface, channel_region(frame, limits.passage_spacing_m), limits.passage_spacing_m);
  if (passage.status != geometry::FreePassage::Status::passes) {
    report.add("free passage", CheckStatus::fail, geometry::FreePassage::status_name(passage.status),
               fmt::format("{}: no sphere passes through the impeller's channel from the eye (r < {:.4g} m) to r = "
                           "{:.4g} m between z = 0 and b2 = {:.4g} m ({}); check that the channel between shroud and "
                           "hub is open and the design's D1, D2 and b2 match the file.",
                           impeller.file, frame.eye_radius_m, frame.impeller_radius_m, frame.outlet_width_m,
                           geometry::FreePassage::status_name(passage.status)));
    return;
  }
  report.free_passage_m = passage.diameter_m;
  report.free_passage_error_m = passage.error_bound_m;
  report.bottleneck_m = passage.bottleneck_m;
  report.add("free passage", CheckStatus::pass,
             fmt::format("{:.1f} mm (+-{:.1f}), stuck at {}", 1e3 * passage.diameter_m, 1e3 * passage.error_bound_m,
                         point_text(passage.bottleneck_m)));
}

Part scaled(const std::string &what, const std::string &file, const RegionSoup &mesh, double scale) {
  Part part{what, file, mesh};
  part.mesh.soup.vertices_m *= scale;
  return part;
}

void skip(GeometryCheckReport &report, const std::vector<std::string> &names, const std::string &why) {
  for (const std::string &name : names)
    report.add(name, CheckStatus::skipped, why);
}

} // namespace

PumpGeometryFrame PumpGeometryFrame::from_design(const PumpDesign &design) {
  const auto &imp = design.impeller;
  const VoluteSizing volute = size_volute(design);
  PumpGeometryFrame frame;
  frame.impeller_radius_m = 0.5 * imp.outer_diameter_m;
  frame.eye_radius_m = 0.5 * imp.eye_diameter_m;
  frame.outlet_width_m = imp.outlet_width_m;
  frame.disc_thickness_m = imp.disc_thickness_m();
  frame.volute_base_radius_m = design.volute.base_radius_m;
  // The generator's throat (CasingSolid: the spiral's 360 deg section) lies in the half-plane
  // x = 0 on the side -sense y: +y for rotation about -z, -y about +z.
  frame.cut_water_angle_rad = -design.rotation_sense() * M_PI / 2;
  frame.design_throat_area_m2 = volute.throat_area_m2();
  const ThroatBand band = throat_band(design);
  frame.throat_band_min_m2 = band.min_area_m2;
  frame.throat_band_max_m2 = band.max_area_m2;
  return frame;
}

GeometryChecks::GeometryChecks(const PumpGeometryFrame &frame, const GeometryCheckLimits &limits)
    : frame_(frame), limits_(limits) {}

GeometryCheckReport GeometryChecks::run(const std::string &impeller_stl, const std::string &casing_stl) const {
  return run(geometry::read_stl_regions(impeller_stl), impeller_stl, geometry::read_stl_regions(casing_stl),
             casing_stl);
}

GeometryCheckReport GeometryChecks::run(const RegionSoup &impeller_mesh, const std::string &impeller_name,
                                        const RegionSoup &casing_mesh, const std::string &casing_name) const {
  GeometryCheckReport report;
  report.impeller_file = impeller_name;
  report.casing_file = casing_name;
  report.unit_scale = limits_.unit_scale;
  const Part impeller = scaled("impeller", impeller_name, impeller_mesh, limits_.unit_scale);
  const Part casing = scaled("casing", casing_name, casing_mesh, limits_.unit_scale);
  bool usable = true;
  for (const Part *part : {&impeller, &casing}) {
    if (check_closed(report, *part))
      usable = check_orientation(report, *part) && usable;
    else
      usable = false;
  }
  usable = check_units(report, impeller, frame_, limits_) && usable;
  const std::vector<std::string> together = {"impeller inside casing", "impeller-casing gap", "volute throat",
                                             "free passage"};
  if (!usable) {
    skip(report, together, "needs closed, outward meshes in the design's units");
    return report;
  }
  const auto impeller_surface = build_surface(report, impeller, FluidSide::outside);
  const auto casing_surface = build_surface(report, casing, FluidSide::inside);
  if (!impeller_surface || !casing_surface) {
    skip(report, together, "needs usable meshes");
    return report;
  }
  check_inside_and_gap(report, impeller, *impeller_surface, casing, *casing_surface, limits_);
  measure_throat(report, casing, frame_);
  measure_free_passage(report, impeller, *impeller_surface, frame_, limits_);
  return report;
}

} // namespace fsi::pump
