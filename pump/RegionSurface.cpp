#include "RegionSurface.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <queue>
#include <stdexcept>
#include <unordered_map>

namespace fsi::pump {
namespace {

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}

/// For every undirected edge, the triangles using it.
std::unordered_map<std::uint64_t, std::vector<int>> edge_triangles(const std::vector<std::array<int, 3>> &tris) {
  std::unordered_map<std::uint64_t, std::vector<int>> edges;
  edges.reserve(3 * tris.size());
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
    for (int k = 0; k < 3; ++k)
      edges[edge_key(tris[t][k], tris[t][(k + 1) % 3])].push_back(t);
  return edges;
}

/// Does triangle `tri` run the edge a -> b?
bool runs(const std::array<int, 3> &tri, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (tri[k] == a && tri[(k + 1) % 3] == b)
      return true;
  return false;
}

Vec3 facet_normal(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

} // namespace

void RegionSurface::orient_outward(const std::string &part) {
  const auto edges = edge_triangles(triangles);
  for (const auto &[key, users] : edges)
    if (users.size() != 2)
      throw std::runtime_error(part + ": the triangulated surface is not a closed manifold (an edge is used by " +
                               std::to_string(users.size()) + " triangles)");
  std::vector<char> done(triangles.size(), 0);
  for (std::size_t seed = 0; seed < triangles.size(); ++seed) {
    if (done[seed])
      continue;
    done[seed] = 1;
    std::queue<int> front;
    front.push(static_cast<int>(seed));
    while (!front.empty()) { // flood: a neighbour must run the shared edge the other way
      const int t = front.front();
      front.pop();
      for (int k = 0; k < 3; ++k) {
        const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
        const auto &users = edges.at(edge_key(a, b));
        const int other = users[0] == t ? users[1] : users[0];
        if (done[other])
          continue;
        if (runs(triangles[other], a, b))
          std::swap(triangles[other][1], triangles[other][2]);
        done[other] = 1;
        front.push(other);
      }
    }
  }
  if (enclosed_volume_m3() < 0.0)
    for (auto &tri : triangles)
      std::swap(tri[1], tri[2]);
  check_closed_and_outward(part);
}

int RegionSurface::split_caps() {
  int removed = 0;
  for (bool again = true; again;) {
    again = false;
    const auto edges = edge_triangles(triangles);
    for (std::size_t t = 0; t < triangles.size() && !again; ++t) {
      const auto tri = triangles[t];
      const Vec3 &a = vertices_m[tri[0]], &b = vertices_m[tri[1]], &c = vertices_m[tri[2]];
      const double lengths[3] = {(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()};
      const int k = static_cast<int>(std::max_element(lengths, lengths + 3) - lengths);
      const double longest = lengths[k];
      // Collinear: the doubled area against the longest edge squared, near rounding.
      if (!(longest > 0.0) || (b - a).cross(c - a).norm() > 1e-10 * longest)
        continue;
      const int p = tri[k], q = tri[(k + 1) % 3], middle = tri[(k + 2) % 3];
      if ((vertices_m[middle] - vertices_m[p]).squaredNorm() == 0.0 ||
          (vertices_m[middle] - vertices_m[q]).squaredNorm() == 0.0)
        continue; // coincident vertices: not a cap
      const auto &users = edges.at(edge_key(p, q));
      if (users.size() != 2)
        continue;
      const int n = users[0] == static_cast<int>(t) ? users[1] : users[0];
      const auto other = triangles[n]; // runs q -> p
      int apex = -1;
      for (int j = 0; j < 3; ++j)
        if (other[j] == q && other[(j + 1) % 3] == p)
          apex = other[(j + 2) % 3];
      if (apex < 0)
        continue; // not consistently oriented: orient_outward first
      // The cap p -> q -> middle goes; the neighbour q -> p -> apex becomes
      // q -> middle -> apex and middle -> p -> apex.
      triangles[n] = {q, middle, apex};
      triangles[t] = {middle, p, apex};
      triangle_regions[t] = triangle_regions[n];
      ++removed;
      again = true;
    }
  }
  return removed;
}

void RegionSurface::check_closed_and_outward(const std::string &part) const {
  for (const auto &[key, users] : edge_triangles(triangles)) {
    if (users.size() != 2)
      throw std::runtime_error(part + ": an edge is used by " + std::to_string(users.size()) +
                               " triangles (not a closed manifold)");
    const auto &first = triangles[users[0]];
    for (int k = 0; k < 3; ++k) {
      const int a = first[k], b = first[(k + 1) % 3];
      if (edge_key(a, b) == key && runs(triangles[users[1]], a, b))
        throw std::runtime_error(part + ": two triangles run a shared edge the same way (inconsistent orientation)");
    }
  }
  if (!(enclosed_volume_m3() > 0.0))
    throw std::runtime_error(part + ": the surface encloses no positive volume (normals point inwards)");
}

double RegionSurface::enclosed_volume_m3() const {
  double six_volume = 0.0;
  for (const auto &t : triangles)
    six_volume += vertices_m[t[0]].cross(vertices_m[t[1]]).dot(vertices_m[t[2]]);
  return six_volume / 6.0;
}

double RegionSurface::region_area_m2(int region) const {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    if (triangle_regions[i] == region) {
      const auto &t = triangles[i];
      twice_area += (vertices_m[t[1]] - vertices_m[t[0]]).cross(vertices_m[t[2]] - vertices_m[t[0]]).norm();
    }
  return 0.5 * twice_area;
}

int RegionSurface::region_index(const std::string &name) const {
  for (std::size_t i = 0; i < region_names.size(); ++i)
    if (region_names[i] == name)
      return static_cast<int>(i);
  return -1;
}

std::array<Vec3, 2> RegionSurface::bounding_box_m() const {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const auto &p : vertices_m) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

void RegionSurface::write_ascii_stl(const std::filesystem::path &file) const {
  std::ofstream out(file);
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
  char line[160];
  for (std::size_t region = 0; region < region_names.size(); ++region) {
    bool opened = false;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      if (triangle_regions[i] != static_cast<int>(region))
        continue;
      if (!opened)
        out << "solid " << region_names[region] << "\n";
      opened = true;
      const auto &t = triangles[i];
      const Vec3 n = facet_normal(vertices_m[t[0]], vertices_m[t[1]], vertices_m[t[2]]);
      std::snprintf(line, sizeof line, "facet normal %.6g %.6g %.6g\nouter loop\n", n[0], n[1], n[2]);
      out << line;
      for (const int v : t) {
        // 9 significant digits: below a micrometre on a metre, and the same text for the same
        // vertex everywhere, so a reader merges the corners again exactly.
        std::snprintf(line, sizeof line, "vertex %.9g %.9g %.9g\n", vertices_m[v][0], vertices_m[v][1],
                      vertices_m[v][2]);
        out << line;
      }
      out << "endloop\nendfacet\n";
    }
    if (opened)
      out << "endsolid " << region_names[region] << "\n";
  }
  if (!out)
    throw std::runtime_error("writing " + file.string() + " failed");
}

} // namespace fsi::pump
