#pragma once
// The impeller as one OCC solid in the current gmsh model: hub disc, shroud disc (closed
// impellers), hub boss and n_blades blades, each blade the extrusion of its BladeProfile
// across the channel and a little into the discs, trimmed on r2 and fused (rounded leading
// edge: a semicircle, or a circular bulb when leading_edge_radius_m > t / 2). Coordinates of
// docs/pump-design.md: axis z, channel z in [0, b2], shroud below, hub disc above. Include only
// from fsi_pump_geometry.

#include "BladeProfile.hpp"
#include "CadFace.hpp"
#include "PumpDesign.hpp"

#include <string>
#include <vector>

namespace fsi::pump {

class ImpellerSolid {
public:
  explicit ImpellerSolid(const PumpDesign &design);

  /// Builds the solid in the current gmsh model; returns its volume tag. Throws GeometryError.
  int build();
  /// The region of a face of the built solid (index into region_names()).
  int classify(const CadFace &face) const;
  static const std::vector<std::string> &region_names();

  /// The leading-edge angle of blade k (rad about z).
  double blade_angle_rad(int blade) const;
  int n_blades() const { return impeller_.n_blades; }
  const BladeCamber &camber() const { return camber_; }
  /// The tags of the blade-1 camber curve, kept in the model for measurement (gmsh curve tag).
  int camber_curve_tag() const { return camber_curve_; }
  /// Volume of the solid by OCC (m^3).
  double cad_volume_m3() const { return cad_volume_m3_; }

private:
  int build_blade(int blade);
  int build_discs_and_boss(std::vector<std::pair<int, int>> &parts);

  ImpellerDesign impeller_;
  BladeCamber camber_;
  double sense_;
  int camber_curve_ = -1;
  double cad_volume_m3_ = 0.0;
};

} // namespace fsi::pump
