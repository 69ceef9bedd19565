#pragma once
// The free passage of a channel: the diameter of the largest sphere that can travel from a
// start region to an end region without entering a solid (a pump's impeller: the largest
// solid a rag can carry through it). The sphere's centre stays in an allowed region sampled
// by a voxel grid of spacing h; at each voxel the clearance is the distance to the solid's
// surface (0 inside the solid), and the best path is the one whose smallest clearance is
// largest: Dijkstra's algorithm with a max-heap on that smallest clearance (the widest-path
// problem) over 26 neighbours. The passage is twice the bottleneck clearance, within sqrt(3) h
// (a grid point lies within sqrt(3) h / 2 of every point, and the clearance is 1-Lipschitz).
//
// Most voxels never need a distance query: the clearance drops by at most the step from one
// voxel to the next, so a voxel whose lower bound already exceeds the path's bottleneck so far
// cannot lower it, and its exact clearance is asked only when the bound falls below it. The
// answer equals that of querying every voxel.

#include "common/Types.hpp"
#include "geometry/RigidSurface.hpp"

#include <Eigen/Geometry>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace fsi::geometry {

/// A test on a point (m): "may the sphere's centre be here?", "is this the start?".
using PointPredicate = std::function<bool(const Vec3 &)>;

/// True inside (or on) any of the boxes.
PointPredicate inside_any_box(std::vector<Eigen::AlignedBox3d> boxes_m);

/// Where the sphere's centre may travel. The grid's points are bounds_m.min() + h (i, j, k);
/// start and end are tested only at allowed points.
struct PassageRegion {
  Eigen::AlignedBox3d bounds_m;
  PointPredicate allowed;
  PointPredicate start;
  PointPredicate end;
};

struct FreePassage {
  enum class Status {
    passes,   ///< a sphere of diameter_m gets through
    blocked,  ///< no path from the start to the end avoids the solid
    no_start, ///< no allowed grid point is in the start region
    no_end    ///< no allowed grid point is in the end region
  };
  Status status = Status::blocked;
  double diameter_m = 0.0;          ///< twice the bottleneck clearance; 0 unless passes
  double error_bound_m = 0.0;       ///< |diameter_m - exact| <= this (sqrt(3) h) for an exact surface
  Vec3 bottleneck_m = Vec3::Zero(); ///< the sphere's centre where its clearance is smallest
  std::vector<Vec3> path_m;         ///< grid points of the best path, start to end
  std::size_t n_allowed_points = 0;
  std::size_t n_distance_queries = 0;

  /// "passes", "blocked", "no start point", "no end point".
  static std::string status_name(Status status);
};

/// Searches the widest path through the region around `solid` (whose signed distance is
/// positive on the fluid side). Throws std::invalid_argument for a spacing that is not
/// positive, an empty box or a grid above 20 million points.
FreePassage find_free_passage(const RigidSurface &solid, const PassageRegion &region, double spacing_m);

} // namespace fsi::geometry
