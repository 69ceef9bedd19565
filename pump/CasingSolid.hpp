#pragma once
// The casing's fluid domain as one OCC solid in the current gmsh model: suction pipe,
// impeller chamber (r <= r3), spiral volute (two lofts through sections every <= 12 deg, from
// just before the cut-water to the throat at 360 deg), the tongue's filled tip with its round
// nose (CutWater), and the discharge: a straight duct of the throat's section leaving
// tangentially in the direction of rotation, a loft to the discharge circle and a straight
// pipe. Coordinates of docs/pump-design.md. Include only from fsi_pump_geometry.

#include "CadFace.hpp"
#include "CutWater.hpp"
#include "PumpDesign.hpp"
#include "VoluteSizing.hpp"

#include <string>
#include <vector>

namespace fsi::pump {

class CasingSolid {
public:
  explicit CasingSolid(const PumpDesign &design);

  /// Builds the solid in the current gmsh model; returns its volume tag. Throws GeometryError.
  int build();
  /// The region of a face of the built solid (index into region_names()).
  int classify(const CadFace &face) const;
  static const std::vector<std::string> &region_names();

  double cad_volume_m3() const { return cad_volume_m3_; }
  const CutWater &cut_water() const { return cut_water_; }
  /// The cut-water nose centre in x, y (m).
  Eigen::Vector2d nose_centre_xy_m() const;
  /// Where the straight duct ends and the loft to the circle begins, and the outlet plane (x, m).
  double duct_end_x_m() const { return duct_length_m_; }
  double outlet_x_m() const;
  /// The discharge axis: y of the pipe's centre line (z = chamber middle).
  double discharge_axis_y_m() const;

private:
  using Section = std::vector<Eigen::Vector2d>; // (r or v, z) corners of a section
  Section spiral_section(double phi_rad) const;
  Section throat_section(double inner_v_m) const;
  int spiral_loft(double phi_from_rad, double phi_to_rad);
  int discharge();
  int tongue_filler();
  Eigen::Vector3d to_xyz(double u, double v, double z) const { return {u, -sense_ * v, z}; }

  PumpDesign design_;
  VoluteSizing volute_;
  double sense_, r3_, z_low_, z_high_, inner_v_m_, duct_length_m_;
  CutWater cut_water_;
  double cad_volume_m3_ = 0.0;
};

} // namespace fsi::pump
