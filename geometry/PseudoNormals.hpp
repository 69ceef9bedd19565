#pragma once
// Angle-weighted pseudo-normals of a closed, consistently oriented triangle mesh (Baerentzen &
// Aanaes 2005, "Signed distance computation using the angle weighted pseudonormal"): the face
// normal for a face interior, the sum of the two face normals for an edge, and the sum of the
// incident face normals weighted by their angle at the vertex for a vertex. If c is the
// closest surface point to p and n the pseudo-normal of the feature holding c, then p is
// outside exactly when (p - c).n > 0: the sign of the distance without any inside test.

#include "common/Types.hpp"
#include "geometry/TrianglePoint.hpp"
#include "geometry/TriangleSoup.hpp"

#include <cstdint>
#include <vector>

namespace fsi::geometry {

class PseudoNormals {
public:
  /// vertices_m and triangles: a closed mesh oriented outwards (counter-clockwise seen from
  /// the side the normals point to). Features where the mesh is not a 2-manifold (an edge
  /// not shared by exactly two faces walking it in opposite directions, a vertex whose
  /// position another vertex repeats, an edge between two such vertices) get a zero normal,
  /// which a caller reads as "sign unknown, use an exact inside test".
  PseudoNormals(const PointArray &vertices_m, const TriangleArray &triangles);

  /// Unit pseudo-normal (pointing out of the enclosed volume) of a feature of a face, or
  /// zero where it is not defined.
  const Vec3 &normal(std::int32_t face, TriangleFeature feature) const {
    const auto f = static_cast<std::size_t>(face);
    switch (feature) {
    case TriangleFeature::face:
      return face_normals_[f];
    case TriangleFeature::edge_ab:
    case TriangleFeature::edge_bc:
    case TriangleFeature::edge_ca:
      return edge_normals_[3 * f + static_cast<std::size_t>(feature) - 3];
    default:
      return vertex_normals_[face_vertices_[3 * f + static_cast<std::size_t>(feature)]];
    }
  }

  std::size_t n_undefined_features() const { return n_undefined_; }

private:
  void compute_face_and_vertex_normals(const PointArray &vertices_m,
                                       const TriangleArray &triangles);
  void compute_edge_normals(const TriangleArray &triangles);
  void clear_repeated_positions(const PointArray &vertices_m, const TriangleArray &triangles);

  std::vector<Vec3> face_normals_;          ///< per face
  std::vector<Vec3> edge_normals_;          ///< per face and edge (ab, bc, ca)
  std::vector<Vec3> vertex_normals_;        ///< per vertex
  std::vector<std::int32_t> face_vertices_; ///< per face and corner
  std::size_t n_undefined_ = 0;
};

} // namespace fsi::geometry
