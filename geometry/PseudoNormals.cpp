#include "geometry/PseudoNormals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace fsi::geometry {
namespace {

/// Interior angle at corner a of triangle abc (rad), robust for small and obtuse angles.
double corner_angle(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 ab = b - a, ac = c - a;
  return std::atan2(ab.cross(ac).norm(), ab.dot(ac));
}

std::uint64_t directed_edge_key(std::int32_t from, std::int32_t to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) |
         static_cast<std::uint32_t>(to);
}

Vec3 normalized_or_zero(const Vec3 &v) {
  const double length = v.norm();
  return length > 0.0 ? Vec3(v / length) : Vec3(Vec3::Zero());
}

} // namespace

PseudoNormals::PseudoNormals(const PointArray &vertices_m, const TriangleArray &triangles) {
  face_vertices_.resize(3 * static_cast<std::size_t>(triangles.rows()));
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k)
      face_vertices_[3 * static_cast<std::size_t>(t) + k] = triangles(t, k);
  }
  compute_face_and_vertex_normals(vertices_m, triangles);
  compute_edge_normals(triangles);
  clear_repeated_positions(vertices_m, triangles);
}

void PseudoNormals::compute_face_and_vertex_normals(const PointArray &vertices_m,
                                                    const TriangleArray &triangles) {
  face_normals_.resize(static_cast<std::size_t>(triangles.rows()));
  vertex_normals_.assign(static_cast<std::size_t>(vertices_m.rows()), Vec3::Zero());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const std::array<Vec3, 3> corner = {vertices_m.row(triangles(t, 0)).transpose(),
                                        vertices_m.row(triangles(t, 1)).transpose(),
                                        vertices_m.row(triangles(t, 2)).transpose()};
    const Vec3 normal = normalized_or_zero((corner[1] - corner[0]).cross(corner[2] - corner[0]));
    face_normals_[static_cast<std::size_t>(t)] = normal;
    for (int k = 0; k < 3; ++k) {
      const double angle = corner_angle(corner[k], corner[(k + 1) % 3], corner[(k + 2) % 3]);
      vertex_normals_[static_cast<std::size_t>(triangles(t, k))] += angle * normal;
    }
  }
  for (Vec3 &normal : vertex_normals_)
    normal = normalized_or_zero(normal);
}

void PseudoNormals::compute_edge_normals(const TriangleArray &triangles) {
  // Each directed edge of a closed, consistently oriented 2-manifold appears once, and its
  // reverse belongs to the neighbouring face.
  std::unordered_map<std::uint64_t, std::int64_t> slot_of_edge;
  slot_of_edge.reserve(3 * static_cast<std::size_t>(triangles.rows()));
  std::vector<char> repeated(3 * static_cast<std::size_t>(triangles.rows()), 0);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto slot = static_cast<std::int64_t>(3 * t + k);
      const auto [it, inserted] =
          slot_of_edge.emplace(directed_edge_key(triangles(t, k), triangles(t, (k + 1) % 3)), slot);
      if (!inserted)
        repeated[static_cast<std::size_t>(it->second)] = repeated[static_cast<std::size_t>(slot)] =
            1;
    }
  }
  edge_normals_.assign(3 * static_cast<std::size_t>(triangles.rows()), Vec3::Zero());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto slot = static_cast<std::size_t>(3 * t + k);
      const auto twin =
          slot_of_edge.find(directed_edge_key(triangles(t, (k + 1) % 3), triangles(t, k)));
      if (repeated[slot] || twin == slot_of_edge.end() ||
          repeated[static_cast<std::size_t>(twin->second)]) {
        ++n_undefined_;
        continue;
      }
      const std::size_t twin_face = static_cast<std::size_t>(twin->second) / 3;
      edge_normals_[slot] =
          normalized_or_zero(face_normals_[static_cast<std::size_t>(t)] + face_normals_[twin_face]);
    }
  }
}

void PseudoNormals::clear_repeated_positions(const PointArray &vertices_m,
                                             const TriangleArray &triangles) {
  // Vertices split apart where the mesh pinches (a non-manifold vertex or edge) keep their
  // position: their normals see only part of the surface around them.
  std::vector<std::int32_t> order(static_cast<std::size_t>(vertices_m.rows()));
  std::iota(order.begin(), order.end(), 0);
  const auto position = [&vertices_m](std::int32_t v) {
    return std::array<double, 3>{vertices_m(v, 0), vertices_m(v, 1), vertices_m(v, 2)};
  };
  std::sort(order.begin(), order.end(),
            [&](std::int32_t a, std::int32_t b) { return position(a) < position(b); });
  std::vector<char> repeated(order.size(), 0);
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (position(order[k]) == position(order[k - 1]))
      repeated[static_cast<std::size_t>(order[k])] =
          repeated[static_cast<std::size_t>(order[k - 1])] = 1;
  }
  for (std::size_t v = 0; v < repeated.size(); ++v) {
    if (repeated[v]) {
      vertex_normals_[v] = Vec3::Zero();
      ++n_undefined_;
    }
  }
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (repeated[static_cast<std::size_t>(triangles(t, k))] &&
          repeated[static_cast<std::size_t>(triangles(t, (k + 1) % 3))])
        edge_normals_[static_cast<std::size_t>(3 * t + k)] = Vec3::Zero();
    }
  }
}

} // namespace fsi::geometry
