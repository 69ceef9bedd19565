#include "geometry/TriangleBvh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace fsi::geometry {
namespace {

constexpr std::uint32_t kLeafSize = 4;

float round_down(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}

float round_up(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

} // namespace

TriangleBvh::TriangleBvh(const std::vector<Triangle> &triangles) {
  std::vector<Vec3> centroids(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    centroids[t] = (triangles[t][0] + triangles[t][1] + triangles[t][2]) / 3.0;
  face_.resize(triangles.size());
  std::iota(face_.begin(), face_.end(), 0);
  nodes_.reserve(2 * triangles.size() / kLeafSize + 1);
  if (!triangles.empty())
    build(0, static_cast<std::uint32_t>(triangles.size()), triangles, centroids);
  triangles_.resize(triangles.size());
  slot_.resize(triangles.size());
  for (std::size_t s = 0; s < face_.size(); ++s) {
    triangles_[s] = triangles[static_cast<std::size_t>(face_[s])];
    slot_[static_cast<std::size_t>(face_[s])] = static_cast<std::uint32_t>(s);
  }
}

std::uint32_t TriangleBvh::build(std::uint32_t begin, std::uint32_t end,
                                 const std::vector<Triangle> &triangles,
                                 const std::vector<Vec3> &centroids) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Eigen::AlignedBox3d box, centre_box;
  for (std::uint32_t s = begin; s < end; ++s) {
    const auto face = static_cast<std::size_t>(face_[s]);
    for (const Vec3 &corner : triangles[face])
      box.extend(corner);
    centre_box.extend(centroids[face]);
  }
  for (int axis = 0; axis < 3; ++axis) {
    nodes_[index].lo[axis] = round_down(box.min()[axis]);
    nodes_[index].hi[axis] = round_up(box.max()[axis]);
  }
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  int axis = 0;
  centre_box.sizes().maxCoeff(&axis);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(face_.begin() + begin, face_.begin() + middle, face_.begin() + end,
                   [&](std::int32_t a, std::int32_t b) {
                     return centroids[static_cast<std::size_t>(a)][axis] <
                            centroids[static_cast<std::size_t>(b)][axis];
                   });
  build(begin, middle, triangles, centroids);
  const std::uint32_t second = build(middle, end, triangles, centroids);
  nodes_[index].first = second;
  nodes_[index].count = 0;
  return index;
}

double TriangleBvh::box_distance_sq(const Node &node, const Vec3 &p) const {
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double below = node.lo[axis] - p[axis], above = p[axis] - node.hi[axis];
    const double gap = std::max({below, above, 0.0});
    sum += gap * gap;
  }
  return sum;
}

void TriangleBvh::test_triangle(std::uint32_t slot, const Vec3 &p, Nearest &best) const {
  const Triangle &t = triangles_[slot];
  const TrianglePoint closest = closest_point_on_triangle(p, t[0], t[1], t[2]);
  const double distance_sq_m2 = (closest.point_m - p).squaredNorm();
  if (distance_sq_m2 < best.distance_sq_m2) {
    best.face = face_[slot];
    best.closest = closest;
    best.distance_sq_m2 = distance_sq_m2;
  }
}

TriangleBvh::Nearest TriangleBvh::nearest(const Vec3 &point_m, std::int32_t start_face) const {
  Nearest best;
  best.distance_sq_m2 = std::numeric_limits<double>::infinity();
  if (start_face >= 0)
    test_triangle(slot_[static_cast<std::size_t>(start_face)], point_m, best);
  search(point_m, best);
  return best;
}

TriangleBvh::Nearest TriangleBvh::nearest_within(const Vec3 &point_m, double max_distance_m) const {
  // The bound is on sqrt(distance_sq_m2), inclusive: search a little beyond its square (which
  // rounds either way), then keep the nearest triangle only if it is within the bound.
  Nearest best;
  const double searched_m = max_distance_m * (1.0 + 8.0 * std::numeric_limits<double>::epsilon());
  best.distance_sq_m2 = std::nextafter(searched_m * searched_m, std::numeric_limits<double>::infinity());
  search(point_m, best);
  if (best.face < 0 || !(std::sqrt(best.distance_sq_m2) <= max_distance_m))
    return Nearest{-1, TrianglePoint{}, std::numeric_limits<double>::infinity()};
  return best;
}

void TriangleBvh::search(const Vec3 &point_m, Nearest &best) const {
  if (nodes_.empty())
    return;
  // Depth-first, nearer child first; a stack entry keeps its box distance to re-check it
  // against the best distance when it is popped. Each level adds at most one entry.
  struct Pending {
    std::uint32_t node;
    double distance_sq_m2;
  };
  std::array<Pending, 128> stack;
  std::size_t top = 0;
  stack[top++] = {0, box_distance_sq(nodes_[0], point_m)};
  while (top > 0) {
    const Pending pending = stack[--top];
    if (pending.distance_sq_m2 >= best.distance_sq_m2)
      continue;
    const Node &node = nodes_[pending.node];
    if (node.count > 0) {
      for (std::uint32_t slot = node.first; slot < node.first + node.count; ++slot)
        test_triangle(slot, point_m, best);
      continue;
    }
    Pending near{pending.node + 1, box_distance_sq(nodes_[pending.node + 1], point_m)};
    Pending far{node.first, box_distance_sq(nodes_[node.first], point_m)};
    if (far.distance_sq_m2 < near.distance_sq_m2)
      std::swap(near, far);
    if (far.distance_sq_m2 < best.distance_sq_m2)
      stack[top++] = far;
    if (near.distance_sq_m2 < best.distance_sq_m2)
      stack[top++] = near;
  }
}

} // namespace fsi::geometry
