#include "geometry/FeatureRegions.hpp"

#include "geometry/ConeSpread.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace fsi::geometry {
namespace {

std::uint64_t directed_edge_key(std::int32_t from, std::int32_t to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) |
         static_cast<std::uint32_t>(to);
}

/// The half-space (x - origin).direction <= 0, direction normalised.
FeatureRegions::HalfSpace behind(const Vec3 &origin_m, const Vec3 &direction) {
  const Vec3 unit = direction.normalized();
  return {unit, unit.dot(origin_m)};
}

/// Grows each half-space so that it holds the centres of the cubes
/// it meets (a normal with a NaN, from a degenerate edge, never excludes anything).
void grow(std::vector<FeatureRegions::HalfSpace> &half_spaces, double half_edge_m,
          double margin_m) {
  for (FeatureRegions::HalfSpace &half : half_spaces) {
    half.limit_m += half_edge_m * half.normal.lpNorm<1>() + margin_m;
    if (!half.normal.allFinite())
      half = {Vec3::Zero(), 0.0};
  }
}

/// Spread of an edge's region without a neighbour face: directions perpendicular to the edge.
Vec3 half_disc_spread(const Vec3 &edge) {
  const Vec3 unit = edge.normalized();
  return (Vec3::Ones() - unit.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
}

/// Spread of the region of edge ab between face abc (normal `normal`) and face b a d (d - b =
/// to_opposite): directions u perpendicular to ab beyond the edge seen from both faces, the
/// arc between the faces' normals (or their opposites, on the concave side). |u_i| is at
/// most |r1_i| + |r1 - r2| on the arc from r1 to r2.
Vec3 wedge_spread(const Vec3 &normal, const Vec3 &to_opposite, const Vec3 &a, const Vec3 &b) {
  constexpr double kFlat = 1e-9;
  const Vec3 n1 = normal.normalized(), n2 = (a - b).cross(to_opposite).normalized();
  const Vec3 beyond1 = (b - a).cross(n1), beyond2 = (a - b).cross(n2); // outward in-plane
  const double s1 = n1.dot(beyond2), s2 = n2.dot(beyond1);
  const Vec3 r1 = s1 >= -kFlat ? n1 : Vec3(-n1);
  Vec3 r2 = s2 >= -kFlat ? n2 : Vec3(-n2);
  if (std::abs(s1) <= kFlat || std::abs(s2) <= kFlat) // flat: the line of both normals
    r2 = r1.dot(n2) >= 0.0 ? n2 : Vec3(-n2);
  const Vec3 spread = (r1.cwiseAbs().array() + (r1 - r2).norm() + 1e-6).min(1.0).matrix();
  return spread.allFinite() ? spread : Vec3(Vec3::Ones());
}

} // namespace

FeatureRegions::FeatureRegions(const PointArray &vertices_m, const TriangleArray &triangles)
    : vertices_m_(vertices_m), triangles_(triangles) {
  const auto n_faces = static_cast<std::size_t>(triangles.rows());
  std::unordered_map<std::uint64_t, std::int32_t> third_vertex; // directed edge -> opposite
  third_vertex.reserve(3 * n_faces);
  std::vector<std::vector<std::int32_t>> neighbours(static_cast<std::size_t>(vertices_m.rows()));
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      third_vertex[directed_edge_key(a, b)] = triangles(t, (k + 2) % 3);
      neighbours[static_cast<std::size_t>(a)].push_back(b);
      neighbours[static_cast<std::size_t>(b)].push_back(a);
    }
  }
  across_edge_.assign(3 * n_faces, -1);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto twin =
          third_vertex.find(directed_edge_key(triangles(t, (k + 1) % 3), triangles(t, k)));
      if (twin != third_vertex.end())
        across_edge_[3 * static_cast<std::size_t>(t) + k] = twin->second;
    }
  }
  first_neighbour_.assign(neighbours.size() + 1, 0);
  for (std::size_t v = 0; v < neighbours.size(); ++v) {
    std::sort(neighbours[v].begin(), neighbours[v].end());
    neighbours[v].erase(std::unique(neighbours[v].begin(), neighbours[v].end()),
                        neighbours[v].end());
    first_neighbour_[v + 1] =
        first_neighbour_[v] + static_cast<std::uint32_t>(neighbours[v].size());
    vertex_neighbours_.insert(vertex_neighbours_.end(), neighbours[v].begin(), neighbours[v].end());
  }
  compute_vertex_spreads();
}

void FeatureRegions::compute_vertex_spreads() {
  // Beyond this many edges the exact spread costs too much; the whole sphere bounds it.
  constexpr std::size_t kMaxEdgesForSpread = 64;
  vertex_spreads_.assign(first_neighbour_.size() - 1, Vec3::Ones());
  std::vector<Vec3> edges;
  for (std::size_t v = 0; v + 1 < first_neighbour_.size(); ++v) {
    if (first_neighbour_[v + 1] - first_neighbour_[v] > kMaxEdgesForSpread)
      continue;
    edges.clear();
    for (std::uint32_t n = first_neighbour_[v]; n < first_neighbour_[v + 1]; ++n)
      edges.push_back(vertex(vertex_neighbours_[n]) - vertex(static_cast<std::int32_t>(v)));
    vertex_spreads_[v] = cone_spread(edges);
  }
}

