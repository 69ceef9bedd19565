#pragma once
// Validation of an indexed triangle mesh before it becomes a collision surface: every check
// that can fail on user data raises a MeshError naming the source.

#include "geometry/TriangleSoup.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace fsi::geometry {

/// The undirected edges used by an odd number of triangles, as vertex pairs (lower index
/// first, sorted): the rims of the holes.
std::vector<std::array<int, 2>> border_edges(const TriangleArray &triangles);

/// Number of undirected edges used by an odd number of triangles (0 for a closed mesh).
std::size_t count_border_edges(const TriangleArray &triangles);

/// Number of edges that two triangles run through in the same direction: where neighbouring
/// triangles disagree on which side is out (0 for a consistently oriented mesh).
std::size_t count_misoriented_edges(const TriangleArray &triangles);

/// Volume enclosed by a closed soup by the divergence theorem (m^3): positive when the
/// triangles are counter-clockwise seen from outside, negative when they all face inwards.
double signed_volume_m3(const TriangleSoup &soup);

/// Number of triangles whose area vanishes relative to their longest edge squared (repeated
/// vertices or collinear corners).
std::size_t count_zero_area_triangles(const TriangleSoup &soup);

/// Throws MeshDegenerateError (no triangle, index out of range, non-finite coordinate,
/// zero-area triangles) or MeshNotClosedError (border edges). `source` names the file.
void check_triangle_soup(const TriangleSoup &soup, const std::string &source);

} // namespace fsi::geometry
