#include "geometry/FreePassage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace fsi::geometry {
namespace {

constexpr std::size_t kMaxGridPoints = 20'000'000;

/// The grid and the per-point state of the widest-path search.
class WidestPathSearch {
public:
  WidestPathSearch(const RigidSurface &solid, const PassageRegion &region, double spacing_m)
      : solid_(solid), origin_m_(region.bounds_m.min()), h_(spacing_m) {
    const Vec3 size_m = region.bounds_m.sizes();
    std::size_t n_points = 1;
    for (int a = 0; a < 3; ++a) {
      n_[a] = static_cast<int>(std::floor(size_m[a] / h_ * (1.0 + 1e-12))) + 1;
      n_points *= static_cast<std::size_t>(n_[a]);
      if (n_points > kMaxGridPoints)
        throw std::invalid_argument("find_free_passage: the grid would exceed 20 million points; use a "
                                    "larger spacing or a smaller box");
    }
    kind_.assign(n_points, Kind::outside);
    for (std::size_t index = 0; index < n_points; ++index) {
      const Vec3 p = position(index);
      if (!region.allowed(p))
        continue;
      kind_[index] = region.end(p) ? Kind::end : Kind::allowed;
      if (region.start(p))
        starts_.push_back(index);
      n_allowed_ += 1;
      n_ends_ += kind_[index] == Kind::end ? 1 : 0;
    }
    lower_bound_.assign(n_points, -std::numeric_limits<float>::infinity());
    best_.assign(n_points, 0.0f);
    exact_.assign(n_points, false);
    done_.assign(n_points, false);
    previous_.assign(n_points, -1);
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        for (int dk = -1; dk <= 1; ++dk)
          if (di != 0 || dj != 0 || dk != 0)
            steps_.push_back({{di, dj, dk}, static_cast<float>(h_ * std::sqrt(di * di + dj * dj + dk * dk))});
  }

  FreePassage run() {
    FreePassage result;
    result.error_bound_m = std::sqrt(3.0) * h_;
    result.n_allowed_points = n_allowed_;
    if (starts_.empty() || n_ends_ == 0) {
      result.status = starts_.empty() ? FreePassage::Status::no_start : FreePassage::Status::no_end;
      return result;
    }
    const std::int64_t reached = search();
    result.n_distance_queries = n_queries_;
    if (reached < 0)
      return result; // blocked
    describe_path(static_cast<std::size_t>(reached), result);
    return result;
  }

private:
  enum class Kind : std::uint8_t { outside, allowed, end };
  struct Step {
    std::array<int, 3> offset;
    float length_m;
  };
  using Entry = std::pair<float, std::size_t>; // bottleneck so far, point

  Vec3 position(std::size_t index) const {
    const auto i = static_cast<int>(index % n_[0]), j = static_cast<int>(index / n_[0] % n_[1]),
               k = static_cast<int>(index / n_[0] / n_[1]);
    return origin_m_ + h_ * Vec3(i, j, k);
  }

  float clearance(std::size_t index) {
    ++n_queries_;
    exact_[index] = true;
    lower_bound_[index] = static_cast<float>(std::max(0.0, solid_.distance(position(index)).signed_distance_m));
    return lower_bound_[index];
  }

  /// The bottleneck of the path to `to` through `from`, when the best path to `from` has
  /// `bottleneck`: queries the clearance of `to` only if its lower bound could lower it.
  float through(std::size_t from, std::size_t to, float step_m, float bottleneck) {
    if (!exact_[to]) {
      lower_bound_[to] = std::max(lower_bound_[to], lower_bound_[from] - step_m);
      if (lower_bound_[to] < bottleneck)
        clearance(to);
    }
    return std::min(bottleneck, lower_bound_[to]);
  }

