#include "structure_solver/collision/CorrectionSpread.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace fsi::structure::collision {

CorrectionSpread::CorrectionSpread(int n1, int n2, int radius_points) : n1_(n1), n2_(n2), radius_(radius_points) {
  if (n1 < 1 || n2 < 1)
    throw std::invalid_argument("CorrectionSpread: grid " + std::to_string(n1) + " x " + std::to_string(n2) +
                                " has no points");
  if (radius_points < 1)
    throw std::invalid_argument("CorrectionSpread: radius_points = " + std::to_string(radius_points) +
                                " must be at least 1 (0 is no spread: do not build one)");
}

std::size_t CorrectionSpread::apply(const PointArray &before, PointArray &after) const {
  const Eigen::Index n = static_cast<Eigen::Index>(n1_) * n2_;
  if (before.rows() != n || after.rows() != n)
    throw std::invalid_argument("CorrectionSpread: " + std::to_string(before.rows()) + " and " +
                                std::to_string(after.rows()) + " points for a grid of " + std::to_string(n));
  const PointArray moves = after - before;
  std::vector<char> corrected(static_cast<std::size_t>(n), 0);
  std::vector<Eigen::Index> sources;
  for (Eigen::Index i = 0; i < n; ++i)
    if (moves.row(i).squaredNorm() > 0.0 && moves.row(i).allFinite()) {
      corrected[static_cast<std::size_t>(i)] = 1;
      sources.push_back(i);
    }
  if (sources.empty())
    return 0;
  PointArray sum = PointArray::Zero(n, 3);
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(n);
  const double reach = radius_ + 1.0;
  for (const Eigen::Index i : sources) {
    const int i1 = static_cast<int>(i / n2_), i2 = static_cast<int>(i % n2_);
    for (int j1 = std::max(0, i1 - radius_); j1 <= std::min(n1_ - 1, i1 + radius_); ++j1)
      for (int j2 = std::max(0, i2 - radius_); j2 <= std::min(n2_ - 1, i2 + radius_); ++j2) {
        const Eigen::Index j = static_cast<Eigen::Index>(j1) * n2_ + j2;
        if (corrected[static_cast<std::size_t>(j)])
          continue;
        const double w = 1.0 - std::hypot(j1 - i1, j2 - i2) / reach;
        if (w <= 0.0)
          continue;
        // Only to a neighbour in front of the wall the point was moved off (behind the plane
        // through the moved point across the move by less than twice the move: a sheet lying
        // on the wall is behind it by the move): a rag folded round a nose has grid neighbours
        // on the nose's other face, which this move would push into it.
        const double move_m = moves.row(i).norm();
        if ((before.row(j) - after.row(i)).dot(moves.row(i)) < -2.0 * move_m * move_m)
          continue;
        sum.row(j) += w * moves.row(i);
        weight[j] += w;
      }
  }
  std::size_t spread = 0;
  for (Eigen::Index j = 0; j < n; ++j)
    if (weight[j] > 0.0) {
      after.row(j) += sum.row(j) / std::max(1.0, weight[j]);
      ++spread;
    }
  return spread;
}

} // namespace fsi::structure::collision
