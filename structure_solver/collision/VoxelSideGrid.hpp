#pragma once
// A coarse voxel classification of a closed mesh's surroundings, computed once, that lets
// most collision queries skip the exact CGAL search: cells that may lie within a query radius
// of the surface are "near"; every other cell is wholly inside or wholly outside the mesh.
// Far-outside points then cost one array look-up, and far-inside points skip the ray-parity
// inside test (they still need the exact closest point to be pushed out). Near and inside
// cells also remember a triangle close to them: a starting guess that shrinks the exact
// closest-point search.

#include "common/Types.hpp"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace fsi::structure::collision {

enum class VoxelState : std::uint8_t { near_surface, inside_mesh, outside_mesh };

class VoxelSideGrid {
public:
  /// One triangle as its three corners (m).
  using Triangle = std::array<Vec3, 3>;

  /// triangles: the closed surface; radius_m: cells whose points may be within this distance
  /// of a triangle are marked near; is_inside_mesh: exact side test, called once per connected
  /// region of far cells that does not touch the grid border; max_cells bounds the memory
  /// (5 bytes a cell). Cells are as small as the budget allows, but not below radius_m / 2.
  VoxelSideGrid(const std::vector<Triangle> &triangles, double radius_m,
                const std::function<bool(const Vec3 &)> &is_inside_mesh,
                std::size_t max_cells = std::size_t{1} << 22);

  /// State of the cell holding the point; outside_mesh beyond the grid (the grid extends
  /// more than radius_m past the mesh's bounding box).
  VoxelState state_at(const Vec3 &point_m) const;

  /// Index (into the constructor's list) of a triangle near the point's cell, -1 if the
  /// point is outside the grid or in a far-outside cell.
  std::int32_t hint_triangle_at(const Vec3 &point_m) const;

  double radius_m() const { return radius_m_; }
  double cell_size_m() const { return cell_size_m_; }
  std::size_t n_near_cells() const;

private:
  void size_grid(const Eigen::AlignedBox3d &mesh_box, std::size_t max_cells);
  /// Sets origin and cell counts for the current cell size; returns the number of cells.
  std::size_t fit_grid(const Eigen::AlignedBox3d &mesh_box);
  void mark_near_cells(const Triangle &triangle, std::int32_t triangle_index,
                       std::vector<float> &hint_distance_sq_m2);
  /// Gives every inside cell the hint of the nearest near cell (breadth-first from them).
  void propagate_hints_inside();
  /// Flat index of the point's cell, -1 outside the grid (or NaN).
  std::int64_t cell_of(const Vec3 &point_m) const;
  void flood_fill_far_cells(const std::function<bool(const Vec3 &)> &is_inside_mesh);
  /// Breadth-first fill of the far cells connected to the seeds with `state`.
  void fill_region(std::vector<std::int32_t> seeds, VoxelState state);
  std::int32_t index(int i, int j, int k) const { return i + n_cells_[0] * (j + n_cells_[1] * k); }
  Vec3 cell_centre_m(int i, int j, int k) const;

  double radius_m_;
  double cell_size_m_ = 0.0;
  Vec3 origin_m_ = Vec3::Zero();
  std::array<int, 3> n_cells_{0, 0, 0};
  std::vector<VoxelState> states_;
  std::vector<std::int32_t> hint_triangles_;
  std::vector<std::uint8_t> visited_;
};

} // namespace fsi::structure::collision
