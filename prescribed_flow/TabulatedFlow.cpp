#include "TabulatedFlow.hpp"

#include "common/ConfigError.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <sstream>

namespace fsi::prescribed_flow {

namespace {

using common::ConfigError;

struct Row {
  Vec3 x, u;
};

std::vector<Row> read_rows(const std::filesystem::path &file) {
  std::ifstream in(file);
  if (!in)
    throw ConfigError(file.string() + ": cannot open the velocity table.");
  std::string line;
  std::getline(in, line);
  line.erase(std::remove_if(line.begin(), line.end(), ::isspace), line.end());
  if (line != "x_m,y_m,z_m,u_m_per_s,v_m_per_s,w_m_per_s")
    throw ConfigError(file.string() + ":1: the header must be 'x_m,y_m,z_m,u_m_per_s,v_m_per_s,w_m_per_s'.");
  std::vector<Row> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    Row r;
    if (!(fields >> r.x[0] >> r.x[1] >> r.x[2] >> r.u[0] >> r.u[1] >> r.u[2]) || !r.x.allFinite() || !r.u.allFinite())
      throw ConfigError(file.string() + ":" + std::to_string(number) + ": expected six finite numbers.");
    rows.push_back(r);
  }
  return rows;
}

std::vector<double> unique_sorted(const std::vector<Row> &rows, int axis) {
  std::vector<double> values;
  for (const auto &r : rows)
    values.push_back(r.x[axis]);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

/// Index of the cell holding v and the weight of its upper node (clamped outside).
std::pair<std::size_t, double> locate(const std::vector<double> &axis, double v) {
  if (axis.size() == 1 || v <= axis.front())
    return {0, 0.0};
  if (v >= axis.back())
    return {axis.size() - 2, 1.0};
  const auto upper = std::upper_bound(axis.begin(), axis.end(), v);
  const auto i = static_cast<std::size_t>(upper - axis.begin()) - 1;
  return {i, (v - axis[i]) / (axis[i + 1] - axis[i])};
}

} // namespace

TabulatedFlow TabulatedFlow::from_csv(const std::filesystem::path &file) {
  const auto rows = read_rows(file);
  std::array<std::vector<double>, 3> axes{unique_sorted(rows, 0), unique_sorted(rows, 1), unique_sorted(rows, 2)};
  const std::size_t expected = axes[0].size() * axes[1].size() * axes[2].size();
  if (rows.size() != expected)
    throw ConfigError(file.string() + ": " + std::to_string(rows.size()) + " rows do not form a full regular grid (" +
                      std::to_string(axes[0].size()) + " x " + std::to_string(axes[1].size()) + " x " +
                      std::to_string(axes[2].size()) + " = " + std::to_string(expected) + " nodes).");
  std::vector<Vec3> values(expected);
  std::vector<bool> seen(expected, false);
  for (const auto &r : rows) {
    std::array<std::size_t, 3> ijk{};
    for (int a = 0; a < 3; ++a)
      ijk[a] = static_cast<std::size_t>(std::lower_bound(axes[a].begin(), axes[a].end(), r.x[a]) - axes[a].begin());
    const std::size_t index = (ijk[0] * axes[1].size() + ijk[1]) * axes[2].size() + ijk[2];
    if (seen[index])
      throw ConfigError(file.string() + ": the node at (" + std::to_string(r.x[0]) + ", " + std::to_string(r.x[1]) +
                        ", " + std::to_string(r.x[2]) + ") m appears twice.");
    seen[index] = true;
    values[index] = r.u;
  }
  return TabulatedFlow(axes[0], axes[1], axes[2], std::move(values), file.string());
}

TabulatedFlow::TabulatedFlow(std::vector<double> x_m, std::vector<double> y_m, std::vector<double> z_m,
                             std::vector<Vec3> values_m_per_s, std::string source)
    : axes_{std::move(x_m), std::move(y_m), std::move(z_m)}, values_(std::move(values_m_per_s)),
      source_(std::move(source)) {
  for (const auto &axis : axes_)
    if (axis.empty() || !std::is_sorted(axis.begin(), axis.end()) ||
        std::adjacent_find(axis.begin(), axis.end()) != axis.end())
      throw std::invalid_argument(source_ + ": grid coordinates must be strictly increasing");
  if (values_.size() != axes_[0].size() * axes_[1].size() * axes_[2].size())
    throw std::invalid_argument(source_ + ": number of values does not match the grid");
}

std::string TabulatedFlow::describe() const {
  return "tabulated (" + source_ + ", " + std::to_string(axes_[0].size()) + " x " + std::to_string(axes_[1].size()) +
         " x " + std::to_string(axes_[2].size()) + " nodes)";
}

Vec3 TabulatedFlow::velocity_m_per_s(const Vec3 &x_m, double) const {
  const auto [i, wx] = locate(axes_[0], x_m.x());
  const auto [j, wy] = locate(axes_[1], x_m.y());
  const auto [k, wz] = locate(axes_[2], x_m.z());
  const auto next = [](std::size_t index, const std::vector<double> &axis) {
    return std::min(index + 1, axis.size() - 1);
  };
  const std::size_t i1 = next(i, axes_[0]), j1 = next(j, axes_[1]), k1 = next(k, axes_[2]);
  Vec3 u = Vec3::Zero();
  for (int corner = 0; corner < 8; ++corner) {
    const bool hx = corner & 1, hy = corner & 2, hz = corner & 4;
    const double w = (hx ? wx : 1 - wx) * (hy ? wy : 1 - wy) * (hz ? wz : 1 - wz);
    if (w != 0.0)
      u += w * at(hx ? i1 : i, hy ? j1 : j, hz ? k1 : k);
  }
  return u;
}

} // namespace fsi::prescribed_flow
