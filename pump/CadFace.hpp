#pragma once
// What the region classifiers know of one face of a built solid: its CAD surface type and
// the extent of its triangles (from the mesh nodes, which lie on the surface), measured once
// the triangles are oriented outwards. Pure data: no gmsh.

#include "common/Types.hpp"

#include <string>
#include <vector>

namespace fsi::pump {

struct CadFace {
  int tag = 0;
  std::string surface_type; ///< gmsh's name of the OCC surface: "Plane", "Cylinder", "BSpline surface"...
  Vec3 lower_m = Vec3::Zero(), upper_m = Vec3::Zero(); ///< bounding box of its mesh nodes
  double min_radius_m = 0.0, max_radius_m = 0.0;       ///< distance of its nodes from the z axis
  double area_m2 = 0.0;
  /// sum over its triangles of area * (outward normal . e_theta), e_theta = e_z x r / |r|: the
  /// circumferential direction of rotation about +z. Positive: the face looks along +theta.
  double swirl_m2 = 0.0;
  std::vector<Vec3> nodes_m; ///< its mesh nodes (for the classifiers' distance tests)
};

} // namespace fsi::pump
