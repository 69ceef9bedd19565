#include "geometry/PlaneSection.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace fsi::geometry {
namespace {

/// The plane's 2-D frame: origin on the plane (on the limiting line when there is one),
/// u along the half-plane's direction, v = n x u, so the kept half-plane is u >= 0.
struct PlaneFrame {
  Vec3 origin_m, normal, u, v;

  Eigen::Vector2d coordinates(const Vec3 &x) const { return {(x - origin_m).dot(u), (x - origin_m).dot(v)}; }
};

PlaneFrame make_frame(const SectionPlane &plane, const std::optional<HalfPlaneLimit> &limit) {
  if (!(plane.normal.norm() > 0.0))
    throw std::invalid_argument("plane_section: the plane's normal is zero");
  PlaneFrame frame;
  frame.normal = plane.normal.normalized();
  const auto onto_plane = [&](const Vec3 &w) { return Vec3(w - w.dot(frame.normal) * frame.normal); };
  frame.origin_m = plane.point_m;
  Vec3 along = frame.normal.unitOrthogonal();
  if (limit) {
    frame.origin_m = plane.point_m + onto_plane(limit->point_m - plane.point_m);
    along = onto_plane(limit->direction);
    if (!(along.norm() > 0.0))
      throw std::invalid_argument("plane_section: the half-plane's direction is along the plane's normal");
  }
  frame.u = along.normalized();
  frame.v = frame.normal.cross(frame.u);
  return frame;
}

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

/// One triangle's piece of the section: from the crossing of mesh edge `from_edge` to that
/// of `to_edge`, directed so that the material is on its left seen from the normal's side.
struct Segment {
  std::uint64_t from_edge, to_edge;
  Vec3 from_m, to_m;
};

/// Twice the signed area swept from the origin by the part of segment ab with u >= 0: the
/// closing pieces a clipped loop gains along the line u = 0 pass through the origin and add
/// nothing, so summing this over a loop's segments gives its restricted area.
double clipped_twice_area(Eigen::Vector2d a, Eigen::Vector2d b, bool clip) {
  if (clip) {
    if (a.x() < 0.0 && b.x() < 0.0)
      return 0.0;
    if (a.x() < 0.0 || b.x() < 0.0) {
      const Eigen::Vector2d cut = a + (b - a) * (a.x() / (a.x() - b.x()));
      (a.x() < 0.0 ? a : b) = Eigen::Vector2d(0.0, cut.y());
    }
  }
  return a.x() * b.y() - a.y() * b.x();
}

std::vector<Segment> cut_triangles(const TriangleSoup &soup, const PlaneFrame &frame) {
  const Eigen::VectorXd height_m = (soup.vertices_m.rowwise() - frame.origin_m.transpose()) * frame.normal;
  const auto crossing = [&](int a, int b) { // a and b on opposite sides; same point from either triangle
    if (a > b)
      std::swap(a, b);
    const double t = height_m[a] / (height_m[a] - height_m[b]);
    return Vec3(soup.vertices_m.row(a).transpose() + t * (soup.vertices_m.row(b) - soup.vertices_m.row(a)).transpose());
  };
  std::vector<Segment> segments;
  for (Eigen::Index t = 0; t < soup.triangles.rows(); ++t) {
    int n_above = 0;
    for (int k = 0; k < 3; ++k)
      n_above += height_m[soup.triangles(t, k)] >= 0.0 ? 1 : 0;
    if (n_above == 0 || n_above == 3)
      continue;
    // The corner alone on its side is k; the plane crosses edges (k, k+1) and (k-1, k).
    int k = 0;
    while ((height_m[soup.triangles(t, k)] >= 0.0) != (n_above == 1))
      ++k;
    const int lone = soup.triangles(t, k), next = soup.triangles(t, (k + 1) % 3),
              previous = soup.triangles(t, (k + 2) % 3);
    Segment s{edge_key(lone, next), edge_key(previous, lone), crossing(lone, next), crossing(previous, lone)};
    if (n_above == 2) { // the lone corner is below: the material's left is the other way
      std::swap(s.from_edge, s.to_edge);
      std::swap(s.from_m, s.to_m);
    }
    segments.push_back(s);
  }
  return segments;
}

} // namespace

PlaneSection plane_section(const TriangleSoup &soup, const SectionPlane &plane,
                           const std::optional<HalfPlaneLimit> &limit) {
  const PlaneFrame frame = make_frame(plane, limit);
  const std::vector<Segment> segments = cut_triangles(soup, frame);
  std::unordered_map<std::uint64_t, std::size_t> starting_at; // mesh edge -> the segment leaving it
  starting_at.reserve(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s)
    starting_at.emplace(segments[s].from_edge, s);

  // Walk the open chains from their first segment (no segment leads into it), then the loops.
  std::vector<bool> has_predecessor(segments.size(), false);
  for (const Segment &s : segments) {
    const auto next = starting_at.find(s.to_edge);
    if (next != starting_at.end())
      has_predecessor[next->second] = true;
  }
  std::vector<std::size_t> order;
  for (const bool heads : {true, false})
    for (std::size_t s = 0; s < segments.size(); ++s)
      if (has_predecessor[s] != heads)
        order.push_back(s);

  PlaneSection section;
  std::vector<bool> used(segments.size(), false);
  for (const std::size_t first : order) {
    if (used[first])
      continue;
    std::vector<Vec3> loop;
    double twice_area = 0.0;
    bool closed = false;
    for (std::size_t s = first; !used[s];) {
      used[s] = true;
      loop.push_back(segments[s].from_m);
      twice_area += clipped_twice_area(frame.coordinates(segments[s].from_m), frame.coordinates(segments[s].to_m),
                                       limit.has_value());
      const auto next = starting_at.find(segments[s].to_edge);
      if (next == starting_at.end())
        break;
      closed = next->second == first;
      s = next->second;
    }
    section.area_m2 += 0.5 * twice_area;
    if (!closed) {
      ++section.n_open_chains;
      continue;
    }
    section.loops_m.push_back(std::move(loop));
    section.loop_areas_m2.push_back(0.5 * twice_area);
  }
  return section;
}

} // namespace fsi::geometry
