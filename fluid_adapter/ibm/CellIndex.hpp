#pragma once
// Spatial index over the cell centres of EulerianCells, built once per mesh (again only when
// the mesh changes). Answers the two questions of the coupling: which cells lie in the
// kernel support of a Lagrangian point (the box |x_c - X|_inf < 2h) and which cell centre is
// nearest to it. A query costs O(log n_cells + cells found), so a step costs O(n_points).
//
// Choice: a KD-tree (nanoflann, searched for boxes by CellIndex itself) rather than a
// uniform bucket grid, measured with tests/fluid_ibm/bench_kernel_stencil.cpp on 300k cells:
// per query the tree takes 2-3.5 us whatever the mesh; a grid sized for the largest cells
// takes 0.4-1.4 us on a uniform mesh but 3.8 us (9x grading) and 11 us (39x grading) for
// points in the refined zone, where the structure is, as it scans every fine cell of its
// coarse buckets. The tree's cost stays bounded on the graded meshes of real cases.

#include "fluid_adapter/ibm/EulerianCells.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace fsi::fluid::ibm {

class CellIndex {
public:
  /// Borrows `cells`, which must outlive the index and stay unchanged.
  explicit CellIndex(const EulerianCells &cells);
  ~CellIndex();
  CellIndex(CellIndex &&) noexcept;
  CellIndex &operator=(CellIndex &&) = delete;

  struct Nearest {
    CellId cell = -1;        ///< -1 when there are no cells
    double distance_m = 0.0; ///< +infinity when there are no cells
  };

  /// Replaces `found` by the cells whose centre c satisfies |c - point|_inf < half_width_m,
  /// in no particular order.
  void cells_in_box(const Vec3 &point_m, double half_width_m, std::vector<CellId> &found) const;
  /// The cell whose centre is nearest to the point (one of them on ties).
  Nearest nearest(const Vec3 &point_m) const;
  /// nearest(), unless the bounding box of the cell centres is farther than beyond_m from the
  /// point: then cell -1 and the distance to that box, a lower bound of the true distance, at
  /// the cost of six comparisons (a rank far from the structure skips its tree searches).
  Nearest nearest_within(const Vec3 &point_m, double beyond_m) const;

  const EulerianCells &cells() const { return cells_; }

private:
  struct Tree;
  const EulerianCells &cells_;
  std::unique_ptr<Tree> tree_;
  Eigen::AlignedBox3d centre_box_m_;
};

} // namespace fsi::fluid::ibm
