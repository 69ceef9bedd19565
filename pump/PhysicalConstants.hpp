#pragma once
// The constants of the pump's design rules (SI): water at the design point and gravity.

#include <cmath>

namespace fsi::pump {

inline constexpr double g_m_per_s2 = 9.81;
inline constexpr double water_kg_per_m3 = 1000.0;

/// N in rpm of a rotation rate omega in rad/s (the unit of the specific speed n_q).
inline double rpm(double omega_rad_per_s) { return omega_rad_per_s * 60.0 / (2.0 * M_PI); }

} // namespace fsi::pump
