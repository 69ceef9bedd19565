#include "fluid_adapter/ibm/ClosestCellLinear.hpp"

#include <stdexcept>

namespace fsi::fluid::ibm {

ClosestCellLinear::ClosestCellLinear(const EulerianCells &cells, const NearestCells &nearest)
    : cells_(cells), nearest_(nearest) {}

PointArray ClosestCellLinear::interpolate(const PointArray &points_m, const PointArray &cell_velocity_m_per_s,
                                          const CellGradientArray &cell_velocity_gradient_per_s) const {
  if (points_m.rows() != nearest_.n_points() || cell_velocity_m_per_s.rows() != cells_.n_cells() ||
      cell_velocity_gradient_per_s.rows() != cells_.n_cells())
    throw std::invalid_argument("ClosestCellLinear::interpolate: expected one point per NearestCells "
                                "entry and one velocity and one gradient per cell");
  PointArray point_velocity_m_per_s = PointArray::Zero(points_m.rows(), 3);
  for (Eigen::Index k = 0; k < points_m.rows(); ++k) {
    const CellId cell = nearest_.cell()[static_cast<std::size_t>(k)];
    if (cell < 0)
      continue;
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> jacobian(
        cell_velocity_gradient_per_s.row(cell).data());
    const Vec3 offset_m = points_m.row(k).transpose() - cells_.centre_m(cell);
    point_velocity_m_per_s.row(k) = (cell_velocity_m_per_s.row(cell).transpose() + jacobian * offset_m).transpose();
  }
  return point_velocity_m_per_s;
}

} // namespace fsi::fluid::ibm
