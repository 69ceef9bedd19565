#include "structure_solver/collision/SelfCollision.hpp"

#include "geometry/SpatialHashGrid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fsi::structure::collision {
namespace {

/// Pairs already at d_c up to round-off are not corrected again.
constexpr double kSettledTolerance_m = 1e-12;

} // namespace

SelfCollision::SelfCollision(const PointArray &rest_positions_m, double threshold_m,
                             double target_distance_m, double exclusion_factor)
    : rest_positions_m_(rest_positions_m), threshold_m_(threshold_m),
      target_distance_m_(target_distance_m) {
  if (!(threshold_m > 0.0) || !(target_distance_m >= threshold_m)) {
    throw std::invalid_argument("self-collision needs 0 < threshold_m (" +
                                std::to_string(threshold_m) + ") <= target_distance_m (" +
                                std::to_string(target_distance_m) + ").");
  }
  if (!(exclusion_factor >= 0.0)) {
    throw std::invalid_argument("self-collision exclusion_factor = " +
                                std::to_string(exclusion_factor) + " must be non-negative.");
  }
  const auto n_points = static_cast<std::size_t>(rest_positions_m.rows());
  offsets_.assign(n_points + 1, 0);
  const double exclusion_m = exclusion_factor * target_distance_m;
  if (exclusion_m <= 0.0 || n_points == 0)
    return;
  const geometry::SpatialHashGrid grid(rest_positions_m_, exclusion_m);
  const auto pairs = grid.pairs_within(exclusion_m); // sorted by i, then j
  for (const auto &[i, j] : pairs) {
    ++offsets_[static_cast<std::size_t>(i) + 1];
    excluded_partners_.push_back(j);
  }
  for (std::size_t i = 0; i < n_points; ++i)
    offsets_[i + 1] += offsets_[i];
}

bool SelfCollision::is_excluded(Eigen::Index i, Eigen::Index j) const {
  const auto begin = excluded_partners_.begin() + static_cast<std::ptrdiff_t>(offsets_[i]);
  const auto end = excluded_partners_.begin() + static_cast<std::ptrdiff_t>(offsets_[i + 1]);
  return std::binary_search(begin, end, j);
}

Vec3 SelfCollision::separation_direction(const PointArray &positions_m, Eigen::Index i,
                                         Eigen::Index j) const {
  const Vec3 current = (positions_m.row(j) - positions_m.row(i)).transpose();
  if (current.norm() > 0.0)
    return current.normalized();
  const Vec3 rest = (rest_positions_m_.row(j) - rest_positions_m_.row(i)).transpose();
  return rest.norm() > 0.0 ? Vec3(rest.normalized()) : Vec3::UnitX();
}

std::size_t SelfCollision::correct(PointArray &positions_m) const {
  if (positions_m.rows() != rest_positions_m_.rows()) {
    throw std::invalid_argument("SelfCollision::correct: got " +
                                std::to_string(positions_m.rows()) + " points, the sheet has " +
                                std::to_string(rest_positions_m_.rows()) + ".");
  }
  if (positions_m.rows() < 2)
    return 0;
  const geometry::SpatialHashGrid grid(positions_m, threshold_m_);
  const auto candidates = grid.pairs_within(threshold_m_);
  std::size_t n_corrected = 0;
  for (const auto &[i, j] : candidates) {
    if (is_excluded(i, j))
      continue;
    // Positions may have moved in an earlier pair: measure again.
    const double distance_m = (positions_m.row(j) - positions_m.row(i)).norm();
    if (!(distance_m < threshold_m_ - kSettledTolerance_m))
      continue;
    const Vec3 half_shift_m =
        0.5 * (target_distance_m_ - distance_m) * separation_direction(positions_m, i, j);
    positions_m.row(i) -= half_shift_m.transpose();
    positions_m.row(j) += half_shift_m.transpose();
    ++n_corrected;
  }
  return n_corrected;
}

} // namespace fsi::structure::collision
