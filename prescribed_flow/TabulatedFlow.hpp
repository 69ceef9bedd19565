#pragma once
// A steady velocity field tabulated on a regular (rectilinear) grid, interpolated trilinearly;
// points outside the grid take the value of the nearest grid face (clamped). Read from a CSV
// with header `x_m,y_m,z_m,u_m_per_s,v_m_per_s,w_m_per_s`, one row per grid node, any order.

#include "FlowField.hpp"

#include <array>
#include <filesystem>
#include <vector>

namespace fsi::prescribed_flow {

class TabulatedFlow final : public FlowField {
public:
  /// Throws common::ConfigError naming the file and line for any malformed input.
  static TabulatedFlow from_csv(const std::filesystem::path &file);
  /// Grid coordinates (strictly increasing, >= 1 node each); values[(i * ny + j) * nz + k].
  TabulatedFlow(std::vector<double> x_m, std::vector<double> y_m, std::vector<double> z_m,
                std::vector<Vec3> values_m_per_s, std::string source = "table");

  std::string describe() const override;
  Vec3 velocity_m_per_s(const Vec3 &x_m, double time_s) const override;

private:
  const Vec3 &at(std::size_t i, std::size_t j, std::size_t k) const {
    return values_[(i * axes_[1].size() + j) * axes_[2].size() + k];
  }

  std::array<std::vector<double>, 3> axes_;
  std::vector<Vec3> values_;
  std::string source_;
};

} // namespace fsi::prescribed_flow
