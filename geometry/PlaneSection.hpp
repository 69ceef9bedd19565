#pragma once
// The section of a closed triangle mesh by a plane (a volute's throat, a pipe's bore): the
// triangles crossing the plane give one segment each, the segments chain through the mesh
// edges they cross into closed loops, and the shoelace formula in the plane's 2-D frame gives
// the area. Optionally only the part of the plane on one side of a line counts (a half-plane
// through the pump's axis, beyond the volute's base circle).

#include "geometry/TriangleSoup.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace fsi::geometry {

/// The plane through point_m with normal `normal` (any length but zero).
struct SectionPlane {
  Vec3 point_m = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
};

/// Keeps the points x of the plane with (x - point_m).direction >= 0; `direction` should lie
/// in the plane (its component along the normal is ignored) and point_m on it (projected).
struct HalfPlaneLimit {
  Vec3 point_m = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
};

struct PlaneSection {
  /// Area of the section (m^2), restricted to the half-plane if one was given. Signed:
  /// positive when the mesh's triangles are counter-clockwise seen from outside, negative
  /// when they all face inwards.
  double area_m2 = 0.0;
  /// The closed loops the plane cuts out of the surface (whole, not restricted), each
  /// running counter-clockwise around the enclosed material seen from the normal's side.
  std::vector<std::vector<Vec3>> loops_m;
  /// The restricted signed area of each loop (m^2): loops around holes count negative.
  std::vector<double> loop_areas_m2;
  /// Chains of segments that do not close: the mesh is open, non-manifold or inconsistently
  /// oriented where the plane cuts it, and area_m2 cannot be trusted. 0 for a closed mesh.
  std::size_t n_open_chains = 0;
};

/// Cuts the closed soup by the plane. Vertices exactly on the plane count as above it (on
/// the normal's side), so every crossing lies strictly inside a mesh edge or at its upper end
/// and the loops stay closed. Cost: one pass over the triangles.
PlaneSection plane_section(const TriangleSoup &soup, const SectionPlane &plane,
                           const std::optional<HalfPlaneLimit> &limit = std::nullopt);

} // namespace fsi::geometry
