#pragma once
// The camber line of a blade in the (r, theta) plane, from the blade inlet radius r1 to the
// outlet radius r2 (pure math, no CAD). The blade angle beta (from the circumferential
// direction) follows
//   cot beta(x) = cot_1 + (cot_2 - cot_1) x + c x (1 - x),   x = (r - r1) / (r2 - r1),
// and the camber line d theta / dr = -s cot beta(r) / r (s = +1: rotation about +z, -1: about
// -z; the trailing edge lags behind the leading edge, a backward-swept blade). c is solved in
// closed form so that int_{r1}^{r2} cot beta / r dr equals the wrap angle.

namespace fsi::pump {

class BladeCamber {
public:
  /// Throws std::invalid_argument when the radii are not 0 < r1 < r2, or when the wrap angle
  /// needs a beta outside (0, 90) deg somewhere between r1 and r2 (the message names the
  /// design keys to change).
  BladeCamber(double inlet_radius_m, double outlet_radius_m, double inlet_angle_rad, double outlet_angle_rad,
              double wrap_angle_rad, double rotation_sense);

  double inlet_radius_m() const { return r1_; }
  double outlet_radius_m() const { return r2_; }
  /// The curvature coefficient c of cot beta.
  double curvature_coefficient() const { return c_; }
  /// cot beta at radius r (r1 <= r <= r2; outside, the quadratic is extrapolated).
  double cot_beta(double radius_m) const;
  /// beta at radius r (rad, in (0, pi/2]).
  double beta_rad(double radius_m) const;
  /// theta(r) - theta(r1) (rad), closed form of -s int_{r1}^{r} cot beta / r dr.
  double theta_rad(double radius_m) const;
  /// +1 or -1: the sense of rotation about +z.
  double rotation_sense() const { return s_; }

private:
  double unwrapped_angle_rad(double radius_m) const; // int_{r1}^{r} cot beta / r dr
  double r1_, r2_, cot1_, cot2_, c_, s_;
};

} // namespace fsi::pump
