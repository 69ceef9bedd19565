#pragma once
// Closed triangle meshes generated in code: for tests, benchmarks and simple cases (a sphere
// obstacle, a torus). Triangles are counter-clockwise seen from outside.

#include "geometry/TriangleSoup.hpp"

namespace fsi::geometry {

/// Icosahedron subdivided `n_subdivisions` times and projected on the sphere:
/// 20 * 4^n triangles (n = 6 gives 81,920).
TriangleSoup make_icosphere(const Vec3 &centre_m, double radius_m, int n_subdivisions);

/// Torus around the z axis through centre_m: tube of radius minor_radius_m whose centre line
/// has radius major_radius_m; 2 * n_around * n_tube triangles (320 x 160 gives 102,400).
TriangleSoup make_torus(const Vec3 &centre_m, double major_radius_m, double minor_radius_m,
                        int n_around, int n_tube);

} // namespace fsi::geometry
