#pragma once
// Configuration of the collision model (Eq. 11): rigid surfaces, each optionally moving with a
// prescribed rigid motion, the threshold d_c and the target distance d_t, and self-collision.

#include "common/ConfigReader.hpp"
#include "common/MotionConfig.hpp"

#include <filesystem>
#include <optional>

namespace fsi::structure {

struct PlaneConfig {
  Vec3 point_m{0.0, 0.0, 0.0};
  Vec3 normal{0.0, 0.0, 1.0};
  template <class V> void visit(V &v) {
    v.vec3("point_m", point_m, "m", "A point of the plane.");
    v.vec3("normal", normal, "1", "Normal pointing into the fluid.");
  }
};

struct BoxConfig {
  Vec3 min_m{-1.0, -1.0, -1.0};
  Vec3 max_m{1.0, 1.0, 1.0};
  template <class V> void visit(V &v) {
    v.vec3("min_m", min_m, "m", "Lower corner of an axis-aligned box holding the fluid (channel walls).");
    v.vec3("max_m", max_m, "m", "Upper corner.");
  }
};

struct CylinderConfig {
  Vec3 axis_start_m{0.0, 0.0, 0.0};
  Vec3 axis_end_m{0.0, 0.0, 1.0};
  double radius_m = 0.008;
  template <class V> void visit(V &v) {
    v.vec3("axis_start_m", axis_start_m, "m", "Centre of one flat cap of a solid finite cylinder (a pole).");
    v.vec3("axis_end_m", axis_end_m, "m", "Centre of the other cap.");
    v.number("radius_m", radius_m, common::Range::positive("m"), "Cylinder radius.");
  }
};

enum class FluidSide { outside, inside };

struct MeshConfig {
  std::filesystem::path file;
  FluidSide fluid_side = FluidSide::outside;
  template <class V> void visit(V &v) {
    v.existing_file("file", file, "Closed triangle mesh (ASCII or binary STL, coordinates in m).");
    v.choice("fluid_side", fluid_side, {{"outside", FluidSide::outside}, {"inside", FluidSide::inside}},
             "outside: a solid body (impeller); inside: a casing holding the fluid (volute).");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      if (file.empty())
        v.fail("needs 'file'.");
  }
};

struct SurfaceConfig {
  std::optional<PlaneConfig> plane;
  std::optional<BoxConfig> box;
  std::optional<CylinderConfig> cylinder;
  std::optional<MeshConfig> mesh;
  std::optional<common::MotionConfig> motion;

  template <class V> void visit(V &v) {
    v.optional_section("plane", plane, "An infinite plane wall.");
    v.optional_section("box", box, "Channel walls seen from inside.");
    v.optional_section("cylinder", cylinder, "A finite solid cylinder.");
    v.optional_section("mesh", mesh, "A closed STL surface.");
    v.optional_section("motion", motion, "Prescribed rigid motion of this surface (absent: static).");
    if constexpr (std::is_same_v<V, common::ConfigReader>) {
      const int given = plane.has_value() + box.has_value() + cylinder.has_value() + mesh.has_value();
      if (given != 1)
        v.fail("must hold exactly one of: plane, box, cylinder, mesh (found " + std::to_string(given) + ").");
    }
  }
};

struct CollisionConfig {
  double threshold_m = 0.004;
  double target_distance_m = 0.004;
  bool self_collision = false;
  std::vector<SurfaceConfig> surfaces;

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
