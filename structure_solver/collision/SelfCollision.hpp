#pragma once
// Optional self-collision of a sheet (the extension suggested at the end of Sec. 2.5): two
// points of the same sheet closer than d_c are pushed apart symmetrically to distance d_t,
// the correction being spread equally between them. Points that are material neighbours at
// rest (closer than exclusion_factor * d_t) never collide with each other.

#include "common/Types.hpp"

#include <cstddef>
#include <vector>

namespace fsi::structure::collision {

class SelfCollision {
public:
  /// rest_positions_m: the initial (stress-free) positions of the sheet's points. Throws
  /// std::invalid_argument unless 0 < threshold_m <= target_distance_m and
  /// exclusion_factor >= 0.
  SelfCollision(const PointArray &rest_positions_m, double threshold_m, double target_distance_m,
                double exclusion_factor = 2.0);

  /// Moves each colliding pair apart along the line joining them, each point by half of
  /// (d_t - distance), pair after pair (each pair's centroid is unchanged). Returns the number
  /// of pairs corrected. Throws std::invalid_argument if the point count differs from rest.
  std::size_t correct(PointArray &positions_m) const;

  /// Number of point pairs excluded as material neighbours.
  std::size_t n_excluded_pairs() const { return excluded_partners_.size(); }

private:
  bool is_excluded(Eigen::Index i, Eigen::Index j) const;
  /// Unit vector from point i to point j, falling back to the rest direction (or x) when
  /// the two points coincide.
  Vec3 separation_direction(const PointArray &positions_m, Eigen::Index i, Eigen::Index j) const;

  PointArray rest_positions_m_;
  double threshold_m_;
  double target_distance_m_;
  /// Excluded partners j > i of point i: excluded_partners_[offsets_[i] .. offsets_[i+1]).
  std::vector<std::size_t> offsets_;
  std::vector<Eigen::Index> excluded_partners_;
};

} // namespace fsi::structure::collision
