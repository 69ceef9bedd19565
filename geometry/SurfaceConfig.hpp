#pragma once
// The scene's rigid surfaces as the case declares them (collisions.surfaces[]): an infinite
// plane, channel walls (a box seen from inside), a finite cylinder or a closed STL mesh, each
// static or moving with a prescribed rigid motion. The structure collides with them (Eq. 11),
// the fluid penalizes the closed meshes among them (Eqs. 9-10), the coupler moves them.

#include "common/ConfigReader.hpp"
#include "motion/MotionConfig.hpp"

#include <filesystem>
#include <optional>

namespace fsi::geometry {

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
  std::optional<motion::MotionConfig> motion;

  template <class V> void visit(V &v) {
    v.optional_section("plane", plane, "An infinite plane wall.");
    v.optional_section("box", box, "Channel walls seen from inside.");
    v.optional_section("cylinder", cylinder, "A finite solid cylinder.");
    v.optional_section("mesh", mesh, "A closed STL surface.");
    v.optional_section("motion", motion, "Prescribed rigid motion of this surface (absent: static).");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      v.require_exactly_one({{"plane", plane.has_value()},
                             {"box", box.has_value()},
                             {"cylinder", cylinder.has_value()},
                             {"mesh", mesh.has_value()}});
  }
};

} // namespace fsi::geometry
