#pragma once
// A closed triangulated surface whose triangles each belong to one named region (the blade's
// leading edge, the casing's inlet...): what the generator writes as a multi-solid ASCII STL,
// one `solid NAME ... endsolid NAME` block per region (snappyHexMesh reads the names as
// patches). Pure geometry: no gmsh.

#include "common/Types.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace fsi::pump {

struct RegionSurface {
  std::vector<std::string> region_names;
  std::vector<Vec3> vertices_m;
  std::vector<std::array<int, 3>> triangles; ///< counter-clockwise seen from outside once oriented
  std::vector<int> triangle_regions;         ///< index into region_names, one per triangle

  /// Makes the orientation consistent across every edge, then outward (positive enclosed
  /// volume). Throws std::runtime_error naming `part` when an edge is not shared by exactly two
  /// triangles (the surface is not a closed manifold).
  void orient_outward(const std::string &part);
  /// Removes the caps of a consistently oriented closed surface: a triangle whose three vertices
  /// are collinear (gmsh leaves one where a CAD edge is split between two faces), its middle
  /// vertex on its longest edge. The neighbour across that edge is split at the middle vertex,
  /// which keeps the surface closed and oriented; the new pair takes the neighbour's region.
  /// Returns the number of caps removed (a triangle with two coincident vertices is left).
  int split_caps();
  /// Throws std::runtime_error naming `part` unless every edge is shared by exactly two
  /// triangles running it in opposite directions and the enclosed volume is positive.
  void check_closed_and_outward(const std::string &part) const;

  /// Signed volume by the divergence theorem, sum of (a x b) . c / 6 (m^3).
  double enclosed_volume_m3() const;
  double region_area_m2(int region) const;
  /// Index of a region by name (-1 when absent).
  int region_index(const std::string &name) const;
  std::array<Vec3, 2> bounding_box_m() const;

  /// Writes the ASCII multi-solid STL (one solid per non-empty region, named after it).
  void write_ascii_stl(const std::filesystem::path &file) const;
};

} // namespace fsi::pump
