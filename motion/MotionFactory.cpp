#include "MotionFactory.hpp"

#include "AxisRotation.hpp"
#include "PendulumHistory.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace fsi::motion {

namespace {

std::shared_ptr<const RigidMotion> make_rotation(const ConstantRotationConfig &c) {
  const double rate = c.rate_rad_per_s;
  return std::make_shared<AxisRotation>(
      c.axis_point_m, c.axis_direction, [rate](double t) { return rate * t; }, [rate](double) { return rate; });
}

std::shared_ptr<const RigidMotion> make_oscillation(const OscillationConfig &c) {
  const double a = c.amplitude_rad, w = 2.0 * M_PI * c.frequency_hz, phase = c.phase_rad;
  return std::make_shared<AxisRotation>(
      c.axis_point_m, c.axis_direction, [=](double t) { return a * std::sin(w * t + phase); },
      [=](double t) { return a * w * std::cos(w * t + phase); });
}

std::shared_ptr<const RigidMotion> make_pendulum(const PendulumConfig &c, double gravity) {
  if (!(gravity > 0.0))
    throw common::ConfigError("a pendulum motion needs a non-zero gravity_m_per_s2 in the case.");
  auto history = std::make_shared<PendulumHistory>(gravity, c.length_m, c.initial_angle_deg * M_PI / 180.0);
  return std::make_shared<AxisRotation>(
      c.axis_point_m, c.axis_direction, [history](double t) { return history->angle_rad(t); },
      [history](double t) { return history->rate_rad_per_s(t); });
}

double interpolate(const std::vector<std::pair<double, double>> &table, double t, bool derivative) {
  if (table.size() == 1 || t <= table.front().first)
    return derivative ? 0.0 : table.front().second;
  if (t >= table.back().first)
    return derivative ? 0.0 : table.back().second;
  const auto upper = std::upper_bound(table.begin(), table.end(), t,
                                      [](double value, const auto &row) { return value < row.first; });
  const auto lower = upper - 1;
  const double slope = (upper->second - lower->second) / (upper->first - lower->first);
  return derivative ? slope : lower->second + slope * (t - lower->first);
}

std::shared_ptr<const RigidMotion> make_table(const TableMotionConfig &c) {
  auto table = std::make_shared<std::vector<std::pair<double, double>>>(read_angle_table(c.file));
  return std::make_shared<AxisRotation>(
      c.axis_point_m, c.axis_direction, [table](double t) { return interpolate(*table, t, false); },
      [table](double t) { return interpolate(*table, t, true); });
}

} // namespace

std::vector<std::pair<double, double>> read_angle_table(const std::filesystem::path &file) {
  std::ifstream in(file);
  if (!in)
    throw common::ConfigError(file.string() + ": cannot open the motion table.");
  std::string line;
  std::getline(in, line);
  line.erase(std::remove_if(line.begin(), line.end(), ::isspace), line.end());
  if (line != "time_s,angle_rad")
    throw common::ConfigError(file.string() + ":1: the header must be 'time_s,angle_rad' (found '" + line + "').");
  std::vector<std::pair<double, double>> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::istringstream fields(line);
    double t = 0, angle = 0;
    char comma = 0;
    if (!(fields >> t >> comma >> angle) || comma != ',' || !std::isfinite(t) || !std::isfinite(angle))
      throw common::ConfigError(file.string() + ":" + std::to_string(number) + ": expected 'time_s,angle_rad', found '" +
                        line + "'.");
    if (!rows.empty() && t <= rows.back().first)
      throw common::ConfigError(file.string() + ":" + std::to_string(number) + ": times must increase strictly.");
    rows.emplace_back(t, angle);
  }
  if (rows.empty())
    throw common::ConfigError(file.string() + ": the motion table has no rows.");
  return rows;
}

std::shared_ptr<const RigidMotion> make_motion(const MotionConfig &config, double gravity_m_per_s2) {
  if (config.rotation)
    return make_rotation(*config.rotation);
  if (config.oscillation)
    return make_oscillation(*config.oscillation);
  if (config.pendulum)
    return make_pendulum(*config.pendulum, gravity_m_per_s2);
  if (config.table)
    return make_table(*config.table);
  return std::make_shared<StaticPose>();
}

} // namespace fsi::motion
