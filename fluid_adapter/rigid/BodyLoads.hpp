#pragma once
// Force and torque of the fluid on a rigid body from the penalization source (Eq. 9).
//
// Sign convention. The input is the momentum source that the penalization applies ON THE
// FLUID, per unit volume (N/m^3), as it acts in the momentum equation after the solve:
//     f_on_fluid = -chi mu/K_ibm (u - u_rib)
// (it pulls the fluid inside the body towards u_rib; the paper's Eq. 9 writes the magnitude
// with the opposite sign, i.e. the drag of the fluid on the body). By Newton's third law the
// load on the body is its reaction:
//     F = -sum_c f_c V_c,        T = -sum_c (x_c - p) x f_c V_c    (sum over cells with chi > 0)
// so that a fluid moving faster than the body pushes the body forward (F along u - u_rib).
// OpenFOAM's incompressible solvers hold the source per unit density (m/s^2): multiply by
// rho once, in the adapter, before calling this. The adapter also takes off the inertia of the
// fluid a body holds (its cells covered at both ends of a step, rho times their ddt): that
// fluid stands for the body's solid (OpenFoamFluidModel::held_fluid_load_density).

#include "common/Types.hpp"
#include "fluid_adapter/rigid/BodyIndicator.hpp"

#include <Eigen/Core>

namespace fsi::fluid::rigid {

struct BodyLoad {
  Vec3 force_n = Vec3::Zero();      ///< force of the fluid on the body (N)
  Vec3 torque_n_m = Vec3::Zero();   ///< torque of the fluid on the body about torque_point_m (N m)
  Vec3 torque_point_m = Vec3::Zero();
};

class BodyLoads {
public:
  /// Sums over the indicator's inside cells (chi > 0 at its last update). Arrays are per
  /// cell of the mesh the indicator was built on. Throws std::invalid_argument on a size
  /// mismatch.
  static BodyLoad from_source_on_fluid(const BodyIndicator &indicator,
                                       const PointArray &cell_centres_m,
                                       const PointArray &force_on_fluid_n_per_m3,
                                       const Eigen::VectorXd &cell_volumes_m3,
                                       const Vec3 &torque_point_m);
};

} // namespace fsi::fluid::rigid
