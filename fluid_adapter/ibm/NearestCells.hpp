#pragma once
// For each Lagrangian point, the nearest Eulerian cell centre. It fixes the kernel width h of
// the point (cbrt of that cell's volume: "h is the Eulerian mesh size", taken locally) and
// the cell used by the closest-cell interpolation of Sec. 2.3.
//
// Decomposed meshes: every rank finds its own nearest cell; the point then belongs to the
// rank with the smallest distance (the lowest rank on ties, as MPI_MINLOC), and all ranks
// must use that rank's width so that their partial sums add up. The caller exchanges
// distance_m() and kernel_width_m() between ranks and folds each other rank in with
// merge_other_rank(). On one process nothing needs merging.

#include "fluid_adapter/ibm/CellIndex.hpp"

#include <vector>

namespace fsi::fluid::ibm {

class NearestCells {
public:
  /// Nearest cell of `index` for each row of points_m (n x 3, m); `rank` is this process's
  /// MPI rank (0 on one process).
  NearestCells(const CellIndex &index, const PointArray &points_m, int rank = 0);

  Eigen::Index n_points() const { return distance_m_.size(); }
  /// Nearest cell on this rank, or -1 when the point belongs to another rank.
  const std::vector<CellId> &cell() const { return cell_; }
  /// Distance (m) from the point to the centre of its nearest cell (over the ranks merged).
  const Eigen::VectorXd &distance_m() const { return distance_m_; }
  /// Kernel width h (m) of each point: cbrt(volume) of its nearest cell.
  const Eigen::VectorXd &kernel_width_m() const { return kernel_width_m_; }
  bool owns(Eigen::Index point) const { return cell_[static_cast<std::size_t>(point)] >= 0; }
  /// Rank that holds the nearest cell of each point.
  const std::vector<int> &owner_rank() const { return owner_rank_; }

  /// Folds in the distances and widths that rank other_rank found for the same points (its
  /// values as constructed, before any merge of its own): it
  /// takes a point when it is nearer than the current owner, or as near and of lower rank.
  /// The result does not depend on the order in which ranks are merged. Throws
  /// std::invalid_argument when the sizes differ from n_points().
  void merge_other_rank(int other_rank, const Eigen::VectorXd &other_distance_m,
                        const Eigen::VectorXd &other_kernel_width_m);

private:
  std::vector<CellId> cell_;
  std::vector<int> owner_rank_;
  Eigen::VectorXd distance_m_;
  Eigen::VectorXd kernel_width_m_;
};

} // namespace fsi::fluid::ibm