  /// Dijkstra's algorithm on the widest path; returns the first end point settled, or -1.
  std::int64_t search() {
    std::priority_queue<Entry> heap; // largest bottleneck first
    for (const std::size_t s : starts_) {
      best_[s] = clearance(s);
      if (best_[s] > 0.0f)
        heap.push({best_[s], s});
    }
    while (!heap.empty()) {
      const auto [bottleneck, point] = heap.top();
      heap.pop();
      if (done_[point])
        continue;
      done_[point] = true;
      if (kind_[point] == Kind::end)
        return static_cast<std::int64_t>(point);
      const auto i = static_cast<int>(point % n_[0]), j = static_cast<int>(point / n_[0] % n_[1]),
                 k = static_cast<int>(point / n_[0] / n_[1]);
      for (const Step &step : steps_) {
        const int ni = i + step.offset[0], nj = j + step.offset[1], nk = k + step.offset[2];
        if (ni < 0 || nj < 0 || nk < 0 || ni >= n_[0] || nj >= n_[1] || nk >= n_[2])
          continue;
        const std::size_t next = (static_cast<std::size_t>(nk) * n_[1] + nj) * n_[0] + ni;
        if (kind_[next] == Kind::outside || done_[next])
          continue;
        const float wide = through(point, next, step.length_m, bottleneck);
        if (wide > 0.0f && wide > best_[next]) {
          best_[next] = wide;
          previous_[next] = static_cast<std::int32_t>(point);
          heap.push({wide, next});
        }
      }
    }
    return -1;
  }

  /// The path back from the end point, and its first point of smallest clearance (there the
  /// bottleneck dropped to its final value, so that point's clearance was queried).
  void describe_path(std::size_t end, FreePassage &result) const {
    std::vector<std::size_t> path;
    for (std::int32_t p = static_cast<std::int32_t>(end); p >= 0; p = previous_[static_cast<std::size_t>(p)])
      path.push_back(static_cast<std::size_t>(p));
    std::reverse(path.begin(), path.end());
    const float bottleneck = best_[end];
    result.status = FreePassage::Status::passes;
    result.diameter_m = 2.0 * static_cast<double>(bottleneck);
    for (const std::size_t p : path)
      result.path_m.push_back(position(p));
    const auto first_narrowest =
        std::find_if(path.begin(), path.end(), [&](std::size_t p) { return best_[p] <= bottleneck; });
    result.bottleneck_m = position(*first_narrowest);
  }

  const RigidSurface &solid_;
  Vec3 origin_m_;
  double h_;
  std::array<int, 3> n_{};
  std::vector<Kind> kind_;
  std::vector<std::size_t> starts_;
  std::size_t n_allowed_ = 0, n_ends_ = 0, n_queries_ = 0;
  std::vector<float> lower_bound_; ///< of the clearance; the clearance itself once exact_
  std::vector<float> best_;        ///< largest bottleneck of a path found so far
  std::vector<bool> exact_, done_;
  std::vector<std::int32_t> previous_;
  std::vector<Step> steps_;
};

} // namespace

PointPredicate inside_any_box(std::vector<Eigen::AlignedBox3d> boxes_m) {
  return [boxes_m = std::move(boxes_m)](const Vec3 &p) {
    return std::any_of(boxes_m.begin(), boxes_m.end(), [&](const Eigen::AlignedBox3d &box) { return box.contains(p); });
  };
}

std::string FreePassage::status_name(Status status) {
  switch (status) {
  case Status::passes:
    return "passes";
  case Status::blocked:
    return "blocked";
  case Status::no_start:
    return "no start point";
  case Status::no_end:
    return "no end point";
  }
  return "unknown";
}

FreePassage find_free_passage(const RigidSurface &solid, const PassageRegion &region, double spacing_m) {
  if (!(spacing_m > 0.0))
    throw std::invalid_argument("find_free_passage: the spacing must be positive");
  if (region.bounds_m.isEmpty())
    throw std::invalid_argument("find_free_passage: the region's box is empty");
  return WidestPathSearch(solid, region, spacing_m).run();
}

} // namespace fsi::geometry
