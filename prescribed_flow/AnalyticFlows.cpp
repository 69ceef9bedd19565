#include "AnalyticFlows.hpp"

#include <sstream>
#include <stdexcept>

namespace fsi::prescribed_flow {

namespace {
std::string format(const Vec3 &v) {
  std::ostringstream out;
  out << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return out.str();
}
} // namespace

std::string UniformFlow::describe() const { return "uniform " + format(u_) + " m/s"; }

LinearFlow::LinearFlow(const Vec3 &reference_velocity_m_per_s, const Vec3 &reference_point_m,
                       const Eigen::Matrix3d &gradient_1_per_s)
    : u0_(reference_velocity_m_per_s), x0_(reference_point_m), g_(gradient_1_per_s) {
  if (std::abs(g_.trace()) > 1e-12 * std::max(1.0, g_.norm()))
    throw std::invalid_argument("a linear flow must be divergence-free (trace of the velocity gradient = 0)");
}

std::string LinearFlow::describe() const { return "linear, u = " + format(u0_) + " m/s + G (x - x0)"; }

SolidBodyRotation::SolidBodyRotation(const Vec3 &axis_point_m, const Vec3 &axis_direction, double rate_rad_per_s)
    : point_(axis_point_m) {
  if (axis_direction.norm() == 0.0)
    throw std::invalid_argument("the rotation axis direction must not be the zero vector");
  omega_ = rate_rad_per_s * axis_direction.normalized();
}

std::string SolidBodyRotation::describe() const {
  return "solid-body rotation " + format(omega_) + " rad/s about " + format(point_) + " m";
}

} // namespace fsi::prescribed_flow
