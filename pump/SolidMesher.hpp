#pragma once
// Triangulates the boundary of one OCC volume of the current gmsh model and names its
// triangles: the mesh is made consistent and outward (gmsh's surface meshes of an OCC volume
// are not), then each CAD face is handed with its measures to the part's classifier, and all
// its triangles take the region the classifier names. Include only from fsi_pump_geometry.

#include "CadFace.hpp"
#include "RegionSurface.hpp"

#include <functional>
#include <string>
#include <vector>

namespace fsi::pump {

struct MeshSizes {
  double max_size_m = 0.008;
  double min_size_m = 0.0005;
  /// Elements per 2 pi of curvature (the size near the rounded edges and small radii).
  int elements_per_2pi = 24;
};

/// `classify` returns an index into `region_names` for a face.
RegionSurface mesh_solid(const std::string &part, int volume_tag, const MeshSizes &sizes,
                         const std::vector<std::string> &region_names,
                         const std::function<int(const CadFace &)> &classify);

} // namespace fsi::pump
