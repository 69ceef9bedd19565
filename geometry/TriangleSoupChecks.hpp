#pragma once
// Validation of an indexed triangle mesh before it becomes a collision surface: every check
// that can fail on user data raises a MeshError naming the source.

#include "geometry/TriangleSoup.hpp"

#include <cstddef>
#include <string>

namespace fsi::geometry {

/// Number of undirected edges used by an odd number of triangles (0 for a closed mesh).
std::size_t count_border_edges(const TriangleArray &triangles);

/// Number of triangles whose area vanishes relative to their longest edge squared (repeated
/// vertices or collinear corners).
std::size_t count_zero_area_triangles(const TriangleSoup &soup);

/// Throws MeshDegenerateError (no triangle, index out of range, non-finite coordinate,
/// zero-area triangles) or MeshNotClosedError (border edges). `source` names the file.
void check_triangle_soup(const TriangleSoup &soup, const std::string &source);

} // namespace fsi::geometry
