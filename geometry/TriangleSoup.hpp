#pragma once
// An indexed triangle mesh in plain arrays: the exchange format between STL files, mesh
// generators and TriangleMeshSurface.

#include "common/Types.hpp"

#include <Eigen/Core>

namespace fsi::geometry {

/// n_triangles x 3 vertex indices (row-major, like PointArray).
using TriangleArray = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct TriangleSoup {
  PointArray vertices_m;   ///< n_vertices x 3 positions (m)
  TriangleArray triangles; ///< n_triangles x 3 indices into vertices_m, counter-clockwise
                           ///< seen from outside for generated meshes
};

} // namespace fsi::geometry
