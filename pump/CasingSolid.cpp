#include "CasingSolid.hpp"

#include "GmshSession.hpp"

#include <gmsh.h>

#include <cmath>

namespace fsi::pump {
namespace {

constexpr const char *part = "casing";
enum Region { inlet, suction_wall, volute_wall, nose, discharge_wall, outlet };
constexpr double deg = M_PI / 180.0;
/// The spiral's sections start this far before the cut-water (inside the chamber there).
constexpr double spiral_lead_in_rad = 5.0 * deg;
constexpr double max_section_step_rad = 12.0 * deg;

int add_point(const Eigen::Vector3d &p) { return gmsh::model::occ::addPoint(p[0], p[1], p[2]); }

int polygon_wire(const std::vector<Eigen::Vector3d> &corners) {
  std::vector<int> points, lines;
  for (const auto &c : corners)
    points.push_back(add_point(c));
  for (std::size_t i = 0; i < points.size(); ++i)
    lines.push_back(gmsh::model::occ::addLine(points[i], points[(i + 1) % points.size()]));
  return gmsh::model::occ::addWire(lines);
}

int volume_of(const gmsh::vectorpair &entities) {
  for (const auto &[dim, tag] : entities)
    if (dim == 3)
      return tag;
  throw GeometryError(std::string(part) + ": an operation gave no solid");
}

} // namespace

CasingSolid::CasingSolid(const PumpDesign &design)
    : design_(design), volute_(size_volute(design)), sense_(design.rotation_sense()), r3_(design.volute.base_radius_m) {
  const double b2 = design.impeller.outlet_width_m, b3 = design.volute.base_width_m;
  z_low_ = 0.5 * (b2 - b3);
  z_high_ = 0.5 * (b2 + b3);
  // The duct's inner wall sits a little inside the base circle, so that it cuts the chamber
  // instead of touching it tangentially (the throat grows by this strip, < 1 %).
  inner_v_m_ = r3_ - std::min(0.001, 0.2 * (r3_ - 0.5 * design.impeller.outer_diameter_m));
  cut_water_ = gmsh_step(part, "placing the cut-water", [&] {
    return place_cut_water([this](double phi) { return volute_.outer_radius_m(phi); }, inner_v_m_,
                           design.volute.cut_water_nose_radius_m);
  });
  duct_length_m_ = cut_water_.nose_centre_m[0] + 3.0 * design.volute.cut_water_nose_radius_m;
}

const std::vector<std::string> &CasingSolid::region_names() {
  static const std::vector<std::string> names{"inlet",     "suction_wall",   "volute_wall",
                                              "cut_water", "discharge_wall", "outlet"};
  return names;
}

Eigen::Vector2d CasingSolid::nose_centre_xy_m() const {
  const Eigen::Vector3d p = to_xyz(cut_water_.nose_centre_m[0], cut_water_.nose_centre_m[1], 0.0);
  return {p[0], p[1]};
}

double CasingSolid::outlet_x_m() const {
  const double transition = std::max({volute_.outer_radius_m(2 * M_PI) - inner_v_m_, design_.volute.base_width_m,
                                      design_.volute.discharge_diameter_m});
  return duct_length_m_ + transition + design_.volute.discharge_length_m;
}

double CasingSolid::discharge_axis_y_m() const {
  return -sense_ * 0.5 * (inner_v_m_ + volute_.outer_radius_m(2 * M_PI));
}

CasingSolid::Section CasingSolid::spiral_section(double phi_rad) const {
  const double inner = r3_ - 0.5 * (r3_ - 0.5 * design_.impeller.outer_diameter_m); // overlaps the chamber
  const double outer = volute_.outer_radius_m(phi_rad);
  if (design_.volute.section == VoluteSection::rectangular)
    return {{inner, z_low_}, {outer, z_low_}, {outer, z_high_}, {inner, z_high_}};
  // The flanks open at the flank angle from width b3 at r3; inside the chamber (r < r3) they
  // run on, narrower, so that they cut the chamber's flat walls instead of lying on them.
  const double zc = 0.5 * (z_low_ + z_high_);
  const double inner_half = 0.5 * volute_.width_m(inner), outer_half = 0.5 * volute_.width_m(outer);
  return {{inner, zc - inner_half}, {outer, zc - outer_half}, {outer, zc + outer_half}, {inner, zc + inner_half}};
}

CasingSolid::Section CasingSolid::throat_section(double inner_v_m) const {
  Section section = spiral_section(2 * M_PI);
  const double zc = 0.5 * (z_low_ + z_high_), inner_half = 0.5 * volute_.width_m(inner_v_m);
  section.front() = {inner_v_m, zc - inner_half};
  section.back() = {inner_v_m, zc + inner_half};
  return section;
}

int CasingSolid::spiral_loft(double phi_from_rad, double phi_to_rad) {
  const int n = static_cast<int>(std::ceil((phi_to_rad - phi_from_rad) / max_section_step_rad - 1e-9));
  std::vector<int> wires;
  for (int i = 0; i <= n; ++i) {
    const double phi = phi_from_rad + (phi_to_rad - phi_from_rad) * i / n;
    const double s = i == n && phi_to_rad == 2 * M_PI ? 0.0 : std::sin(phi);
    const double c = i == n && phi_to_rad == 2 * M_PI ? 1.0 : std::cos(phi);
    std::vector<Eigen::Vector3d> corners;
    for (const auto &corner : spiral_section(phi))
      corners.push_back(to_xyz(corner[0] * s, corner[0] * c, corner[1]));
    wires.push_back(polygon_wire(corners));
  }
  gmsh::vectorpair loft;
  gmsh::model::occ::addThruSections(wires, loft, -1, true, false);
  return volume_of(loft);
}

int CasingSolid::discharge() {
  namespace occ = gmsh::model::occ;
  const Section throat = throat_section(inner_v_m_);
  const double transition = outlet_x_m() - duct_length_m_ - design_.volute.discharge_length_m;
  const double v_c = 0.5 * (inner_v_m_ + volute_.outer_radius_m(2 * M_PI)), zc = 0.5 * (z_low_ + z_high_);
  const double radius = 0.5 * design_.volute.discharge_diameter_m;
  std::vector<Eigen::Vector3d> start, end;
  for (const auto &corner : throat) {
    start.push_back(to_xyz(0.0, corner[0], corner[1]));
    end.push_back(to_xyz(duct_length_m_, corner[0], corner[1]));
  }
  // The straight duct: the throat's section pushed along the discharge.
  gmsh::vectorpair duct;
  occ::addThruSections({polygon_wire(start), polygon_wire(end)}, duct, -1, true, true);
  // The loft to the circle: as many arcs as the section has corners, at the corners' angles.
  const double x_circle = duct_length_m_ + transition;
  const int centre = add_point(to_xyz(x_circle, v_c, zc));
  std::vector<int> arc_points, arcs;
  for (const auto &corner : throat) {
    const double angle = std::atan2(corner[1] - zc, corner[0] - v_c);
    arc_points.push_back(add_point(to_xyz(x_circle, v_c + radius * std::cos(angle), zc + radius * std::sin(angle))));
  }
  for (std::size_t i = 0; i < arc_points.size(); ++i)
    arcs.push_back(occ::addCircleArc(arc_points[i], centre, arc_points[(i + 1) % arc_points.size()]));
  gmsh::vectorpair transition_loft;
  occ::addThruSections({polygon_wire(end), occ::addWire(arcs)}, transition_loft, -1, true, false);
  const Eigen::Vector3d axis_start = to_xyz(x_circle, v_c, zc);
  const int pipe =
      occ::addCylinder(axis_start[0], axis_start[1], axis_start[2], design_.volute.discharge_length_m, 0, 0, radius);
  gmsh::vectorpair fused;
  std::vector<gmsh::vectorpair> map;
  occ::fuse({{3, volume_of(duct)}}, {{3, volume_of(transition_loft)}, {3, pipe}}, fused, map);
  return volume_of(fused);
}

int CasingSolid::tongue_filler() {
  namespace occ = gmsh::model::occ;
  const CutWater &cw = cut_water_;
  const double rn = cw.nose_radius_m, margin = 0.5 * rn;
  const Eigen::Vector2d c = cw.nose_centre_m;
  const Eigen::Vector2d to_wall = (cw.wall_contact_m - c).normalized();
  const double u_lo = 0.5 * cw.crossing_m[0];
  const Eigen::Vector2d p1(u_lo, inner_v_m_ + margin), p2(c[0], inner_v_m_ + margin), top(c[0], c[1] + rn);
  const Eigen::Vector2d beside = c + rn * to_wall, inside = c + (rn + margin) * to_wall;
  const Eigen::Vector2d bottom(u_lo, std::min(inside[1], inner_v_m_ - 2.0 * rn));
  auto point = [&](const Eigen::Vector2d &p) { return add_point(to_xyz(p[0], p[1], z_low_)); };
  const int a = point(p1), b = point(p2), t = point(top), centre = point(c), s = point(beside), i = point(inside),
            d = point(bottom);
  const int loop = occ::addCurveLoop({occ::addLine(a, b), occ::addLine(b, t), occ::addCircleArc(t, centre, s),
                                      occ::addLine(s, i), occ::addLine(i, d), occ::addLine(d, a)});
  gmsh::vectorpair extruded;
  occ::extrude({{2, occ::addPlaneSurface({loop})}}, 0, 0, z_high_ - z_low_, extruded);
  return volume_of(extruded);
}

int CasingSolid::build() {
  namespace occ = gmsh::model::occ;
  std::vector<std::pair<std::string, int>> parts;
  const int chamber =
      gmsh_step(part, "impeller chamber", [&] { return occ::addCylinder(0, 0, z_low_, 0, 0, z_high_ - z_low_, r3_); });
  gmsh_step(part, "suction pipe", [&] {
    const double length = design_.inlet.suction_pipe_length_m, overlap = 0.25 * (z_high_ - z_low_);
    parts.emplace_back("suction pipe", occ::addCylinder(0, 0, z_low_ - length, 0, 0, length + overlap,
                                                        0.5 * design_.inlet.suction_pipe_diameter_m));
  });
  if (design_.inlet.has_sump())
    gmsh_step(part, "inlet sump", [&] {
      // Its top overlaps the pipe's foot, so that the fuse cuts a clean circle in the sump's roof.
      const double top = z_low_ - design_.inlet.suction_pipe_length_m, overlap = 0.002;
      const double bottom = top - design_.inlet.sump_height_m;
      parts.emplace_back("inlet sump",
                         occ::addCylinder(0, 0, bottom, 0, 0, top + overlap - bottom, 0.5 * design_.inlet.sump_diameter_m));
    });
  gmsh_step(part, "spiral volute (lofts through its sections)", [&] {
    parts.emplace_back("spiral's first half", spiral_loft(-spiral_lead_in_rad, M_PI));
    parts.emplace_back("spiral's second half", spiral_loft(M_PI, 2 * M_PI));
  });
  gmsh_step(part, "discharge duct", [&] { parts.emplace_back("discharge duct", discharge()); });
  gmsh_step(part, "cut-water nose", [&] { parts.emplace_back("cut-water's filled tip", tongue_filler()); });
  // One part at a time: a failure names the part, and small booleans are the robust ones.
  int body = chamber;
  for (const auto &[name, tag] : parts)
    body = gmsh_step(part, "fusing the " + name + " with the rest", [&, tag = tag, name = name] {
      gmsh::vectorpair fused;
      std::vector<gmsh::vectorpair> map;
      occ::fuse({{3, body}}, {{3, tag}}, fused, map);
      if (fused.size() != 1)
        throw GeometryError(std::string(part) + ": fusing the " + name + " gave " + std::to_string(fused.size()) +
                            " solids instead of one");
      return fused.front().second;
    });
  gmsh_step(part, "synchronizing", [&] { occ::synchronize(); });
  gmsh::vectorpair fused{{3, body}};
  gmsh_step(part, "measuring the volume", [&] { occ::getMass(3, fused.front().second, cad_volume_m3_); });
  return fused.front().second;
}

int CasingSolid::classify(const CadFace &face) const {
  constexpr double tol = 1e-5;
  const double suction_bottom = z_low_ - design_.inlet.suction_pipe_length_m - design_.inlet.sump_height_m;
  if (face.upper_m[2] <= suction_bottom + tol)
    return inlet;
  if (face.lower_m[0] >= outlet_x_m() - tol)
    return outlet;
  // The suction pipe's wall, and the sump's wall and roof.
  const double suction_radius =
      0.5 * std::max(design_.inlet.suction_pipe_diameter_m, design_.inlet.sump_diameter_m);
  if (face.upper_m[2] <= z_low_ + tol && face.lower_m[2] < z_low_ - tol && face.max_radius_m <= suction_radius + tol)
    return suction_wall;
  const Eigen::Vector2d nose_xy = nose_centre_xy_m();
  bool on_nose = face.surface_type != "Plane";
  for (const auto &p : face.nodes_m)
    on_nose = on_nose && std::hypot(p[0] - nose_xy[0], p[1] - nose_xy[1]) <= cut_water_.nose_radius_m + tol;
  if (on_nose)
    return nose;
  // Downstream of the throat plane x = 0, on the duct's side of its inner wall (or past the
  // straight duct): the discharge.
  bool discharge = face.lower_m[0] >= -tol;
  for (const auto &p : face.nodes_m)
    discharge = discharge && (-sense_ * p[1] >= inner_v_m_ - tol || p[0] >= duct_length_m_ - tol);
  return discharge ? discharge_wall : volute_wall;
}

} // namespace fsi::pump
