#pragma once
// The time-step limit of OpenFOAM's PISO/PIMPLE loop in a viscous flow. With a momentum
// predictor and few pressure correctors, pimpleFoam (v1912, and this solver, which follows it)
// diverges once the viscous number D = nu_eff dt sum_i 1/dx_i^2 of a cell passes a limit, with
// or without immersed bodies: a lid-driven cavity without any body diverges as a penalized
// cylinder does, at the same D, in 2D and in 3D (docs/verification.md, "The limits of PISO").
// Measured limits (bisection; stable below, growing above):
//   momentumPredictor yes, nOuterCorrectors 1: nCorrectors 1: D = 0.55; nCorrectors 2: D = 30.5;
//   nCorrectors 3: above 1,800 (not reached); momentumPredictor no, nCorrectors 2: above 1,900.
// A case over a known limit is refused before its first step, with the time step that would
// be stable and the settings that remove the limit; other settings are logged, not judged.

#include "common/Types.hpp"

#include <string>

namespace fsi::fluid {

/// The PIMPLE dictionary's settings that decide the limit (system/fvSolution).
struct PisoSettings {
  bool momentum_predictor = true;
  int correctors = 1;       ///< nCorrectors
  int outer_correctors = 1; ///< nOuterCorrectors
};

/// The largest viscous number over the cells (the empty direction of a 2D mesh does not count;
/// nu_eff = nu + nu_t at the start) and the centre of its cell.
struct ViscousNumber {
  double value = 0.0;
  Vec3 where_m = Vec3::Zero();
};

class PisoLimit {
public:
  /// Refuse a case above this fraction of the measured limit.
  static constexpr double kMargin = 0.8;

  /// The measured limit of D for these settings; +inf where none is known.
  static double measured_limit(const PisoSettings &settings);

  /// "" when D is within kMargin of the measured limit (or none is known); otherwise the
  /// refusal: D, where, the limit, the largest stable time step, and what removes the limit.
  static std::string refusal(const PisoSettings &settings, const ViscousNumber &d, double dt_s);
};

} // namespace fsi::fluid
