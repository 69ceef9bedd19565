#pragma once
// The checks of a generated pump's two STL files before they become a case (issue 11): the
// impeller (a closed solid) and the casing (the fluid domain as one closed solid), both in the
// pump's frame: rotation axis z through the origin, flow entering the eye from -z, the channel
// between the shroud (-t <= z <= 0, R_eye <= r <= R2) and the hub disc (b2 <= z <= b2 + t),
// the volute's throat in the half-plane through the axis at the cut-water angle.
//
// Each file: closed (open edges counted and located), consistently and outward oriented,
// in the design's units (the impeller's radius against D2 / 2). Then together: the impeller
// inside the casing and not touching it (smallest gap between the surfaces), and the measures:
// the enclosed volumes, the volute's throat area against the design rules' band and the
// constant-angular-momentum rule, and the free passage through the impeller's channel with
// the point where the largest sphere gets stuck. A failure says what is wrong, in which file,
// and what to do; checks that need a failed one are skipped.

#include "geometry/RegionSoup.hpp"
#include "pump/GeometryCheckReport.hpp"
#include "pump/PumpDesign.hpp"

#include <string>

namespace fsi::pump {

/// The numbers of the design the checks compare the files with (m, rad).
struct PumpGeometryFrame {
  double impeller_radius_m = 0.1;      ///< R2 = D2 / 2
  double eye_radius_m = 0.05;          ///< R_eye = D1 / 2
  double outlet_width_m = 0.05;        ///< b2: the channel is 0 <= z <= b2
  double disc_thickness_m = 0.008;     ///< t of the shroud and hub discs
  double volute_base_radius_m = 0.105; ///< r3
  double cut_water_angle_rad = 0.0;    ///< the throat's half-plane, from +x towards +y
  double design_throat_area_m2 = 0.0;  ///< VoluteSizing's throat area
  double throat_band_min_m2 = 80e-4;   ///< the design rules' band for the duty (ThroatBand)
  double throat_band_max_m2 = 115e-4;

  /// From the design file. The design has no disc thickness and no cut-water angle yet:
  /// t = the blade thickness, the cut-water on +x (the generator's conventions).
  static PumpGeometryFrame from_design(const PumpDesign &design);
};

/// The tolerances of the checks.
struct GeometryCheckLimits {
  double unit_scale = 1.0;           ///< metres per file unit (0.001: millimetres)
  double min_clearance_m = 0.001;    ///< closer than this the impeller touches the casing
  double passage_spacing_m = 0.0015; ///< voxel spacing h of the free passage
  double radius_tolerance = 0.1;     ///< impeller radius within R2 (1 +- this)
};

class GeometryChecks {
public:
  GeometryChecks(const PumpGeometryFrame &frame, const GeometryCheckLimits &limits);

  /// Reads both files (a geometry::MeshError when one is missing or unreadable) and checks.
  GeometryCheckReport run(const std::string &impeller_stl, const std::string &casing_stl) const;
  /// The same on soups in file units; the names stand for the files in the messages.
  GeometryCheckReport run(const geometry::RegionSoup &impeller, const std::string &impeller_name,
                          const geometry::RegionSoup &casing, const std::string &casing_name) const;

private:
  PumpGeometryFrame frame_;
  GeometryCheckLimits limits_;
};

} // namespace fsi::pump
