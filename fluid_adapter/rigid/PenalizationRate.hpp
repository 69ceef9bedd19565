#pragma once
// The coefficient of the penalization term of Eq. (9) in the units an incompressible
// OpenFOAM solver needs, and a note on its implicit treatment.
//
// OpenFOAM's incompressible momentum equation is written per unit density, so Eq. (9)
// divided by rho_f becomes f/rho = chi (nu/K_ibm) (u - u_rib): the coefficient is a RATE
//     lambda = nu / K_ibm   (1/s),   nu = mu/rho_f (m^2/s), K_ibm a permeability (m^2).
// Implicit treatment (for the solver author; no OpenFOAM code here): put the term on the
// left with the unknown velocity and the body velocity on the right,
//     fvm::ddt(U) + ... + fvm::Sp(chi*lambda, U) == ... + chi*lambda*U_rib
// (chi and chi*lambda*U_rib as volScalarField / volVectorField from BodyIndicator::chi() and
// body_velocity_m_per_s()). The diagonal then gains chi*lambda*V: the matrix only becomes
// more diagonally dominant, so no lambda limits the time step, and one Euler-implicit step
// leaves the fraction 1/(1 + lambda dt) of the slip u - u_rib inside the body (about
// 1/(lambda dt) when large). Also include chi*lambda in the 1/A (rAU) used by the pressure
// equation, as fvm::Sp does automatically when it is part of UEqn.
//
// Units warning. Read literally (K_ibm = 1e-6 m^2, water nu = 1e-6 m^2/s) lambda is only
// 1 1/s: the body would be a weak sponge (slip left per step ~ 1 - dt). Penalization methods
// of the Specklin & Delaure kind behave as intended when lambda dt >> 1, which is what one
// gets reading K_ibm = 1e-6 as a relaxation TIME in seconds (lambda = 1/K_ibm = 1e6 1/s).
// from_relaxation_time() builds that reading; slip_left_after_step() lets a case check its
// choice (aim for < 1e-3, and lambda >> the body's angular rate).

namespace fsi::fluid::rigid {

class PenalizationRate {
public:
  /// lambda = nu / K (Eq. 9 per unit density). Throws std::invalid_argument unless both > 0.
  static PenalizationRate from_permeability(double kinematic_viscosity_m2_per_s,
                                            double permeability_m2);
  /// lambda = 1 / tau (K_ibm read as a relaxation time). Throws unless tau > 0.
  static PenalizationRate from_relaxation_time(double relaxation_time_s);

  /// lambda (1/s): the coefficient of fvm::Sp(chi*lambda, U).
  double per_s() const { return rate_per_s_; }
  /// Fraction of the slip u - u_rib left inside the body after one implicit Euler step.
  double slip_left_after_step(double time_step_s) const { return 1.0 / (1.0 + rate_per_s_ * time_step_s); }
  /// The dynamic coefficient mu/K_ibm (kg m^-3 s^-1) of Eq. 9 for a density rho_f.
  double dynamic_per_s(double density_kg_per_m3) const { return density_kg_per_m3 * rate_per_s_; }

private:
  explicit PenalizationRate(double rate_per_s) : rate_per_s_(rate_per_s) {}
  double rate_per_s_;
};

} // namespace fsi::fluid::rigid
