#pragma once
// The volute tongue (cut-water) in the plane of the volute, in the volute's own frame (u, v):
// v along the radius through the cut-water, u along the discharge (the direction of rotation
// there), so that the spiral's outer wall is W(phi) = r_o(phi) (sin phi, cos phi). The
// discharge duct's inner wall is the line v = v_w, tangent to the base circle's neighbourhood;
// between it and the spiral's outer wall lies a thin wedge of casing. Where that wedge is
// thinner than two nose radii it is filled as fluid, ending on a round nose of the given radius
// that cuts both walls at a small angle (so that the booleans meet no tangency). Pure math.

#include <Eigen/Core>

#include <functional>

namespace fsi::pump {

struct CutWater {
  Eigen::Vector2d crossing_m; ///< where the spiral's outer wall crosses the duct's inner wall
  Eigen::Vector2d nose_centre_m;
  double nose_radius_m = 0.0;
  Eigen::Vector2d wall_contact_m; ///< the point of the spiral's wall nearest the nose centre
  double wall_contact_phi_rad = 0.0;
};

/// outer_radius(phi): the spiral's outer radius (phi in rad from the cut-water). The nose of
/// radius r_n is tangent to both walls when shrunk to `tangent_fraction` r_n. Throws
/// std::invalid_argument when the walls do not meet within the first quarter turn.
CutWater place_cut_water(const std::function<double(double)> &outer_radius, double inner_wall_v_m, double nose_radius_m,
                         double tangent_fraction = 0.9);

} // namespace fsi::pump
