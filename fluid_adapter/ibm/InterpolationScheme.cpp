#include "fluid_adapter/ibm/InterpolationScheme.hpp"

#include <stdexcept>

namespace fsi::fluid::ibm {

std::vector<std::string> interpolation_scheme_names() { return {"kernel", "closest_cell_linear"}; }

std::string interpolation_scheme_name(InterpolationScheme scheme) {
  return scheme == InterpolationScheme::kernel ? "kernel" : "closest_cell_linear";
}

InterpolationScheme interpolation_scheme_from_name(const std::string &name) {
  if (name == "kernel")
    return InterpolationScheme::kernel;
  if (name == "closest_cell_linear")
    return InterpolationScheme::closest_cell_linear;
  throw std::invalid_argument("unknown velocity interpolation scheme '" + name +
                              "'; valid schemes: kernel, closest_cell_linear");
}

PointArray interpolate_velocity(InterpolationScheme scheme, const KernelStencil &stencil,
                                const ClosestCellLinear &closest_cell, const PointArray &points_m,
                                const PointArray &cell_velocity_m_per_s,
                                const CellGradientArray &cell_velocity_gradient_per_s) {
  if (scheme == InterpolationScheme::kernel)
    return stencil.interpolate(cell_velocity_m_per_s);
  return closest_cell.interpolate(points_m, cell_velocity_m_per_s, cell_velocity_gradient_per_s);
}

} // namespace fsi::fluid::ibm
