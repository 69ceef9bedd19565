#include "geometry/VoxelSideGrid.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsi::geometry {

VoxelSideGrid::VoxelSideGrid(const std::vector<Triangle> &triangles, double radius_m,
                             const std::function<bool(const Vec3 &)> &is_inside_mesh,
                             std::size_t max_cells)
    : radius_m_(std::max(radius_m, 0.0)) {
  Eigen::AlignedBox3d mesh_box;
  for (const Triangle &triangle : triangles) {
    for (const Vec3 &corner : triangle)
      mesh_box.extend(corner);
  }
  size_grid(mesh_box, max_cells);
  // Everything starts far and outside; near cells are marked, then far cells classified.
  states_.assign(layout_.n_cells(), VoxelState::outside_mesh);
  hint_triangles_.assign(states_.size(), -1);
  std::vector<float> hint_distance_sq_m2(states_.size(), std::numeric_limits<float>::max());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    mark_near_cells(triangles[t], static_cast<std::int32_t>(t), hint_distance_sq_m2);
  }
  flood_fill_far_cells(is_inside_mesh);
  propagate_hints_inside();
}

void VoxelSideGrid::size_grid(const Eigen::AlignedBox3d &mesh_box, std::size_t max_cells) {
  // Cells no smaller than half the radius keep the near marking of each triangle cheap.
  const double padded_volume_m3 = (mesh_box.sizes().array() + 2.0 * radius_m_).prod();
  double cell_size_m = std::max({0.5 * radius_m_, std::cbrt(padded_volume_m3 / max_cells),
                                 1e-9 * mesh_box.sizes().maxCoeff()});
  // Two spare cells beyond radius_m on each side: the border layer is never near.
  layout_ = VoxelLayout(mesh_box, radius_m_ + 2.0 * cell_size_m, cell_size_m);
  while (layout_.n_cells() > max_cells) {
    cell_size_m *= 1.1;
    layout_ = VoxelLayout(mesh_box, radius_m_ + 2.0 * cell_size_m, cell_size_m);
  }
}

void VoxelSideGrid::mark_near_cells(const Triangle &triangle, std::int32_t triangle_index,
                                    std::vector<float> &hint_distance_sq_m2) {
  Eigen::AlignedBox3d box;
  for (const Vec3 &corner : triangle)
    box.extend(corner);
  const Vec3 centroid_m = (triangle[0] + triangle[1] + triangle[2]) / 3.0;
  const Vec3 normal = (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).normalized();
  // A cell is near when its centre lies within radius + half a cell diagonal of both the
  // triangle's bounding box and its plane (both contain the triangle: conservative).
  const double reach_m = radius_m_ + layout_.half_diagonal_m();
  const VoxelLayout::CellRange range = layout_.cells_covering(box, reach_m);
  for (int k = range.first[2]; k <= range.last[2]; ++k) {
    for (int j = range.first[1]; j <= range.last[1]; ++j) {
      for (int i = range.first[0]; i <= range.last[0]; ++i) {
        const Vec3 centre_m = layout_.centre_m(i, j, k);
        if (std::abs(normal.dot(centre_m - triangle[0])) > reach_m)
          continue;
        const auto cell = static_cast<std::size_t>(layout_.index(i, j, k));
        states_[cell] = VoxelState::near_surface;
        const auto distance_sq_m2 = static_cast<float>((centre_m - centroid_m).squaredNorm());
        if (distance_sq_m2 < hint_distance_sq_m2[cell]) { // keep the closest triangle centroid
          hint_distance_sq_m2[cell] = distance_sq_m2;
          hint_triangles_[cell] = triangle_index;
        }
      }
    }
  }
}

void VoxelSideGrid::flood_fill_far_cells(const std::function<bool(const Vec3 &)> &is_inside_mesh) {
  const std::array<int, 3> &n_cells = layout_.n_cells_per_axis();
  visited_.assign(states_.size(), 0);
  std::vector<std::int32_t> border;
  for (int k = 0; k < n_cells[2]; ++k) {
    for (int j = 0; j < n_cells[1]; ++j) {
      for (int i = 0; i < n_cells[0]; ++i) {
        if (layout_.on_border(i, j, k))
          border.push_back(layout_.index(i, j, k));
      }
    }
  }
  fill_region(border, VoxelState::outside_mesh);
  // Enclosed far regions: one exact side test decides each whole region.
  for (std::int32_t cell = 0; cell < static_cast<std::int32_t>(states_.size()); ++cell) {
    if (visited_[cell] || states_[cell] == VoxelState::near_surface)
      continue;
    const bool inside = is_inside_mesh(layout_.centre_m(cell));
    fill_region({cell}, inside ? VoxelState::inside_mesh : VoxelState::outside_mesh);
  }
  visited_.clear();
  visited_.shrink_to_fit();
}

void VoxelSideGrid::fill_region(std::vector<std::int32_t> seeds, VoxelState state) {
  const std::array<int, 3> &n_cells = layout_.n_cells_per_axis();
  const std::int32_t strides[3] = {1, n_cells[0], n_cells[0] * n_cells[1]};
  std::vector<std::int32_t> queue;
  for (std::int32_t seed : seeds) {
    if (!visited_[seed] && states_[seed] != VoxelState::near_surface) {
      visited_[seed] = 1;
      queue.push_back(seed);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t cell = queue[head];
    states_[cell] = state;
    const std::array<int, 3> coords = layout_.coordinates(cell);
    for (int axis = 0; axis < 3; ++axis) {
      for (int step : {-1, 1}) {
        const int next_coord = coords[axis] + step;
        if (next_coord < 0 || next_coord >= n_cells[axis])
          continue;
        const std::int32_t next = cell + step * strides[axis];
        if (visited_[next] || states_[next] == VoxelState::near_surface)
          continue;
        visited_[next] = 1;
        queue.push_back(next);
      }
    }
  }
}

void VoxelSideGrid::propagate_hints_inside() {
  std::vector<std::int32_t> queue;
  for (std::size_t cell = 0; cell < states_.size(); ++cell) {
    if (states_[cell] == VoxelState::near_surface)
      queue.push_back(static_cast<std::int32_t>(cell));
  }
  const std::array<int, 3> &n_cells = layout_.n_cells_per_axis();
  const std::int32_t strides[3] = {1, n_cells[0], n_cells[0] * n_cells[1]};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t cell = queue[head];
    for (const std::int32_t stride : strides) {
      for (const std::int32_t next : {cell - stride, cell + stride}) {
        // Inside cells never touch the grid border, so the neighbours stay in the grid.
        if (next < 0 || next >= static_cast<std::int32_t>(states_.size()))
          continue;
        if (states_[next] != VoxelState::inside_mesh || hint_triangles_[next] >= 0)
          continue;
        hint_triangles_[next] = hint_triangles_[cell];
        queue.push_back(next);
      }
    }
  }
}

VoxelState VoxelSideGrid::state_at(const Vec3 &point_m) const {
  const std::int64_t cell = layout_.cell_of(point_m);
  return cell < 0 ? VoxelState::outside_mesh : states_[static_cast<std::size_t>(cell)];
}

std::int32_t VoxelSideGrid::hint_triangle_at(const Vec3 &point_m) const {
  const std::int64_t cell = layout_.cell_of(point_m);
  return cell < 0 ? -1 : hint_triangles_[static_cast<std::size_t>(cell)];
}

std::size_t VoxelSideGrid::n_near_cells() const {
  return static_cast<std::size_t>(
      std::count(states_.begin(), states_.end(), VoxelState::near_surface));
}

} // namespace fsi::geometry
