#pragma once
// A single-channel impeller as one OCC solid in the current gmsh model: the vane is the solid
// between the discs (z in [0, b2], r <= D2 / 2) less the channel lofted through the
// ChannelLayout's sections, fused with the hub disc, the shroud ring around the eye, the
// wear-ring neck below it, a rounded boss nose and the leading edge's round nose (a cylinder
// along the edge where the channel's rising floor meets the vane's underside in the eye, from
// the boss to the eye's rim). The channel runs backwards against the rotation from the leading
// edge, as a backward-swept blade does. Coordinates and region names as ImpellerSolid's
// (docs/pump-design.md). Include only from fsi_pump_geometry.

#include "CadFace.hpp"
#include "ChannelLayout.hpp"
#include "PumpDesign.hpp"

#include <string>
#include <vector>

namespace fsi::pump {

class ChannelImpellerSolid {
public:
  explicit ChannelImpellerSolid(const PumpDesign &design);

  /// Builds the solid in the current gmsh model; returns its volume tag. Throws GeometryError.
  int build();
  /// The region of a face of the built solid (index into ImpellerSolid::region_names()).
  int classify(const CadFace &face) const;

  const ChannelLayout &layout() const { return layout_; }
  /// The angle about z of a point phi along the channel (rad).
  double angle_rad(double phi_rad) const { return -sense_ * phi_rad; }
  /// The leading edge's nose: its axis runs radially at angle_rad(leading_edge_phi_rad()) in the
  /// shroud plane z = 0, from nose_start_radius_m() to nose_end_radius_m().
  double nose_start_radius_m() const;
  double nose_end_radius_m() const;
  /// Volume of the solid by OCC (m^3), and of the channel inside D2 (the block less the vane).
  double cad_volume_m3() const { return cad_volume_m3_; }
  double channel_volume_m3() const { return channel_volume_m3_; }

private:
  int build_vane();
  void build_discs_and_noses(std::vector<std::pair<int, int>> &parts);

  ImpellerDesign impeller_;
  InletDesign inlet_;
  ChannelLayout layout_;
  double sense_;
  double cad_volume_m3_ = 0.0, channel_volume_m3_ = 0.0;
};

} // namespace fsi::pump
