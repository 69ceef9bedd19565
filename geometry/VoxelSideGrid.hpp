#pragma once
// A coarse voxel classification of a closed mesh's surroundings, computed once, that lets
// most collision queries skip the exact CGAL search: cells that may lie within a query radius
// of the surface are "near"; every other cell is wholly inside or wholly outside the mesh.
// Far-outside points then cost one array look-up, and far-inside points skip the ray-parity
// inside test (they still need the exact closest point to be pushed out). Near and inside
// cells also remember a triangle close to them: a starting guess that shrinks the exact
// closest-point search.

#include "common/Types.hpp"
#include "geometry/VoxelLayout.hpp"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace fsi::geometry {

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
  /// State of a cell by its flat index in layout().
  VoxelState state_of_cell(std::int32_t cell) const {
    return states_[static_cast<std::size_t>(cell)];
  }

  /// Index (into the constructor's list) of a triangle near the point's cell, -1 if the
  /// point is outside the grid or in a far-outside cell.
  std::int32_t hint_triangle_at(const Vec3 &point_m) const;

  double radius_m() const { return radius_m_; }
  double cell_size_m() const { return layout_.cell_size_m(); }
  const VoxelLayout &layout() const { return layout_; }
  std::size_t n_near_cells() const;

private:
  void size_grid(const Eigen::AlignedBox3d &mesh_box, std::size_t max_cells);
  void mark_near_cells(const Triangle &triangle, std::int32_t triangle_index,
                       std::vector<float> &hint_distance_sq_m2);
  /// Gives every inside cell the hint of the nearest near cell (breadth-first from them).
  void propagate_hints_inside();
  void flood_fill_far_cells(const std::function<bool(const Vec3 &)> &is_inside_mesh);
  /// Breadth-first fill of the far cells connected to the seeds with `state`.
  void fill_region(std::vector<std::int32_t> seeds, VoxelState state);

  double radius_m_;
  VoxelLayout layout_;
  std::vector<VoxelState> states_;
  std::vector<std::int32_t> hint_triangles_;
  std::vector<std::uint8_t> visited_;
};

} // namespace fsi::geometry
