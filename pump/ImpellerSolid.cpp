#include "ImpellerSolid.hpp"

#include "GmshSession.hpp"

#include <gmsh.h>

#include <cmath>

namespace fsi::pump {
namespace {

constexpr const char *part = "impeller";
enum Region { leading_edge, pressure_side, suction_side, trailing_edge, hub, shroud, eye, blade_tip };

int add_point(const Eigen::Vector2d &p, double z) { return gmsh::model::occ::addPoint(p[0], p[1], z); }

int add_spline(const std::vector<Eigen::Vector2d> &points, double z, bool reversed) {
  std::vector<int> tags;
  for (const auto &p : points)
    tags.push_back(add_point(p, z));
  if (reversed)
    std::reverse(tags.begin(), tags.end());
  return gmsh::model::occ::addSpline(tags);
}

} // namespace

ImpellerSolid::ImpellerSolid(const PumpDesign &design)
    : impeller_(design.impeller), camber_(design.blade_camber()), sense_(design.rotation_sense()) {}

const std::vector<std::string> &ImpellerSolid::region_names() {
  static const std::vector<std::string> names{
      "blade_leading_edge", "blade_pressure_side", "blade_suction_side", "blade_trailing_edge", "hub", "shroud", "eye",
      "blade_tip"};
  return names;
}

double ImpellerSolid::blade_angle_rad(int blade) const { return 2.0 * M_PI * blade / impeller_.n_blades; }

int ImpellerSolid::build_blade(int blade) {
  namespace occ = gmsh::model::occ;
  const double t = impeller_.blade_thickness_m, b2 = impeller_.outlet_width_m;
  const double z0 = impeller_.closed ? -0.5 * t : 0.0, z1 = b2 + 0.5 * t;
  const BladeProfile profile = make_blade_profile(camber_, blade_angle_rad(blade), t, 1.5 * t, 60);
  // The closed section: left side outwards, across the end, right side back, and the
  // semicircular nose in two quarter arcs around the leading-edge centre.
  const int left = add_spline(profile.left_m, z0, false);
  const int right = add_spline(profile.right_m, z0, true);
  const int left_end = add_point(profile.left_m.back(), z0), right_end = add_point(profile.right_m.back(), z0);
  const int across = occ::addLine(left_end, right_end);
  const int centre = add_point(profile.leading_edge_centre_m, z0), tip = add_point(profile.leading_edge_tip_m, z0);
  const int right_start = add_point(profile.right_m.front(), z0), left_start = add_point(profile.left_m.front(), z0);
  const int nose_right = occ::addCircleArc(right_start, centre, tip);
  const int nose_left = occ::addCircleArc(tip, centre, left_start);
  const int loop = occ::addCurveLoop({left, across, right, nose_right, nose_left});
  const int section = occ::addPlaneSurface({loop});
  gmsh::vectorpair extruded;
  occ::extrude({{2, section}}, 0.0, 0.0, z1 - z0, extruded);
  int volume = -1;
  for (const auto &[dim, tag] : extruded)
    if (dim == 3)
      volume = tag;
  if (blade == 0) { // the camber line itself, mid-channel, for the as-built angles
    std::vector<Eigen::Vector2d> inside(profile.camber_m.begin(), profile.camber_m.begin() + profile.n_inside);
    camber_curve_ = add_spline(inside, 0.5 * b2, false);
  }
  gmsh::vectorpair trimmed;
  std::vector<gmsh::vectorpair> map;
  const int outer = occ::addCylinder(0, 0, z0 - t, 0, 0, z1 - z0 + 2 * t, 0.5 * impeller_.outer_diameter_m);
  occ::intersect({{3, volume}}, {{3, outer}}, trimmed, map);
  if (trimmed.size() != 1)
    throw GeometryError(std::string(part) + ": trimming blade " + std::to_string(blade + 1) + " on r2 gave " +
                        std::to_string(trimmed.size()) + " pieces");
  return trimmed.front().second;
}

int ImpellerSolid::build_discs_and_boss(std::vector<std::pair<int, int>> &parts) {
  namespace occ = gmsh::model::occ;
  const double t = impeller_.blade_thickness_m, b2 = impeller_.outlet_width_m, r2 = 0.5 * impeller_.outer_diameter_m;
  const int hub_disc = occ::addCylinder(0, 0, b2, 0, 0, t, r2);
  if (impeller_.closed) {
    const int disc = occ::addCylinder(0, 0, -t, 0, 0, t, r2);
    const int hole = occ::addCylinder(0, 0, -2 * t, 0, 0, 3 * t, 0.5 * impeller_.eye_diameter_m);
    gmsh::vectorpair ring;
    std::vector<gmsh::vectorpair> map;
    occ::cut({{3, disc}}, {{3, hole}}, ring, map);
    parts.insert(parts.end(), ring.begin(), ring.end());
  }
  if (impeller_.hub_diameter_m > 0.0) {
    const double nose_z = -PumpDesign::hub_nose_depth * b2;
    parts.emplace_back(3, occ::addCylinder(0, 0, nose_z, 0, 0, b2 + 0.5 * t - nose_z, 0.5 * impeller_.hub_diameter_m));
  }
  return hub_disc;
}

int ImpellerSolid::build() {
  namespace occ = gmsh::model::occ;
  std::vector<std::pair<int, int>> parts;
  for (int blade = 0; blade < impeller_.n_blades; ++blade) {
    parts.emplace_back(3, gmsh_step(part, "blade " + std::to_string(blade + 1), [&] { return build_blade(blade); }));
    if (impeller_.leading_edge_radius_m > 0.5 * impeller_.blade_thickness_m * (1.0 + 1e-9)) {
      const Eigen::Vector2d c = camber_point(camber_, blade_angle_rad(blade), camber_.inlet_radius_m());
      const double t = impeller_.blade_thickness_m, z0 = impeller_.closed ? -0.5 * t : 0.0;
      parts.emplace_back(3, occ::addCylinder(c[0], c[1], z0, 0, 0, impeller_.outlet_width_m + 0.5 * t - z0,
                                             impeller_.leading_edge_radius_m));
    }
  }
  const int hub_disc = gmsh_step(part, "discs and boss", [&] { return build_discs_and_boss(parts); });
  gmsh::vectorpair fused;
  gmsh_step(part, "fusing blades, discs and boss", [&] {
    std::vector<gmsh::vectorpair> map;
    occ::fuse({{3, hub_disc}}, parts, fused, map);
    occ::synchronize();
  });
  if (fused.size() != 1)
    throw GeometryError(std::string(part) + ": the fused blades, discs and boss form " + std::to_string(fused.size()) +
                        " solids instead of one");
  gmsh_step(part, "measuring the volume", [&] { occ::getMass(3, fused.front().second, cad_volume_m3_); });
  return fused.front().second;
}

int ImpellerSolid::classify(const CadFace &face) const {
  constexpr double tol = 1e-5;
  const double b2 = impeller_.outlet_width_m, r2 = 0.5 * impeller_.outer_diameter_m;
  if (face.lower_m[2] >= b2 - tol)
    return hub;
  if (face.upper_m[2] <= tol) {
    if (face.max_radius_m <= 0.5 * impeller_.eye_diameter_m + tol) {
      // Flat, across the axis, in the eye outside the boss: a blade's bottom edge (it reaches
      // below the shroud plane), the edge the axial inflow and a rising rag meet crosswise: its
      // leading edge as much as the nose.
      if (face.upper_m[2] - face.lower_m[2] <= tol && face.min_radius_m > 0.5 * impeller_.hub_diameter_m + tol)
        return leading_edge;
      return eye; // the shroud's inner rim, the boss's nose
    }
    return impeller_.closed ? shroud : blade_tip;
  }
  if (face.max_radius_m <= 0.5 * impeller_.hub_diameter_m + tol)
    return eye; // the boss
  if (face.min_radius_m >= r2 - tol)
    return trailing_edge;
  const double nose_radius = std::max(impeller_.leading_edge_radius_m, 0.5 * impeller_.blade_thickness_m);
  for (int blade = 0; blade < impeller_.n_blades; ++blade) {
    const Eigen::Vector2d c = camber_point(camber_, blade_angle_rad(blade), camber_.inlet_radius_m());
    bool near_nose = true;
    for (const auto &p : face.nodes_m)
      near_nose = near_nose && std::hypot(p[0] - c[0], p[1] - c[1]) <= nose_radius + tol;
    if (near_nose)
      return leading_edge;
  }
  // The pressure side faces the direction of rotation: its outward normal runs along s e_theta.
  return sense_ * face.swirl_m2 > 0.0 ? pressure_side : suction_side;
}

} // namespace fsi::pump
