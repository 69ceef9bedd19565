#pragma once
// Closed triangle meshes generated in code: for tests, benchmarks and simple cases (a sphere
// obstacle, a torus, boxes, discs and rings). Triangles are counter-clockwise seen from outside.

#include "geometry/TriangleSoup.hpp"

namespace fsi::geometry {

/// Icosahedron subdivided `n_subdivisions` times and projected on the sphere:
/// 20 * 4^n triangles (n = 6 gives 81,920).
TriangleSoup make_icosphere(const Vec3 &centre_m, double radius_m, int n_subdivisions);

/// Torus around the z axis through centre_m: tube of radius minor_radius_m whose centre line
/// has radius major_radius_m; 2 * n_around * n_tube triangles (320 x 160 gives 102,400).
TriangleSoup make_torus(const Vec3 &centre_m, double major_radius_m, double minor_radius_m, int n_around, int n_tube);

/// Axis-aligned box [min_m, max_m], two triangles a face (12 triangles).
TriangleSoup make_box(const Vec3 &min_m, const Vec3 &max_m);

/// Ring around the z axis through base_centre_m, from z = base_centre_m.z() to that plus
/// height_m, between inner_radius_m and outer_radius_m; inner_radius_m = 0 gives a solid
/// cylinder (a disc). Both circles are polygons of n_around corners, the first on the +x
/// axis (their edges' midpoints lie at radius * cos(pi / n_around)).
TriangleSoup make_ring(const Vec3 &base_centre_m, double inner_radius_m, double outer_radius_m, double height_m,
                       int n_around);

/// The two soups in one (their vertices are not merged): a solid of several parts.
TriangleSoup append_soup(const TriangleSoup &first, const TriangleSoup &second);

} // namespace fsi::geometry
