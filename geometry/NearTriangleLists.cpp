#include "geometry/NearTriangleLists.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace fsi::geometry {
namespace {

constexpr float kNoList = -1.0f;
constexpr std::size_t kMaxTriangles = std::size_t{1} << 24;
constexpr std::size_t kHeaderEntries = 2;

/// The largest float not above x: stored distances only ever underestimate.
float round_down(double x) {
  const auto rounded = static_cast<float>(x);
  return static_cast<double>(rounded) > x
             ? std::nextafter(rounded, -std::numeric_limits<float>::infinity())
             : rounded;
}

std::uint32_t float_bits(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

float bits_float(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

Eigen::AlignedBox3d box_of(const NearTriangleLists::Triangle &triangle) {
  Eigen::AlignedBox3d box(triangle[0]);
  box.extend(triangle[1]);
  box.extend(triangle[2]);
  return box;
}

double distance_to_triangle(const Vec3 &p, const NearTriangleLists::Triangle &triangle) {
  return (closest_point_on_triangle(p, triangle[0], triangle[1], triangle[2]).point_m - p).norm();
}

/// The longest cut length, at most max_per_cell, for which the lists of cells with these
/// candidate counts hold at most max_entries entries.
std::size_t fitting_length(const std::vector<std::size_t> &counts, std::size_t max_per_cell,
                           std::size_t max_entries) {
  const auto total = [&](std::size_t length) {
    std::size_t sum = 0;
    for (const std::size_t count : counts)
      sum += kHeaderEntries + std::min(count, length);
    return sum;
  };
  std::size_t length = max_per_cell;
  while (length > 1 && total(length) > max_entries)
    length = length * 3 / 4;
  return length;
}

} // namespace

NearTriangleLists::NearTriangleLists(const VoxelSideGrid &grid,
                                     const std::vector<Triangle> &triangles,
                                     const FeatureRegions &regions, std::size_t max_per_cell,
                                     std::size_t max_entries)
    : layout_(grid.layout()), cells_(layout_.n_cells()) {
  for (std::size_t cell = 0; cell < cells_.size(); ++cell) {
    const VoxelState state = grid.state_of_cell(static_cast<std::int32_t>(cell));
    cells_[cell] = static_cast<std::uint32_t>(state) << kStateShift;
  }
  if (triangles.size() >= kMaxTriangles)
    return;
  store_in_spatial_order(triangles);
  // Near cells hold points within radius of the mesh, so their centres are within
  // radius + h of it; d0 is capped there to bound the lists of cells marked near for safety.
  const double h = layout_.half_diagonal_m();
  const double cap_m = grid.radius_m() + h;
  const std::vector<float> reach_m = list_reaches(grid, cap_m);
  const std::vector<std::int32_t> near_cells = near_cells_in_curve_order(reach_m);
  build_lists(gather(regions, reach_m, near_cells, cap_m + 2.0 * h * (1.0 + 1e-5)), reach_m,
              near_cells, std::max<std::size_t>(max_per_cell, 1),
              std::min<std::size_t>(max_entries, kOffsetMask));
}

std::uint64_t NearTriangleLists::curve_key(std::int32_t cell) const {
  // Morton order: interleaved bits of the cell coordinates.
  const std::array<int, 3> coordinates = layout_.coordinates(cell);
  std::uint64_t key = 0;
  for (int bit = 0; bit < 21; ++bit) {
    for (int axis = 0; axis < 3; ++axis)
      key |= ((static_cast<std::uint64_t>(coordinates[axis]) >> bit) & 1u) << (3 * bit + axis);
  }
  return key;
}

std::vector<std::int32_t>
NearTriangleLists::near_cells_in_curve_order(const std::vector<float> &reach_m) const {
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed;
  for (std::size_t cell = 0; cell < reach_m.size(); ++cell) {
    if (reach_m[cell] >= 0.0f)
      keyed.emplace_back(curve_key(static_cast<std::int32_t>(cell)),
                         static_cast<std::int32_t>(cell));
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::int32_t> cells(keyed.size());
  for (std::size_t rank = 0; rank < keyed.size(); ++rank)
    cells[rank] = keyed[rank].second;
  return cells;
}

void NearTriangleLists::store_in_spatial_order(const std::vector<Triangle> &triangles) {
  std::vector<std::uint64_t> keys(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Vec3 centroid_m = (triangles[t][0] + triangles[t][1] + triangles[t][2]) / 3.0;
    keys[t] = curve_key(
        static_cast<std::int32_t>(std::max<std::int64_t>(layout_.cell_of(centroid_m), 0)));
  }
  faces_.resize(triangles.size());
  std::iota(faces_.begin(), faces_.end(), 0);
  std::stable_sort(faces_.begin(), faces_.end(), [&keys](std::int32_t a, std::int32_t b) {
    return keys[static_cast<std::size_t>(a)] < keys[static_cast<std::size_t>(b)];
  });
  triangles_.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    triangles_[t] = triangles[static_cast<std::size_t>(faces_[t])];
}

std::vector<float> NearTriangleLists::list_reaches(const VoxelSideGrid &grid, double cap_m) const {
  std::vector<float> distance_m(layout_.n_cells(), kNoList);
  for (std::size_t cell = 0; cell < distance_m.size(); ++cell) {
    if (grid.state_of_cell(static_cast<std::int32_t>(cell)) == VoxelState::near_surface)
      distance_m[cell] = static_cast<float>(cap_m);
  }
  for (const Triangle &triangle : triangles_) {
    const Eigen::AlignedBox3d box = box_of(triangle);
    layout_.for_each_cell_near(
        box, cap_m, [&](std::int32_t cell, const Vec3 &centre_m, double box_distance_sq_m2) {
          float &best_m = distance_m[static_cast<std::size_t>(cell)];
          if (best_m != kNoList && box_distance_sq_m2 < double(best_m) * best_m)
            best_m = std::min(best_m, static_cast<float>(distance_to_triangle(centre_m, triangle)));
        });
  }
  // Float round-off of d0 is covered by a margin far below any geometric scale.
  const double extra_m = 2.0 * layout_.half_diagonal_m() * (1.0 + 1e-6);
  for (float &reach : distance_m) {
    if (reach != kNoList)
      reach = static_cast<float>(reach + extra_m);
  }
  return distance_m;
}

std::vector<NearTriangleLists::Candidate>
NearTriangleLists::gather(const FeatureRegions &regions, const std::vector<float> &reach_m,
                          const std::vector<std::int32_t> &near_cells, double max_reach_m) const {
  std::vector<std::uint32_t> rank_of(layout_.n_cells(), 0);
  for (std::size_t rank = 0; rank < near_cells.size(); ++rank)
    rank_of[static_cast<std::size_t>(near_cells[rank])] = static_cast<std::uint32_t>(rank);
  FeatureRegions::TriangleRegions triangle_regions;
  std::vector<Candidate> candidates;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const Eigen::AlignedBox3d box = box_of(triangles_[t]);
    regions.regions_of(faces_[t], 0.5 * layout_.cell_size_m(), 1e-6 * layout_.cell_size_m(),
                       triangle_regions);
    // Only cells that meet a region within the largest reach can take the triangle (plus
    // the cell's half diagonal: a point of the cube may be that much farther).
    triangle_regions.for_each_cell(
        layout_, max_reach_m + layout_.half_diagonal_m(),
        [&](std::int32_t cell, const Vec3 &centre_m) {
          const double reach = reach_m[static_cast<std::size_t>(cell)];
          if (reach < 0.0 || box.squaredExteriorDistance(centre_m) > reach * reach)
            return;
          const double distance = distance_to_triangle(centre_m, triangles_[t]);
          if (distance <= reach)
            candidates.push_back({rank_of[static_cast<std::size_t>(cell)],
                                  static_cast<std::int32_t>(t), round_down(distance)});
        });
  }
  return candidates;
}

void NearTriangleLists::build_lists(std::vector<Candidate> candidates,
                                    const std::vector<float> &reach_m,
                                    const std::vector<std::int32_t> &near_cells,
                                    std::size_t max_per_cell, std::size_t max_entries) {
  std::sort(candidates.begin(), candidates.end(), [](const Candidate &a, const Candidate &b) {
    return a.rank != b.rank ? a.rank < b.rank : a.centre_distance_m < b.centre_distance_m;
  });
  std::vector<std::size_t> counts(near_cells.size(), 0);
  for (const Candidate &candidate : candidates)
    ++counts[candidate.rank];
  max_per_cell = fitting_length(counts, max_per_cell, max_entries);
  const Candidate *next = candidates.data();
  for (std::size_t rank = 0; rank < near_cells.size(); ++rank) {
    const auto cell = static_cast<std::size_t>(near_cells[rank]);
    append_list(near_cells[rank], next, next + counts[rank], reach_m[cell], max_per_cell);
    next += counts[rank];
  }
  entries_.shrink_to_fit();
}

void NearTriangleLists::append_list(std::int32_t cell, const Candidate *begin, const Candidate *end,
                                    float reach_m, std::size_t max_per_cell) {
  const auto length = std::min<std::size_t>(static_cast<std::size_t>(end - begin), max_per_cell);
  const bool cut = begin + length < end;
  n_cut_lists_ += cut ? 1 : 0;
  const float reach = cut ? begin[length].centre_distance_m : reach_m;
  cells_[static_cast<std::size_t>(cell)] |= static_cast<std::uint32_t>(entries_.size());
  entries_.push_back(float_bits(reach));
  entries_.push_back(static_cast<std::uint32_t>(length));
  for (const Candidate *c = begin; c < begin + length; ++c) {
    const auto fraction = static_cast<std::uint32_t>(
        std::clamp(std::floor(255.0 * double(c->centre_distance_m) / double(reach)), 0.0, 255.0));
    entries_.push_back(static_cast<std::uint32_t>(c->triangle) << 8 | fraction);
  }
}

NearTriangleLists::Hit NearTriangleLists::nearest(const Vec3 &point_m) const {
  Hit hit;
  Vec3 centre_m;
  const std::int64_t cell = layout_.cell_of(point_m, centre_m);
  if (cell < 0)
    return hit;
  const std::uint32_t word = cells_[static_cast<std::size_t>(cell)];
  if (static_cast<VoxelState>(word >> kStateShift) != VoxelState::near_surface || entries_.empty())
    return hit;
  const std::uint32_t header = word & kOffsetMask;
  const double reach_m = bits_float(entries_[header]);
  const std::uint32_t end = header + kHeaderEntries + entries_[header + 1];
  const double offset_m = (point_m - centre_m).norm();
  double best_sq_m2 = std::numeric_limits<double>::infinity();
  std::int32_t best = -1;
  for (std::uint32_t e = header + kHeaderEntries; e < end; ++e) {
    const double lower_bound_m = (entries_[e] & 0xff) * (reach_m / 255.0) - offset_m;
    if (lower_bound_m > 0.0 && lower_bound_m * lower_bound_m >= best_sq_m2) {
      hit.exact = true; // this and every later triangle are at least as far
      break;
    }
    const auto stored = static_cast<std::int32_t>(entries_[e] >> 8);
    const Triangle &t = triangles_[static_cast<std::size_t>(stored)];
    const TrianglePoint closest = closest_point_on_triangle(point_m, t[0], t[1], t[2]);
    const double distance_sq_m2 = (closest.point_m - point_m).squaredNorm();
    if (distance_sq_m2 < best_sq_m2) {
      best_sq_m2 = distance_sq_m2;
      best = stored;
      hit.closest = closest;
    }
  }
  if (!hit.exact) { // unlisted triangles are farther than reach - offset from the point
    const double margin_m = reach_m - offset_m;
    hit.exact = margin_m >= 0.0 && best_sq_m2 <= margin_m * margin_m;
  }
  hit.exact = hit.exact && best >= 0;
  hit.face = best >= 0 ? faces_[static_cast<std::size_t>(best)] : -1;
  hit.distance_sq_m2 = best_sq_m2;
  return hit;
}

} // namespace fsi::geometry