bool FeatureRegions::TriangleRegions::row_interval(std::size_t k, int axis, const Vec3 &point_m,
                                                   double &lo_m, double &hi_m) const {
  lo_m = -std::numeric_limits<double>::infinity();
  hi_m = std::numeric_limits<double>::infinity();
  for (std::size_t h = k == 0 ? 0 : ends[k - 1]; h < ends[k]; ++h) {
    const HalfSpace &half = half_spaces[h];
    const double along = half.normal[axis];
    // normal.x <= limit with x = point + (t - point[axis]) e_axis: along * t <= rest.
    const double rest_m = half.limit_m - half.normal.dot(point_m) + along * point_m[axis];
    if (along > 0.0)
      hi_m = std::min(hi_m, rest_m / along);
    else if (along < 0.0)
      lo_m = std::max(lo_m, rest_m / along);
    else if (rest_m < 0.0)
      return false;
  }
  return lo_m <= hi_m;
}

Eigen::AlignedBox3d FeatureRegions::TriangleRegions::sweep_box(std::size_t k,
                                                               double distance_m) const {
  // The region of a feature is the feature swept along directions u of its cone, and a
  // point of it within distance_m of the triangle is within distance_m of the feature.
  Eigen::AlignedBox3d box(corners[k == 0 ? 0 : (k - 1) % 3]);
  if (k == 0) {
    box.extend(corners[1]);
    box.extend(corners[2]);
  } else if (k <= 3) {
    box.extend(corners[k % 3]);
  }
  const Vec3 reach_m = distance_m * spreads[k];
  return {box.min() - reach_m, box.max() + reach_m};
}

void FeatureRegions::add_vertex_region(std::int32_t v, TriangleRegions &regions) const {
  const Vec3 origin_m = vertex(v);
  for (std::uint32_t n = first_neighbour_[static_cast<std::size_t>(v)];
       n < first_neighbour_[static_cast<std::size_t>(v) + 1]; ++n)
    regions.half_spaces.push_back(behind(origin_m, vertex(vertex_neighbours_[n]) - origin_m));
}

void FeatureRegions::regions_of(std::int32_t face, double half_edge_m, double margin_m,
                                TriangleRegions &regions) const {
  regions.half_spaces.clear();
  const std::array<std::int32_t, 3> corner_index = {triangles_(face, 0), triangles_(face, 1),
                                                    triangles_(face, 2)};
  const std::array<Vec3, 3> corner = {vertex(corner_index[0]), vertex(corner_index[1]),
                                      vertex(corner_index[2])};
  const Vec3 normal = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
  // Outward in-plane normal of edge k (corner k -> corner k + 1), away from the third corner.
  std::array<Vec3, 3> edge_normal;
  for (int k = 0; k < 3; ++k)
    edge_normal[k] = (corner[(k + 1) % 3] - corner[k]).cross(normal);
  regions.corners = corner;
  for (int k = 0; k < 3; ++k) // region 0: the prism over the face
    regions.half_spaces.push_back(behind(corner[k], edge_normal[k]));
  regions.ends[0] = regions.half_spaces.size();
  regions.spreads[0] = normal.normalized().cwiseAbs();
  for (int k = 0; k < 3; ++k) { // regions 1-3: the edges
    const Vec3 &a = corner[k], &b = corner[(k + 1) % 3];
    regions.half_spaces.push_back(behind(a, a - b));
    regions.half_spaces.push_back(behind(b, b - a));
    regions.half_spaces.push_back(behind(a, -edge_normal[k]));
    const std::int32_t opposite = across_edge_[3 * static_cast<std::size_t>(face) + k];
    if (opposite >= 0) { // the neighbour b, a, d: its own outward normal of edge b -> a
      const Vec3 neighbour_normal = (a - b).cross(vertex(opposite) - b);
      regions.half_spaces.push_back(behind(a, -(a - b).cross(neighbour_normal)));
    }
    regions.spreads[1 + k] =
        opposite >= 0 ? wedge_spread(normal, vertex(opposite) - b, a, b) : half_disc_spread(a - b);
    regions.ends[1 + k] = regions.half_spaces.size();
  }
  for (int k = 0; k < 3; ++k) { // regions 4-6: the vertices
    add_vertex_region(corner_index[k], regions);
    regions.ends[4 + k] = regions.half_spaces.size();
    regions.spreads[4 + k] = vertex_spreads_[static_cast<std::size_t>(corner_index[k])];
  }
  grow(regions.half_spaces, half_edge_m, margin_m);
}

} // namespace fsi::geometry
