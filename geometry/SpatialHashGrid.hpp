#pragma once
// Uniform-grid spatial hash over a point cloud: finds all pairs closer than a radius in
// O(N) for roughly uniform clouds (used by the self-collision of a sheet).

#include "common/Types.hpp"

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fsi::geometry {

class SpatialHashGrid {
public:
  using IndexPair = std::pair<Eigen::Index, Eigen::Index>;

  /// Hashes the points into cubic cells of edge cell_size_m (> 0). Non-finite points are
  /// left out.
  SpatialHashGrid(const PointArray &points_m, double cell_size_m);

  /// Every pair (i, j), i < j, with |x_i - x_j| < radius_m, sorted by i then j.
  /// Requires radius_m <= cell_size_m.
  std::vector<IndexPair> pairs_within(double radius_m) const;

private:
  struct CellKey {
    std::int64_t x, y, z;
    bool operator==(const CellKey &other) const {
      return x == other.x && y == other.y && z == other.z;
    }
  };
  struct CellKeyHash {
    std::size_t operator()(const CellKey &key) const;
  };

  CellKey key_of(Eigen::Index i) const;
  /// Appends the partners j > i of point i found in the cell `key`.
  void collect_partners(Eigen::Index i, const CellKey &key, double radius_sq_m2,
                        std::vector<IndexPair> &pairs) const;

  const PointArray &points_m_;
  double cell_size_m_;
  std::vector<Eigen::Index> sorted_points_; ///< point indices grouped by cell
  std::unordered_map<CellKey, std::pair<std::size_t, std::size_t>, CellKeyHash> cell_ranges_;
};

} // namespace fsi::geometry
