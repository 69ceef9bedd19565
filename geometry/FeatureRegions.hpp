#pragma once
// Where a point can be for a feature of a triangle (its face interior, an edge or a vertex)
// to hold its closest point on a closed mesh: necessary conditions, each a half-space, from
// "the closest point is also the closest on every neighbouring face and edge":
//   face abc   the prism over the triangle: inside the three planes through its edges
//              perpendicular to it;
//   edge ab    between the planes through a and b perpendicular to ab, and beyond the edge
//              as seen from each of its two faces;
//   vertex v   (x - v).(w - v) <= 0 for every edge vw.
// A triangle can be the closest one to some point of a box only if the box meets one of its
// seven regions; NearTriangleLists uses this to keep per-cell candidate lists short.

#include "common/Types.hpp"
#include "geometry/TriangleSoup.hpp"
#include "geometry/VoxelLayout.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace fsi::geometry {

class FeatureRegions {
public:
  /// x is in the half-space when normal.x <= limit_m (normal of unit length); the limit
  /// may be raised to grow the half-space (see regions_of).
  struct HalfSpace {
    Vec3 normal;
    double limit_m;
  };
  /// The seven regions of one triangle (face, edges ab, bc, ca, vertices a, b, c): region k
  /// is half_spaces[ends[k - 1], ends[k]). Each region is its feature swept along a cone of
  /// directions, whose largest |component| along each axis is spreads[k] (see cone_spread).
  struct TriangleRegions {
    std::vector<HalfSpace> half_spaces;
    std::array<std::size_t, 7> ends{};
    std::array<Vec3, 3> corners;
    std::array<Vec3, 7> spreads;

    /// Box holding every point of region k within distance_m of the triangle.
    Eigen::AlignedBox3d sweep_box(std::size_t k, double distance_m) const;
    /// The interval [lo, hi] of coordinate `axis` over the points of region k on the line
    /// through point_m parallel to that axis; false if the line misses the region.
    bool row_interval(std::size_t k, int axis, const Vec3 &point_m, double &lo_m,
                      double &hi_m) const;

    /// Calls visit(cell, centre) once for every cell of `layout` whose cube may meet a region
    /// within reach_m of the triangle (its centre lies in the grown region). Rows run along
    /// the axis closest to the triangle's normal, so that each crosses the thin regions once.
    template <typename Visit>
    void for_each_cell(const VoxelLayout &layout, double reach_m, Visit &&visit) const;
  };

  /// vertices_m and triangles: a closed mesh (orientation consistent, either way).
  FeatureRegions(const PointArray &vertices_m, const TriangleArray &triangles);

  /// The regions of one triangle (overwrites `regions`, reusing its memory), each half-space
  /// grown so that it holds the centre of every axis-aligned cube of half edge half_edge_m
  /// that it meets, plus a margin margin_m for round-off.
  void regions_of(std::int32_t face, double half_edge_m, double margin_m,
                  TriangleRegions &regions) const;

  /// False only when a cube centred at centre_m meets none of the (grown) regions.
  static bool may_meet_cube(const TriangleRegions &regions, const Vec3 &centre_m) {
    std::size_t begin = 0;
    for (const std::size_t end : regions.ends) {
      std::size_t h = begin;
      while (h < end &&
             regions.half_spaces[h].normal.dot(centre_m) <= regions.half_spaces[h].limit_m)
        ++h;
      if (h == end)
        return true;
      begin = end;
    }
    return false;
  }

private:
  Vec3 vertex(std::int32_t v) const { return vertices_m_.row(v).transpose(); }
  void add_vertex_region(std::int32_t v, TriangleRegions &regions) const;
  void compute_vertex_spreads();

  PointArray vertices_m_;
  TriangleArray triangles_;
  std::vector<std::int32_t> across_edge_;       ///< per face and edge: the neighbour's third
                                                ///< vertex, -1 if the edge is not manifold
  std::vector<std::uint32_t> first_neighbour_;  ///< per vertex, plus one (CSR)
  std::vector<std::int32_t> vertex_neighbours_; ///< vertices joined to each vertex by an edge
  std::vector<Vec3> vertex_spreads_;            ///< per vertex, of its region's cone
};

template <typename Visit>
void FeatureRegions::TriangleRegions::for_each_cell(const VoxelLayout &layout, double reach_m,
                                                    Visit &&visit) const {
  std::array<Eigen::AlignedBox3d, 7> sweeps; // of the cube centres, per region
  Eigen::AlignedBox3d all;
  for (std::size_t region = 0; region < sweeps.size(); ++region) {
    const Eigen::AlignedBox3d sweep = sweep_box(region, reach_m);
    sweeps[region] = Eigen::AlignedBox3d(sweep.min().array() - 0.5 * layout.cell_size_m(),
                                         sweep.max().array() + 0.5 * layout.cell_size_m());
    all.extend(sweeps[region]);
  }
  int axis = 0;
  spreads[0].maxCoeff(&axis); // the largest component of the normal
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const VoxelLayout::CellRange range = layout.cells_covering(all, 0.0);
  std::vector<char> seen(static_cast<std::size_t>(range.last[axis] - range.first[axis] + 1));
  std::array<int, 3> cell{};
  for (cell[v] = range.first[v]; cell[v] <= range.last[v]; ++cell[v]) {
    for (cell[u] = range.first[u]; cell[u] <= range.last[u]; ++cell[u]) {
      cell[axis] = 0;
      const Vec3 row_start_m = layout.centre_m(cell[0], cell[1], cell[2]);
      std::fill(seen.begin(), seen.end(), 0);
      for (std::size_t region = 0; region < sweeps.size(); ++region) {
        const Eigen::AlignedBox3d &sweep = sweeps[region];
        double lo_m, hi_m;
        if (row_start_m[u] < sweep.min()[u] || row_start_m[u] > sweep.max()[u] ||
            row_start_m[v] < sweep.min()[v] || row_start_m[v] > sweep.max()[v] ||
            !row_interval(region, axis, row_start_m, lo_m, hi_m))
          continue;
        const double lo =
            (std::max(lo_m, sweep.min()[axis]) - row_start_m[axis]) / layout.cell_size_m();
        const double hi =
            (std::min(hi_m, sweep.max()[axis]) - row_start_m[axis]) / layout.cell_size_m();
        const int first = static_cast<int>(std::ceil(std::max(lo, range.first[axis] - 1.0)));
        const int last = static_cast<int>(std::floor(std::min(hi, range.last[axis] + 1.0)));
        for (cell[axis] = std::max(first, range.first[axis]);
             cell[axis] <= std::min(last, range.last[axis]); ++cell[axis]) {
          char &done = seen[static_cast<std::size_t>(cell[axis] - range.first[axis])];
          if (!done)
            visit(layout.index(cell[0], cell[1], cell[2]),
                  layout.centre_m(cell[0], cell[1], cell[2]));
          done = 1;
        }
      }
    }
  }
}

} // namespace fsi::geometry
