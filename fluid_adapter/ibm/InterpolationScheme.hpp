#pragma once
// How the fluid velocity is brought to the Lagrangian points (U_ib of Eq. 5):
//   kernel               U(X_k) = sum_c u_c delta_h(x_c - X_k) V_c, adjoint to spreading;
//   closest_cell_linear  u_c + grad(u)_c (X - x_c) at the nearest cell, as Sec. 2.3 states.

#include "fluid_adapter/ibm/ClosestCellLinear.hpp"
#include "fluid_adapter/ibm/KernelStencil.hpp"

#include <string>
#include <vector>

namespace fsi::fluid::ibm {

enum class InterpolationScheme { kernel, closest_cell_linear };

/// The configuration names: "kernel", "closest_cell_linear".
std::vector<std::string> interpolation_scheme_names();
std::string interpolation_scheme_name(InterpolationScheme scheme);
/// Throws std::invalid_argument naming the valid schemes when `name` is none of them.
InterpolationScheme interpolation_scheme_from_name(const std::string &name);

/// This rank's part of U at every point (n x 3, m/s) by `scheme`; the parts of all ranks add
/// up to the result. The gradient is read by closest_cell_linear only (may be empty for
/// kernel).
PointArray interpolate_velocity(InterpolationScheme scheme, const KernelStencil &stencil,
                                const ClosestCellLinear &closest_cell, const PointArray &points_m,
                                const PointArray &cell_velocity_m_per_s,
                                const CellGradientArray &cell_velocity_gradient_per_s);

} // namespace fsi::fluid::ibm
