#pragma once
// Configuration of a prescribed flow (the `fluid.prescribed` section of a case): exactly one
// of the fields below. Header-only data; prescribed_flow/FlowFactory builds the FlowField.

#include "common/ConfigReader.hpp"

#include <filesystem>
#include <optional>

namespace fsi::prescribed_flow {

struct QuiescentFlowConfig {
  template <class V> void visit(V &) {}
};

struct UniformFlowConfig {
  Vec3 velocity_m_per_s{0.0, 0.0, 0.0};
  template <class V> void visit(V &v) {
    v.vec3("velocity_m_per_s", velocity_m_per_s, "m/s", "Flow velocity U (the same everywhere, at all times).");
  }
};

struct ShearFlowConfig {
  Vec3 reference_point_m{0.0, 0.0, 0.0};
  Vec3 reference_velocity_m_per_s{0.0, 0.0, 0.0};
  Vec3 flow_direction{1.0, 0.0, 0.0};
  Vec3 gradient_direction{0.0, 0.0, 1.0};
  double shear_rate_1_per_s = 1.0;
  template <class V> void visit(V &v) {
    v.vec3("reference_point_m", reference_point_m, "m", "Point x0 where the velocity is the reference velocity.");
    v.vec3("reference_velocity_m_per_s", reference_velocity_m_per_s, "m/s", "Velocity U0 at x0.");
    v.vec3("flow_direction", flow_direction, "1", "Direction e of the sheared velocity (normalised).");
    v.vec3("gradient_direction", gradient_direction, "1",
           "Direction g along which the velocity changes (normalised; perpendicular to flow_direction).");
    v.number("shear_rate_1_per_s", shear_rate_1_per_s, common::Range::any("1/s"),
             "u = U0 + rate ((x - x0) . g) e.");
  }
};

struct RotationFlowConfig {
  Vec3 axis_point_m{0.0, 0.0, 0.0};
  Vec3 axis_direction{0.0, 0.0, 1.0};
  double rate_rad_per_s = 1.0;
  template <class V> void visit(V &v) {
    v.vec3("axis_point_m", axis_point_m, "m", "A point on the rotation axis.");
    v.vec3("axis_direction", axis_direction, "1", "Axis direction a (right-hand rule; normalised).");
    v.number("rate_rad_per_s", rate_rad_per_s, common::Range::any("rad/s"), "u = rate a x (x - p).");
  }
};

struct TableFlowConfig {
  std::filesystem::path file;
  template <class V> void visit(V &v) {
    v.existing_file("file", file,
                    "CSV with header 'x_m,y_m,z_m,u_m_per_s,v_m_per_s,w_m_per_s', one row per node of a rectilinear "
                    "grid; trilinear interpolation, clamped outside.");
  }
};

struct PrescribedFlowConfig {
  std::optional<QuiescentFlowConfig> quiescent;
  std::optional<UniformFlowConfig> uniform;
  std::optional<ShearFlowConfig> shear;
  std::optional<RotationFlowConfig> rotation;
  std::optional<TableFlowConfig> table;

  template <class V> void visit(V &v) {
    v.optional_section("quiescent", quiescent, "Fluid at rest: u = 0 (`quiescent: {}`).");
    v.optional_section("uniform", uniform, "Uniform flow u = U.");
    v.optional_section("shear", shear, "Linear shear flow.");
    v.optional_section("rotation", rotation, "Solid-body rotation about an axis.");
    v.optional_section("table", table, "Steady field tabulated on a grid (e.g. exported from a CFD run).");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      v.require_exactly_one({{"quiescent", quiescent.has_value()},
                             {"uniform", uniform.has_value()},
                             {"shear", shear.has_value()},
                             {"rotation", rotation.has_value()},
                             {"table", table.has_value()}});
  }
};

} // namespace fsi::prescribed_flow
