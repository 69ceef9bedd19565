#pragma once
// Closed-form prescribed flows: quiescent, uniform, linear (shear or any constant velocity
// gradient) and solid-body rotation. Each is one small class.

#include "FlowField.hpp"

#include <Eigen/Core>

namespace fsi::prescribed_flow {

/// u = 0.
class QuiescentFlow final : public FlowField {
public:
  std::string describe() const override { return "quiescent"; }
  Vec3 velocity_m_per_s(const Vec3 &, double) const override { return Vec3::Zero(); }
};

/// u = U.
class UniformFlow final : public FlowField {
public:
  explicit UniformFlow(const Vec3 &velocity_m_per_s) : u_(velocity_m_per_s) {}
  std::string describe() const override;
  Vec3 velocity_m_per_s(const Vec3 &, double) const override { return u_; }

private:
  Vec3 u_;
};

/// u = U0 + G (x - x0): linear shear when G has one off-diagonal entry (du_x/dy = G(0, 1)).
class LinearFlow final : public FlowField {
public:
  LinearFlow(const Vec3 &reference_velocity_m_per_s, const Vec3 &reference_point_m,
             const Eigen::Matrix3d &gradient_1_per_s);
  std::string describe() const override;
  Vec3 velocity_m_per_s(const Vec3 &x_m, double) const override { return u0_ + g_ * (x_m - x0_); }

private:
  Vec3 u0_, x0_;
  Eigen::Matrix3d g_;
};

/// u = omega a x (x - p): rigid rotation about the axis through p along a.
class SolidBodyRotation final : public FlowField {
public:
  SolidBodyRotation(const Vec3 &axis_point_m, const Vec3 &axis_direction, double rate_rad_per_s);
  std::string describe() const override;
  Vec3 velocity_m_per_s(const Vec3 &x_m, double) const override { return omega_.cross(x_m - point_); }

private:
  Vec3 point_, omega_;
};

} // namespace fsi::prescribed_flow
