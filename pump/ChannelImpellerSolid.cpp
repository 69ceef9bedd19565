#include "ChannelImpellerSolid.hpp"

#include "GmshSession.hpp"
#include "ImpellerSolid.hpp"

#include <gmsh.h>

#include <cmath>

namespace fsi::pump {
namespace {

constexpr const char *part = "impeller";
enum Region { leading_edge, pressure_side, suction_side, trailing_edge, hub, shroud, eye, blade_tip };
/// The loft's sections are at most this far apart along the wrap.
constexpr double max_section_step_rad = 10.0 * M_PI / 180.0;

int volume_of(const gmsh::vectorpair &entities, const std::string &what) {
  if (entities.size() != 1 || entities.front().first != 3)
    throw GeometryError(std::string(part) + ": " + what + " gave " + std::to_string(entities.size()) +
                        " entities instead of one solid");
  return entities.front().second;
}

} // namespace

ChannelImpellerSolid::ChannelImpellerSolid(const PumpDesign &design)
    : impeller_(design.impeller), inlet_(design.inlet), layout_(design), sense_(design.rotation_sense()) {}

double ChannelImpellerSolid::nose_start_radius_m() const { return 0.3 * layout_.boss_radius_m(); }

double ChannelImpellerSolid::nose_end_radius_m() const {
  return layout_.eye_radius_m() + 0.5 * impeller_.leading_edge_radius_m;
}

int ChannelImpellerSolid::build_vane() {
  namespace occ = gmsh::model::occ;
  std::vector<int> wires;
  for (const ChannelSection &s : layout_.loft_sections(max_section_step_rad)) {
    const double angle = angle_rad(s.phi_rad), c = std::cos(angle), sn = std::sin(angle);
    const double corners[4][2] = {{s.inner_radius_m, s.floor_z_m},
                                  {s.outer_radius_m, s.floor_z_m},
                                  {s.outer_radius_m, s.top_z_m},
                                  {s.inner_radius_m, s.top_z_m}};
    int points[4];
    for (int i = 0; i < 4; ++i)
      points[i] = occ::addPoint(corners[i][0] * c, corners[i][0] * sn, corners[i][1]);
    std::vector<int> lines;
    for (int i = 0; i < 4; ++i)
      lines.push_back(occ::addLine(points[i], points[(i + 1) % 4]));
    wires.push_back(occ::addWire(lines));
  }
  gmsh::vectorpair channel;
  gmsh_step(part, "lofting the channel", [&] { occ::addThruSections(wires, channel, -1, true, false); });
  const double r2 = layout_.outer_radius_m(), b2 = impeller_.outlet_width_m;
  const int block = occ::addCylinder(0, 0, 0, 0, 0, b2, r2);
  gmsh::vectorpair vane;
  gmsh_step(part, "cutting the channel out of the vane", [&] {
    std::vector<gmsh::vectorpair> map;
    occ::cut({{3, block}}, channel, vane, map);
  });
  const int tag = volume_of(vane, "cutting the channel out of the vane");
  double volume = 0.0;
  occ::getMass(3, tag, volume);
  channel_volume_m3_ = M_PI * r2 * r2 * b2 - volume;
  return tag;
}

void ChannelImpellerSolid::build_discs_and_noses(std::vector<std::pair<int, int>> &parts) {
  namespace occ = gmsh::model::occ;
  const double t = impeller_.disc_thickness_m(), b2 = impeller_.outlet_width_m, r2 = layout_.outer_radius_m();
  const double r_eye = layout_.eye_radius_m(), r_boss = layout_.boss_radius_m();
  parts.emplace_back(3, occ::addCylinder(0, 0, b2, 0, 0, t, r2)); // hub disc
  gmsh::vectorpair ring;
  std::vector<gmsh::vectorpair> map;
  const double neck = impeller_.single_channel->neck_length_m;
  occ::cut({{3, occ::addCylinder(0, 0, -t, 0, 0, t, r2)}}, {{3, occ::addCylinder(0, 0, -2 * t, 0, 0, 3 * t, r_eye)}},
           ring, map);
  parts.insert(parts.end(), ring.begin(), ring.end());
  if (neck > 0.0) { // the wear-ring neck: a tube from the shroud down into the suction pipe
    const double outer = 0.5 * inlet_.suction_pipe_diameter_m - impeller_.single_channel->wear_ring_clearance_m;
    gmsh::vectorpair tube;
    occ::cut({{3, occ::addCylinder(0, 0, -t - neck, 0, 0, neck + 0.5 * t, outer)}},
             {{3, occ::addCylinder(0, 0, -t - neck - t, 0, 0, neck + 2 * t, r_eye)}}, tube, map);
    parts.insert(parts.end(), tube.begin(), tube.end());
  }
  // The boss's rounded nose: a sphere a little inside the boss's radius, so that its surface
  // never touches the channel's inner wall (a tangency the booleans cannot take).
  parts.emplace_back(3, occ::addSphere(0, 0, 0.2 * r_boss, 0.98 * r_boss));
  // The leading edge's round nose along the edge, radially in the shroud plane.
  const double angle = angle_rad(layout_.leading_edge_phi_rad());
  const double a = nose_start_radius_m(), b = nose_end_radius_m();
  parts.emplace_back(3, occ::addCylinder(a * std::cos(angle), a * std::sin(angle), 0.0, (b - a) * std::cos(angle),
                                         (b - a) * std::sin(angle), 0.0, impeller_.leading_edge_radius_m));
}

int ChannelImpellerSolid::build() {
  namespace occ = gmsh::model::occ;
  const int vane = gmsh_step(part, "the vane around the channel", [&] { return build_vane(); });
  std::vector<std::pair<int, int>> parts;
  gmsh_step(part, "discs, neck and noses", [&] { build_discs_and_noses(parts); });
  gmsh::vectorpair fused;
  gmsh_step(part, "fusing the vane, discs, neck and noses", [&] {
    std::vector<gmsh::vectorpair> map;
    occ::fuse({{3, vane}}, parts, fused, map);
    occ::synchronize();
  });
  const int tag = volume_of(fused, "fusing the vane, discs, neck and noses");
  gmsh_step(part, "measuring the volume", [&] { occ::getMass(3, tag, cad_volume_m3_); });
  return tag;
}

int ChannelImpellerSolid::classify(const CadFace &face) const {
  constexpr double tol = 1e-5;
  const double b2 = impeller_.outlet_width_m, r2 = layout_.outer_radius_m();
  const double angle = angle_rad(layout_.leading_edge_phi_rad());
  const Vec3 axis(std::cos(angle), std::sin(angle), 0.0);
  const double a = nose_start_radius_m(), b = nose_end_radius_m(), radius = impeller_.leading_edge_radius_m;
  bool near_nose = true;
  for (const Vec3 &p : face.nodes_m) {
    const double along = std::clamp(p.dot(axis), a, b);
    near_nose = near_nose && (p - along * axis).norm() <= radius + tol;
  }
  if (near_nose)
    return leading_edge;
  if (face.lower_m[2] >= b2 - tol)
    return hub;
  if (face.upper_m[2] <= tol)
    return face.max_radius_m <= layout_.eye_radius_m() + tol ? eye : shroud;
  if (face.min_radius_m >= r2 - tol)
    return trailing_edge;
  // The pressure side faces the direction of rotation: its outward normal runs along s e_theta.
  return sense_ * face.swirl_m2 > 0.0 ? pressure_side : suction_side;
}

} // namespace fsi::pump
