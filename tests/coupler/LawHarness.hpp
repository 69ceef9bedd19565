#pragma once
// What the coupling-law tests share: a flat free membrane sheet of the real solver of Eq. (4),
// and one free point moved by Eq. (4) without elastic terms under a law alone.

#include "coupler/CouplingLaw.hpp"
#include "structure_solver/InitialShape.hpp"
#include "structure_solver/LagrangianSheet.hpp"

#include <memory>

namespace fsi::coupler::testing {

/// A flat n x n sheet of side `size_m` in the xy plane, at rest, free edges.
inline std::unique_ptr<structure::LagrangianSheet> flat_sheet(int n, double size_m, double rho, double phi,
                                                             double zeta, double dt) {
  structure::LagrangianGrid grid(n, n, size_m, size_m);
  structure::SheetSetup setup("sheet", "membrane", grid,
                              structure::initial_shape(grid, Vec3::Zero(),
                                                       structure::make_frame(Vec3::UnitX(), Vec3::UnitY()), 0.0));
  setup.mass_per_measure = rho;
  setup.tension_coefficient = phi;
  setup.bending_rigidity = zeta;
  setup.time_step_s = dt;
  return std::make_unique<structure::LagrangianSheet>(setup);
}

struct FreePoint {
  PointArray x = PointArray::Zero(1, 3), x_prev = PointArray::Zero(1, 3);
  /// |U - V| of the last step, U = 1 m/s along x.
  double slip(double dt) const { return std::abs(1.0 - (x(0, 0) - x_prev(0, 0)) / dt); }
};

/// One point released at rest at the origin in a flow of 1 m/s along x, after `steps` of
/// rho (X^{n+1} - 2 X^n + X^{n-1}) / dt^2 = -F (Eq. 3 without elastic terms), each step accepted.
inline FreePoint free_point_after(CouplingLaw &law, double dt, double rho, int steps) {
  FreePoint p;
  PointArray u(1, 3);
  u << 1.0, 0.0, 0.0;
  law.start(p.x);
  for (int n = 0; n < steps; ++n) {
    const CouplingOutputs out = law.compute({&p.x, &p.x_prev, &u, dt});
    law.accept(out);
    PointArray x_next = 2.0 * p.x - p.x_prev - dt * dt / rho * out.force_density_n_per_measure;
    p.x_prev.swap(p.x);
    p.x.swap(x_next);
  }
  return p;
}

} // namespace fsi::coupler::testing
