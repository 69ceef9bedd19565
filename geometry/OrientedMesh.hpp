#pragma once
// Internal to fsi_collision (it exposes CGAL types; include it from this target's .cpp files
// only): a triangle soup turned into a closed, consistently outward-oriented CGAL mesh, and
// that mesh read back as plain arrays.

#include "geometry/TriangleSoup.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <string>
#include <vector>

namespace fsi::geometry {

using MeshKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using MeshPoint = MeshKernel::Point_3;
using Mesh = CGAL::Surface_mesh<MeshPoint>;

/// Orients the soup consistently and converts it to a closed mesh whose normals point out of
/// the enclosed volume. Throws MeshNotClosedError or MeshDegenerateError naming `source`.
Mesh build_oriented_mesh(const TriangleSoup &soup, const std::string &source);

/// The mesh as arrays, triangles indexed like the faces; the corners of face f are
/// source(h), target(h), target(next(h)) with h = halfedge(f).
TriangleSoup mesh_to_soup(const Mesh &mesh);

/// Corners of every triangle of a soup (m).
std::vector<std::array<Vec3, 3>> triangle_corners(const TriangleSoup &soup);

} // namespace fsi::geometry
