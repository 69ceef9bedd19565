#pragma once
// Configuration of the collision model (Eq. 11): the rigid surfaces (geometry/SurfaceConfig.hpp),
// the threshold d_c and the target distance d_t, the spreading of a correction over the grid, and
// self-collision, and contact between structures.

#include "common/ConfigReader.hpp"
#include "geometry/SurfaceConfig.hpp"

#include <filesystem>
#include <optional>

namespace fsi::structure {

struct CollisionConfig {
  double threshold_m = 0.004;
  double target_distance_m = 0.004;
  int spread_points = 0;
  bool self_collision = false;
  bool structure_contact = false;
  std::vector<geometry::SurfaceConfig> surfaces;

  template <class V> void visit(V &v) {
    v.number("threshold_m", threshold_m, common::Range::positive("m"),
             "d_c: points closer than this to a rigid surface are corrected (Eq. 11).");
    v.number("target_distance_m", target_distance_m, common::Range::positive("m"),
             "d_t: corrected points are moved to this distance along the surface normal.");
    v.integer("spread_points", spread_points, common::Range::at_least(0, "points"),
              "Spread each wall correction (Eq. 11) over the sheet's grid neighbours up to this many points "
              "away, with weights 1 - d / (n + 1) at grid distance d, so that the step in displacement between "
              "neighbours, and the strain it makes, is about 1 / (n + 1) of the correction's (d_t / spacing "
              "without). 0: the paper's correction of each point alone.");
    v.flag("self_collision", self_collision, "Push apart points of the same structure closer than d_c.");
    v.flag("structure_contact", structure_contact,
           "Contact between different structures (rags of a feed piling up): a point closer than d_c to "
           "another sheet's surface is moved with it apart to d_t, on the side it came from, each in "
           "inverse proportion to its mass.");
    v.list("surfaces", surfaces, "Rigid surfaces.");
    if constexpr (std::is_same_v<V, common::ConfigReader>) {
      if (target_distance_m < threshold_m)
        v.fail_value("target_distance_m", "must be >= threshold_m (points would stay inside the threshold).");
      if (spread_points > 0 && surfaces.empty())
        v.fail_value("spread_points", "spreads the corrections against rigid surfaces: give collisions.surfaces, "
                                      "or leave it 0.");
    }
  }
};

} // namespace fsi::structure
