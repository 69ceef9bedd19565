#pragma once
// Closest point of a triangle to a query point, together with the feature (vertex, edge or
// face interior) it lies on: the feature selects the pseudo-normal that signs the distance
// (Baerentzen & Aanaes 2005). Ericson's Voronoi-region test, Real-Time Collision Detection
// 5.1.5.

#include "common/Types.hpp"

#include <cstdint>

namespace fsi::geometry {

/// The part of triangle abc a closest point lies on. Edges run a->b, b->c, c->a.
enum class TriangleFeature : std::uint8_t {
  vertex_a,
  vertex_b,
  vertex_c,
  edge_ab,
  edge_bc,
  edge_ca,
  face
};

struct TrianglePoint {
  Vec3 point_m = Vec3::Zero();
  TriangleFeature feature = TriangleFeature::face;
};

/// Closest point of triangle abc to p and the feature holding it (a point on the boundary of
/// two regions gets either; both give the same point). Inline: it is the inner loop of every
/// near-surface query (GCC would not inline it otherwise, at a quarter of the query time).
[[gnu::always_inline]] inline TrianglePoint
closest_point_on_triangle(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return {a, TriangleFeature::vertex_a};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return {b, TriangleFeature::vertex_b};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return {a + d1 / (d1 - d3) * ab, TriangleFeature::edge_ab};
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return {c, TriangleFeature::vertex_c};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return {a + d2 / (d2 - d6) * ac, TriangleFeature::edge_ca};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), TriangleFeature::edge_bc};
  const double denominator = 1.0 / (va + vb + vc);
  return {a + ab * (vb * denominator) + ac * (vc * denominator), TriangleFeature::face};
}

} // namespace fsi::geometry
