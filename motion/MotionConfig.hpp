#pragma once
// Configuration of a prescribed rigid motion: exactly one of the sections below. Each is a
// rotation about an axis (point + direction); they differ in the angle history theta(t).

#include "common/ConfigReader.hpp"

#include <filesystem>
#include <optional>

namespace fsi::motion {

struct AxisConfig {
  Vec3 axis_point_m{0.0, 0.0, 0.0};
  Vec3 axis_direction{0.0, 0.0, 1.0};
  template <class V> void visit_axis(V &v) {
    v.vec3("axis_point_m", axis_point_m, "m", "A point on the rotation axis.");
    v.vec3("axis_direction", axis_direction, "1", "Direction of the rotation axis (right-hand rule; normalised).");
  }
};

struct ConstantRotationConfig : AxisConfig {
  double rate_rad_per_s = 0.0;
  template <class V> void visit(V &v) {
    visit_axis(v);
    v.number("rate_rad_per_s", rate_rad_per_s, common::Range::any("rad/s"), "Constant angular velocity.");
  }
};

struct OscillationConfig : AxisConfig {
  double amplitude_rad = 0.0;
  double frequency_hz = 1.0;
  double phase_rad = 0.0;
  template <class V> void visit(V &v) {
    visit_axis(v);
    v.number("amplitude_rad", amplitude_rad, common::Range::any("rad"), "theta(t) = amplitude sin(2 pi f t + phase).");
    v.number("frequency_hz", frequency_hz, common::Range::positive("Hz"), "Oscillation frequency f.");
    v.number("phase_rad", phase_rad, common::Range::any("rad"), "Phase at t = 0.");
  }
};

struct PendulumConfig : AxisConfig {
  double length_m = 0.1;
  double initial_angle_deg = 30.0;
  template <class V> void visit(V &v) {
    visit_axis(v);
    v.number("length_m", length_m, common::Range::positive("m"),
             "Equivalent simple-pendulum length L: theta'' = -(g/L) sin(theta), g from the case gravity.");
    v.number("initial_angle_deg", initial_angle_deg, common::Range::between(-179.0, 179.0, "deg"),
             "Release angle; released from rest at t = 0.");
  }
};

struct TableMotionConfig : AxisConfig {
  std::filesystem::path file;
  template <class V> void visit(V &v) {
    visit_axis(v);
    v.existing_file("file", file, "CSV with header 'time_s,angle_rad'; linear interpolation, held constant outside.");
  }
};

struct MotionConfig {
  std::optional<ConstantRotationConfig> rotation;
  std::optional<OscillationConfig> oscillation;
  std::optional<PendulumConfig> pendulum;
  std::optional<TableMotionConfig> table;

  template <class V> void visit(V &v) {
    v.optional_section("rotation", rotation, "Rotation at a constant rate (an impeller).");
    v.optional_section("oscillation", oscillation, "Harmonic angular oscillation.");
    v.optional_section("pendulum", pendulum, "Free pendulum swinging in vacuum (nonlinear, RK4).");
    v.optional_section("table", table, "Angle history read from a CSV file (measured motion).");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      v.require_exactly_one({{"rotation", rotation.has_value()},
                             {"oscillation", oscillation.has_value()},
                             {"pendulum", pendulum.has_value()},
                             {"table", table.has_value()}});
  }
};

} // namespace fsi::motion
