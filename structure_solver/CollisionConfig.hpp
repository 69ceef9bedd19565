#pragma once
// Configuration of the collision model (Eq. 11): the rigid surfaces (geometry/SurfaceConfig.hpp),
// the threshold d_c and the target distance d_t, and self-collision.

#include "common/ConfigReader.hpp"
#include "geometry/SurfaceConfig.hpp"

#include <filesystem>
#include <optional>

namespace fsi::structure {

struct CollisionConfig {
  double threshold_m = 0.004;
  double target_distance_m = 0.004;
  bool self_collision = false;
  std::vector<geometry::SurfaceConfig> surfaces;

  template <class V> void visit(V &v) {
    v.number("threshold_m", threshold_m, common::Range::positive("m"),
             "d_c: points closer than this to a rigid surface are corrected (Eq. 11).");
    v.number("target_distance_m", target_distance_m, common::Range::positive("m"),
             "d_t: corrected points are moved to this distance along the surface normal.");
    v.flag("self_collision", self_collision, "Push apart points of the same structure closer than d_c.");
    v.list("surfaces", surfaces, "Rigid surfaces.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (target_distance_m < threshold_m)
        v.fail_value("target_distance_m", "must be >= threshold_m (points would stay inside the threshold).");
  }
};

} // namespace fsi::structure
