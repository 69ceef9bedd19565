#pragma once
// Per-cell candidate triangles for exact closest-point queries near a closed mesh. For every
// near cell of a VoxelSideGrid (centre c, half diagonal h), the list holds each triangle T
// that can hold the closest mesh point of some point p of the cell:
//   * T is within d0 + 2h of c, d0 being the distance from c to the mesh: p is within
//     d0 + |p - c| of the mesh and at least dist(c, T) - |p - c| from T;
//   * the cell meets the region of one of T's features (FeatureRegions): the closest point
//     lies on a face interior, an edge or a vertex, and p is then in that feature's region.
// Lists are sorted by distance to the centre, so a query stops at the first triangle that
// is farther than the best so far whatever p in the cell. A list longer than the maximum is
// cut; it then still answers exactly every point closer to the mesh than the first triangle
// it left out (minus |p - c|), and says so: other points go back to a global search.
// Cells also keep the grid's classification, so that one look-up serves both the culling
// test and the query; lists and triangles are stored in space-filling-curve order.

#include "common/Types.hpp"
#include "geometry/FeatureRegions.hpp"
#include "geometry/TrianglePoint.hpp"
#include "geometry/VoxelSideGrid.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fsi::geometry {

class NearTriangleLists {
public:
  using Triangle = VoxelSideGrid::Triangle;

  /// The closest triangle found for a point.
  struct Hit {
    std::int32_t face = -1;    ///< index into the triangles, -1 when no list covers the point
    TrianglePoint closest;     ///< closest point on that triangle and its feature
    double distance_sq_m2 = 0; ///< squared distance from the point to `closest`
    bool exact = false;        ///< true when no other triangle can be closer
  };

  /// Builds the lists for the near cells of `grid`, which was built from the same triangles;
  /// `regions` describes the same mesh. Lists are cut at max_per_cell triangles, or shorter
  /// if all of them would hold more than max_entries entries (4 bytes each). Meshes of 2^24
  /// triangles or more get no lists (every query answers "not exact").
  NearTriangleLists(const VoxelSideGrid &grid, const std::vector<Triangle> &triangles,
                    const FeatureRegions &regions, std::size_t max_per_cell = 64,
                    std::size_t max_entries = std::size_t{1} << 24);

  /// Closest triangle to p among its cell's list: a few exact point-triangle distances.
  Hit nearest(const Vec3 &point_m) const;
  /// The grid's classification of the cell holding p (outside_mesh beyond the grid).
  VoxelState state_at(const Vec3 &point_m) const {
    const std::int64_t cell = layout_.cell_of(point_m);
    return cell < 0
               ? VoxelState::outside_mesh
               : static_cast<VoxelState>(cells_[static_cast<std::size_t>(cell)] >> kStateShift);
  }

  std::size_t n_entries() const { return entries_.size(); }
  std::size_t n_cut_lists() const { return n_cut_lists_; }

private:
  static constexpr int kStateShift = 30;
  static constexpr std::uint32_t kOffsetMask = (std::uint32_t{1} << kStateShift) - 1;

  /// A candidate found while building: the cell's rank along the space-filling curve
  /// among the near cells, the triangle (storage index), its distance from the cell centre.
  struct Candidate {
    std::uint32_t rank;
    std::int32_t triangle;
    float centre_distance_m; ///< rounded down
  };

  /// Stores the triangles sorted along a space-filling curve (faces_ maps them back).
  void store_in_spatial_order(const std::vector<Triangle> &triangles);
  std::uint64_t curve_key(std::int32_t cell) const;
  /// The near cells (those with a reach) sorted along the space-filling curve.
  std::vector<std::int32_t> near_cells_in_curve_order(const std::vector<float> &reach_m) const;
  /// Reach of each near cell's list: min(d0, cap_m) + 2h with d0 the distance from the cell
  /// centre to the mesh; negative for the other cells.
  std::vector<float> list_reaches(const VoxelSideGrid &grid, double cap_m) const;
  /// Every (cell, triangle) pair that passes both tests of the header comment.
  std::vector<Candidate> gather(const FeatureRegions &regions, const std::vector<float> &reach_m,
                                const std::vector<std::int32_t> &near_cells,
                                double max_reach_m) const;
  void build_lists(std::vector<Candidate> candidates, const std::vector<float> &reach_m,
                   const std::vector<std::int32_t> &near_cells, std::size_t max_per_cell,
                   std::size_t max_entries);
  /// Appends the list of one cell: its candidates [begin, end), sorted by distance.
  void append_list(std::int32_t cell, const Candidate *begin, const Candidate *end, float reach_m,
                   std::size_t max_per_cell);

  VoxelLayout layout_;
  std::vector<Triangle> triangles_; ///< in space-filling-curve order
  std::vector<std::int32_t> faces_; ///< the caller's index of each stored triangle
  /// Per cell: the VoxelState in the top two bits; for a near cell, the offset of its list
  /// in entries_ in the others. A list is a header of two entries, the float bits of its
  /// reach R (m) and its length, then one entry per triangle packing the triangle's storage
  /// index (high 24 bits) and its centre distance as a fraction of R, rounded down to a
  /// multiple of 1/255.
  std::vector<std::uint32_t> cells_;
  std::vector<std::uint32_t> entries_;
  std::size_t n_cut_lists_ = 0;
};

} // namespace fsi::geometry
