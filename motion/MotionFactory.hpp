#pragma once
// The registry of prescribed rigid motions: builds a RigidMotion from its configuration.

#include "MotionConfig.hpp"
#include "RigidMotion.hpp"

#include <memory>

namespace fsi::motion {

/// `gravity_m_per_s2` is the magnitude of the case's gravity (used by the pendulum).
std::shared_ptr<const RigidMotion> make_motion(const MotionConfig &config, double gravity_m_per_s2);

/// Reads a 'time_s,angle_rad' CSV file; throws common::ConfigError naming the file and line.
std::vector<std::pair<double, double>> read_angle_table(const std::filesystem::path &file);

} // namespace fsi::motion
