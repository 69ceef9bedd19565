#pragma once
// The channel of a single-channel impeller as meridional sections along its wrap (pure math,
// no CAD; pump/ChannelImpellerSolid lofts through them). Coordinates of docs/pump-design.md:
// axis z, the discs' inner faces at z = 0 (shroud) and z = b2 (hub disc). phi is the angle along
// the channel from its back wall, in the channel's own sense (the solid maps it to the
// backward-swept direction of the rotation). Along phi:
//   - the mouth, phi in [0, phi_m]: the section spans the boss radius to inlet_width_m out, its
//     floor below the shroud plane: the channel stands open to the eye below it; its roof is the
//     hub disc, or (mouth_roof_height_m) rises linearly from that height at the back wall to the
//     hub disc at phi_m, a helical inlet;
//   - the leading edge's ramp, phi in [phi_m, phi_a]: the floor rises at the inlet angle
//     beta_1 (at the eye's mean radius) through the shroud plane, where it meets the vane's
//     underside in the eye along a radial line from the boss to the eye's rim: the leading edge,
//     across the axial inflow; up to the cover's height;
//   - the spiral, phi in [phi_a, wrap]: the inner wall leaves the boss and reaches D2 at the
//     outlet angle beta_2 at phi = wrap (a cubic in phi); the width grows linearly to
//     exit_width_m; once the inner wall is past the eye, the floor falls back to the shroud.
// The section extends past the discs (the hub disc and the shroud ring are fused over it) so
// the booleans never meet coplanar faces.

#include "PumpDesign.hpp"

#include <vector>

namespace fsi::pump {

struct ChannelSection {
  double phi_rad = 0.0;
  double inner_radius_m = 0.0, outer_radius_m = 0.0;
  double floor_z_m = 0.0, top_z_m = 0.0;
};

class ChannelLayout {
public:
  /// Throws std::invalid_argument naming the design keys when the channel cannot be laid out
  /// (its inner wall would not rise monotonically, the ramp would not fit in the wrap, the
  /// nose would not fit on the cover...).
  explicit ChannelLayout(const PumpDesign &design);

  /// The section at phi (rad, 0 <= phi <= exit_phi_rad()).
  ChannelSection section(double phi_rad) const;
  /// The sections the loft runs through: the mouth, the ramp's ends, the spiral every at most
  /// `max_step_rad`, and one past the exit entirely outside D2.
  std::vector<ChannelSection> loft_sections(double max_step_rad) const;

  double mouth_end_rad() const { return phi_m_; }
  double ramp_end_rad() const { return phi_a_; }
  /// Where the rising floor crosses the shroud plane: the leading edge's angle.
  double leading_edge_phi_rad() const { return phi_le_; }
  /// Where the floor starts falling back to the shroud (the inner wall is past the eye).
  double cover_end_rad() const { return phi_r_; }
  double wrap_rad() const { return wrap_; }
  /// The last loft section's angle (past the wrap, the section outside D2).
  double exit_phi_rad() const { return phi_x_; }

  double boss_radius_m() const { return r_boss_; }
  double eye_radius_m() const { return r_eye_; }
  double outer_radius_m() const { return r2_; }
  /// How far below the shroud plane the mouth's floor lies (m).
  double floor_drop_m() const { return drop_; }
  /// The channel's through-flow area at the exit, normal to its direction (m^2): the exit
  /// section's meridional area (width x outlet_width_m) times cos(beta_2), the channel running
  /// at beta_2 from the circumferential direction.
  double exit_area_m2() const;
  /// The roof's angle from the circumferential direction at the eye's mean radius in the mouth
  /// (deg): 0 when the roof is the hub disc.
  double mouth_roof_angle_deg() const;
  /// The smallest of the channel's section widths and heights inside the impeller (m): an upper
  /// bound of the sphere that passes it.
  double smallest_section_side_m() const;

private:
  double inner_radius(double phi) const;
  double width(double phi) const;
  double floor_z(double phi) const;
  double top_z(double phi) const;

  double r2_, b2_, r_eye_, r_boss_, wrap_, phi_m_, phi_a_, phi_le_, phi_r_, phi_x_;
  double tan_beta2_, w1_, w2_, cover_, drop_, roof0_;
};

} // namespace fsi::pump
