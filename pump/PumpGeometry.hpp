#pragma once
// The generated pump: the impeller (a solid body) and the casing's fluid domain (suction pipe,
// chamber, spiral volute, discharge) built with gmsh's OpenCASCADE kernel from a PumpDesign,
// triangulated, oriented outwards and named by region, written as multi-solid ASCII STL
// (impeller.stl, casing.stl) with a report (geometry.yaml). One gmsh session per build.

#include "PumpDesign.hpp"
#include "RegionSurface.hpp"
#include "SolidMesher.hpp"

#include <filesystem>
#include <optional>

namespace fsi::pump {

struct GeometryOptions {
  MeshSizes impeller{0.007, 0.0004, 20};
  MeshSizes casing{0.012, 0.0008, 36};
  /// Coarser sizes for tests (same CAD, fewer triangles).
  static GeometryOptions coarse() { return {{0.012, 0.001, 16}, {0.025, 0.002, 36}}; }
};

/// The blade as built, measured on the built camber curve of blade 1 (a B-spline through the
/// camber points) and on its triangulated trailing edge.
struct AsBuiltBlade {
  double wrap_deg = 0.0;         ///< angle swept by the built camber curve from r1 to r2
  double inlet_angle_deg = 0.0;  ///< beta at r1 from the curve's tangent
  double outlet_angle_deg = 0.0; ///< beta at r2
  double wrap_on_mesh_deg = 0.0; ///< from the leading-edge centre to the trailing-edge face's centroid
};

/// A single-channel impeller as built (ChannelImpellerSolid, ChannelLayout).
struct BuiltChannel {
  double channel_volume_m3 = 0.0;      ///< the channel inside D2 between the discs (OCC)
  double leading_edge_angle_deg = 0.0; ///< the leading edge's angle about z (its radial axis, z = 0)
  double leading_edge_inner_radius_m = 0.0, leading_edge_outer_radius_m = 0.0; ///< boss to the eye's rim
  double exit_area_m2 = 0.0;            ///< through-flow area at the exit (ChannelLayout::exit_area_m2)
  double smallest_section_side_m = 0.0; ///< ChannelLayout::smallest_section_side_m
};

struct BuiltPart {
  RegionSurface surface;
  double cad_volume_m3 = 0.0; ///< OCC's volume of the solid
};

struct PumpGeometry {
  BuiltPart impeller, casing;
  AsBuiltBlade blade;                 ///< bladed impellers
  std::optional<BuiltChannel> channel; ///< single-channel impellers
  Eigen::Vector2d nose_centre_xy_m = Eigen::Vector2d::Zero(); ///< axis of the cut-water's round nose (z-parallel)
  double nose_radius_m = 0.0;
  double seconds = 0.0; ///< wall time of the build (CAD and meshing)

  /// Builds both parts. Throws GeometryError naming the part.
  static PumpGeometry build(const PumpDesign &design, const GeometryOptions &options = {});
  /// Writes dir/impeller.stl, dir/casing.stl and dir/geometry.yaml (dir is created).
  void write(const std::filesystem::path &dir, const PumpDesign &design) const;
};

} // namespace fsi::pump
