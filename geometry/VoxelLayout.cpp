#include "geometry/VoxelLayout.hpp"

#include <algorithm>
#include <cmath>

namespace fsi::geometry {

VoxelLayout::VoxelLayout(const Eigen::AlignedBox3d &box_m, double margin_m, double cell_size_m)
    : cell_size_m_(cell_size_m), inverse_cell_size_(1.0 / cell_size_m),
      origin_m_(box_m.min().array() - margin_m) {
  for (int axis = 0; axis < 3; ++axis) {
    const double span_m = box_m.sizes()[axis] + 2.0 * margin_m;
    n_cells_[axis] = std::max(3, static_cast<int>(std::ceil(span_m / cell_size_m_)));
  }
}

VoxelLayout::CellRange VoxelLayout::cells_covering(const Eigen::AlignedBox3d &box_m,
                                                   double margin_m) const {
  CellRange range;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = (box_m.min()[axis] - margin_m - origin_m_[axis]) / cell_size_m_;
    const double hi = (box_m.max()[axis] + margin_m - origin_m_[axis]) / cell_size_m_;
    range.first[axis] = std::clamp(static_cast<int>(std::floor(lo)), 0, n_cells_[axis] - 1);
    range.last[axis] = std::clamp(static_cast<int>(std::floor(hi)), 0, n_cells_[axis] - 1);
  }
  return range;
}

} // namespace fsi::geometry
