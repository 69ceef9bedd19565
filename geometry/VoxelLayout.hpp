#pragma once
// A regular grid of cubic cells over a box: indexing, cell centres and the cells a box covers.
// Shared by the voxel side classification and the per-cell candidate triangle lists.

#include "common/Types.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace fsi::geometry {

class VoxelLayout {
public:
  /// Inclusive ranges of cell coordinates along each axis.
  struct CellRange {
    std::array<int, 3> first{0, 0, 0};
    std::array<int, 3> last{-1, -1, -1};
  };

  VoxelLayout() = default;
  /// Cells of edge cell_size_m covering box_m grown by margin_m on every side, at least 3
  /// along each axis.
  VoxelLayout(const Eigen::AlignedBox3d &box_m, double margin_m, double cell_size_m);

  std::size_t n_cells() const {
    return static_cast<std::size_t>(n_cells_[0]) * n_cells_[1] * n_cells_[2];
  }
  const std::array<int, 3> &n_cells_per_axis() const { return n_cells_; }
  double cell_size_m() const { return cell_size_m_; }
  /// Half the diagonal of a cell: no point of a cell is farther from its centre.
  double half_diagonal_m() const { return 0.5 * std::sqrt(3.0) * cell_size_m_; }

  std::int32_t index(int i, int j, int k) const { return i + n_cells_[0] * (j + n_cells_[1] * k); }
  std::array<int, 3> coordinates(std::int32_t cell) const {
    return {cell % n_cells_[0], (cell / n_cells_[0]) % n_cells_[1],
            cell / (n_cells_[0] * n_cells_[1])};
  }
  Vec3 centre_m(int i, int j, int k) const {
    return origin_m_ + cell_size_m_ * Vec3(i + 0.5, j + 0.5, k + 0.5);
  }
  Vec3 centre_m(std::int32_t cell) const {
    const std::array<int, 3> c = coordinates(cell);
    return centre_m(c[0], c[1], c[2]);
  }
  bool on_border(int i, int j, int k) const {
    return i == 0 || j == 0 || k == 0 || i == n_cells_[0] - 1 || j == n_cells_[1] - 1 ||
           k == n_cells_[2] - 1;
  }

  /// Flat index of the cell holding the point, -1 outside the grid (or NaN).
  std::int64_t cell_of(const Vec3 &point_m) const {
    Vec3 centre;
    return cell_of(point_m, centre);
  }
  /// The same, and the cell's centre (left unset outside the grid).
  std::int64_t cell_of(const Vec3 &point_m, Vec3 &cell_centre_m) const {
    int cell[3];
    for (int axis = 0; axis < 3; ++axis) {
      const double scaled = (point_m[axis] - origin_m_[axis]) * inverse_cell_size_;
      if (!(scaled >= 0.0 && scaled < n_cells_[axis]))
        return -1; // beyond the grid, or NaN
      cell[axis] = static_cast<int>(scaled);
    }
    cell_centre_m = centre_m(cell[0], cell[1], cell[2]);
    return index(cell[0], cell[1], cell[2]);
  }

  /// Cells holding a point of box_m grown by margin_m, clamped to the grid.
  CellRange cells_covering(const Eigen::AlignedBox3d &box_m, double margin_m) const;

  /// Calls visit(cell, centre_m, squared distance from the centre to box_m) for every cell
  /// whose centre lies within distance_m of box_m (row by row, skipping the box's corners).
  template <typename Visit>
  void for_each_cell_near(const Eigen::AlignedBox3d &box_m, double distance_m,
                          Visit &&visit) const {
    const CellRange range = cells_covering(box_m, distance_m);
    const double limit_sq_m2 = distance_m * distance_m;
    for (int k = range.first[2]; k <= range.last[2]; ++k) {
      const double z_m = origin_m_[2] + (k + 0.5) * cell_size_m_;
      const double gap_z_m = std::max({box_m.min()[2] - z_m, z_m - box_m.max()[2], 0.0});
      for (int j = range.first[1]; j <= range.last[1]; ++j) {
        const double y_m = origin_m_[1] + (j + 0.5) * cell_size_m_;
        const double gap_y_m = std::max({box_m.min()[1] - y_m, y_m - box_m.max()[1], 0.0});
        const double rest_sq_m2 = limit_sq_m2 - gap_y_m * gap_y_m - gap_z_m * gap_z_m;
        if (rest_sq_m2 < 0.0)
          continue;
        // Along x the centre may lie up to sqrt(rest) outside the box.
        const double reach_x_m = std::sqrt(rest_sq_m2);
        const int first_i = std::max(
            range.first[0], static_cast<int>(std::ceil(
                                (box_m.min()[0] - reach_x_m - origin_m_[0]) / cell_size_m_ - 0.5)));
        const int last_i = std::min(
            range.last[0], static_cast<int>(std::floor(
                               (box_m.max()[0] + reach_x_m - origin_m_[0]) / cell_size_m_ - 0.5)));
        for (int i = first_i; i <= last_i; ++i) {
          const Vec3 centre_m(origin_m_[0] + (i + 0.5) * cell_size_m_, y_m, z_m);
          const double gap_x_m =
              std::max({box_m.min()[0] - centre_m[0], centre_m[0] - box_m.max()[0], 0.0});
          visit(index(i, j, k), centre_m,
                gap_x_m * gap_x_m + gap_y_m * gap_y_m + gap_z_m * gap_z_m);
        }
      }
    }
  }

private:
  double cell_size_m_ = 0.0;
  double inverse_cell_size_ = 0.0; ///< 1 / cell_size_m_ (1/m): look-ups multiply
  Vec3 origin_m_ = Vec3::Zero();
  std::array<int, 3> n_cells_{0, 0, 0};
};

} // namespace fsi::geometry
