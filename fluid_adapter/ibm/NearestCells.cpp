#include "fluid_adapter/ibm/NearestCells.hpp"

#include <limits>
#include <stdexcept>

namespace fsi::fluid::ibm {

NearestCells::NearestCells(const CellIndex &index, const PointArray &points_m, int rank)
    : cell_(static_cast<std::size_t>(points_m.rows()), -1),
      owner_rank_(static_cast<std::size_t>(points_m.rows()), rank), distance_m_(points_m.rows()),
      kernel_width_m_(points_m.rows()) {
  for (Eigen::Index k = 0; k < points_m.rows(); ++k) {
    const CellIndex::Nearest nearest = index.nearest(points_m.row(k).transpose());
    cell_[static_cast<std::size_t>(k)] = nearest.cell;
    distance_m_[k] = nearest.distance_m;
    kernel_width_m_[k] = nearest.cell >= 0 ? index.cells().size_m(nearest.cell)
                                           : std::numeric_limits<double>::quiet_NaN();
  }
}

void NearestCells::merge_other_rank(int other_rank, const Eigen::VectorXd &other_distance_m,
                                    const Eigen::VectorXd &other_kernel_width_m) {
  if (other_distance_m.size() != n_points() || other_kernel_width_m.size() != n_points())
    throw std::invalid_argument("NearestCells::merge_other_rank: the other rank sent results "
                                "for a different number of points");
  for (Eigen::Index k = 0; k < n_points(); ++k) {
    const auto p = static_cast<std::size_t>(k);
    const double other = other_distance_m[k], current = distance_m_[k];
    if (other < current || (other == current && other_rank < owner_rank_[p])) {
      cell_[p] = -1;
      owner_rank_[p] = other_rank;
      distance_m_[k] = other;
      kernel_width_m_[k] = other_kernel_width_m[k];
    }
  }
}

} // namespace fsi::fluid::ibm
