#pragma once
// The 2-D section of one blade in the z = const plane (pure math, no CAD): the camber line of
// BladeCamber sampled from the leading edge at r1 to beyond the outlet radius (continued at the
// outlet angle, so that the trailing edge can be trimmed on the circle r2), the two sides
// offset by +-t/2 normal to it, and the centre of the rounded leading edge.

#include "BladeCamber.hpp"

#include <Eigen/Core>

#include <vector>

namespace fsi::pump {

struct BladeProfile {
  std::vector<Eigen::Vector2d> camber_m; ///< from the leading edge at r1 outwards
  std::vector<Eigen::Vector2d> left_m;   ///< camber + t/2 n, n = e_z x tangent
  std::vector<Eigen::Vector2d> right_m;  ///< camber - t/2 n
  Eigen::Vector2d leading_edge_centre_m; ///< the camber point at r1
  Eigen::Vector2d leading_edge_tip_m;    ///< the centre - t/2 tangent: the front of the semicircle
  std::size_t n_inside = 0;              ///< the first n_inside camber points are within r2
};

/// The profile of the blade whose leading edge sits at the angle theta0 (rad) about the axis.
/// The sides run past r2 by `overshoot_m` (trimmed later).
BladeProfile make_blade_profile(const BladeCamber &camber, double theta0_rad, double thickness_m, double overshoot_m,
                                int n_samples);

/// The camber point at radius r (r1 <= r), for the blade at theta0; beyond r2 the camber
/// continues as a logarithmic spiral at the outlet angle.
Eigen::Vector2d camber_point(const BladeCamber &camber, double theta0_rad, double radius_m);

} // namespace fsi::pump
