#pragma once
// Test support for the tension schemes (solver.tension): a structure pinned along one edge (or
// at one end), released horizontally, swinging down under gravity, run through the real parser.
// - membrane: the flap 0.2 m x 0.1 m, Delta s = 0.01 m, rho_1 = 0.08 kg/m^2, phi = 1000 N/m:
//   c = sqrt(2 phi / rho_1) = 158 m/s, frozen limit Delta s / c = 6.3e-5 s, stabilization
//   threshold Delta s / (1.5 c) = 4.2e-5 s.
// - filament: 1 m, Delta s = 0.025 m, 0.1 kg/m, phi = 200 N: c = 63 m/s, threshold 2.6e-4 s.

#include "CaseFixture.hpp"

#include <cmath>
#include <string>

namespace fsi::structure::testing {

struct Swing {
  PointArray x;                          ///< positions at the end (or when it went wrong)
  double max_stretch = 1.0;              ///< largest edge stretch ratio seen
  double max_energy_gain_j = 0.0;        ///< max of E(t) - E(0)
  bool finite = true;
  bool explicit_stretching = true;       ///< what the structure reports
};

inline std::string swing_yaml(const std::string &model, const std::string &tension, double dt, bool gravity) {
  const std::string head = "run: {end_time_s: 1, time_step_s: " + std::to_string(dt) +
                           ", output_interval_s: 0.01}\n"
                           "gravity_m_per_s2: [0, 0, " + (gravity ? "-9.81" : "0") + "]\n";
  const std::string solver = "    solver: {tension: " + tension + ", linear_solver: direct}\n";
  if (model == "filament")
    return head + "structures:\n  - name: chain\n    model: filament\n    length_m: 1.0\n    n_points: 41\n"
                  "    direction: [1, 0, 0]\n    linear_density_kg_per_m: 0.1\n    tension_coefficient_n: 200.0\n"
                  "    bending_rigidity_n_m2: 1.0e-6\n    ends: {start: pinned, end: free}\n" + solver;
  return head + "structures:\n  - name: flap\n    model: membrane\n    size_m: [0.2, 0.1]\n    n_points: [21, 11]\n"
                "    material:\n      mass_per_area_kg_per_m2: 0.08\n"
                "      coefficients: {tension_coefficient_n_per_m: 1000, bending_rigidity_n_m: 1.0e-4}\n"
                "    edges: {s1_min: pinned}\n" + solver;
}

/// Runs the swing for end_time_s (stops early once it blows up: non-finite or stretch > 2).
inline Swing swing(const std::string &model, const std::string &tension, double dt, double end_time_s,
                   bool gravity = true) {
  Scene scene(load_case(swing_yaml(model, tension, dt, gravity)));
  const auto &s = *scene.structures().front();
  const double e0 = s.energy().total();
  Swing out;
  out.explicit_stretching = s.explicit_stretching();
  const long steps = std::lround(end_time_s / dt);
  for (long k = 0; k < steps; ++k) {
    scene.advance();
    out.finite = s.positions_m().allFinite();
    if (!out.finite)
      break;
    out.max_stretch = std::max(out.max_stretch, s.max_stretch_ratio());
    if (out.max_stretch > 2.0)
      break; // blown up
    out.max_energy_gain_j = std::max(out.max_energy_gain_j, s.energy().total() - e0);
  }
  out.x = s.positions_m();
  return out;
}

} // namespace fsi::structure::testing
