#include "geometry/SpatialHashGrid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace fsi::geometry {

std::size_t SpatialHashGrid::CellKeyHash::operator()(const CellKey &key) const {
  // Large primes (Teschner et al. 2003) mixing the three cell coordinates.
  const auto x = static_cast<std::uint64_t>(key.x), y = static_cast<std::uint64_t>(key.y),
             z = static_cast<std::uint64_t>(key.z);
  return static_cast<std::size_t>(x * 73856093ULL ^ y * 19349663ULL ^ z * 83492791ULL);
}

SpatialHashGrid::SpatialHashGrid(const PointArray &points_m, double cell_size_m)
    : points_m_(points_m), cell_size_m_(cell_size_m) {
  if (!(cell_size_m > 0.0)) {
    throw std::invalid_argument("SpatialHashGrid: cell_size_m must be positive.");
  }
  std::vector<std::pair<CellKey, Eigen::Index>> keyed;
  keyed.reserve(static_cast<std::size_t>(points_m.rows()));
  for (Eigen::Index i = 0; i < points_m.rows(); ++i) {
    if (points_m.row(i).allFinite())
      keyed.push_back({key_of(i), i});
  }
  std::sort(keyed.begin(), keyed.end(), [](const auto &a, const auto &b) {
    return std::tie(a.first.x, a.first.y, a.first.z, a.second) <
           std::tie(b.first.x, b.first.y, b.first.z, b.second);
  });
  sorted_points_.reserve(keyed.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    sorted_points_.push_back(keyed[k].second);
    auto [range, inserted] = cell_ranges_.try_emplace(keyed[k].first, k, k + 1);
    if (!inserted)
      range->second.second = k + 1;
  }
}

SpatialHashGrid::CellKey SpatialHashGrid::key_of(Eigen::Index i) const {
  return {static_cast<std::int64_t>(std::floor(points_m_(i, 0) / cell_size_m_)),
          static_cast<std::int64_t>(std::floor(points_m_(i, 1) / cell_size_m_)),
          static_cast<std::int64_t>(std::floor(points_m_(i, 2) / cell_size_m_))};
}

std::vector<SpatialHashGrid::IndexPair> SpatialHashGrid::pairs_within(double radius_m) const {
  if (radius_m > cell_size_m_) {
    throw std::invalid_argument("SpatialHashGrid::pairs_within: radius exceeds the cell size.");
  }
  std::vector<IndexPair> pairs;
  const double radius_sq_m2 = radius_m * radius_m;
  for (Eigen::Index i : sorted_points_) {
    const CellKey home = key_of(i);
    for (std::int64_t dz = -1; dz <= 1; ++dz) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          collect_partners(i, {home.x + dx, home.y + dy, home.z + dz}, radius_sq_m2, pairs);
        }
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

void SpatialHashGrid::collect_partners(Eigen::Index i, const CellKey &key, double radius_sq_m2,
                                       std::vector<IndexPair> &pairs) const {
  const auto found = cell_ranges_.find(key);
  if (found == cell_ranges_.end())
    return;
  for (std::size_t k = found->second.first; k < found->second.second; ++k) {
    const Eigen::Index j = sorted_points_[k];
    if (j > i && (points_m_.row(j) - points_m_.row(i)).squaredNorm() < radius_sq_m2) {
      pairs.emplace_back(i, j);
    }
  }
}

} // namespace fsi::geometry
