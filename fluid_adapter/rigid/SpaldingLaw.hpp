#pragma once
// Spalding's law of the wall, the one OpenFOAM's nutUSpaldingWallFunction applies on the mesh's
// walls (kappa = 0.41, E = 9.8), solved for the wall shear stress of a speed U (tangential,
// relative to the wall) at a distance y from it:
//   y+ = u+ + (1/E) [exp(kappa u+) - 1 - kappa u+ - (kappa u+)^2 / 2 - (kappa u+)^3 / 6],
//   u+ = U / u_tau, y+ = y u_tau / nu, tau_w / rho = u_tau^2.
// It spans the viscous sublayer (u+ = y+: tau_w / rho = nu U / y) and the log layer
// (u+ = ln(E y+) / kappa) with one formula, so the immersed walls' model (ImmersedWallModel)
// needs no switch between them.

namespace fsi::fluid::rigid {

struct SpaldingLaw {
  double kappa = 0.41;
  double e = 9.8;

  /// y+ of a given u+ (the law as written).
  double y_plus(double u_plus) const;
  /// tau_w / rho (m^2/s^2) of the speed U (m/s, >= 0) at the distance y (m, > 0) from the wall
  /// in a fluid of kinematic viscosity nu (m^2/s, > 0): u+ solved from Re_y = U y / nu = u+ y+
  /// by safeguarded Newton to a relative 1e-12. 0 for U = 0.
  double wall_shear_per_density(double speed_m_per_s, double distance_m, double nu_m2_per_s) const;
};

} // namespace fsi::fluid::rigid
