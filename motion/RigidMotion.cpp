#include "RigidMotion.hpp"

namespace fsi::motion {

Eigen::Vector3d RigidMotion::velocity_at(const Eigen::Vector3d &world_point_m, double time_s) const {
  // x(t) = P(t) P(t0)^-1 x0: differentiate the world position of the body-fixed point.
  const double h = 1e-6;
  const Eigen::Vector3d body = pose_at(time_s).inverse() * world_point_m;
  return (pose_at(time_s + h) * body - pose_at(time_s - h) * body) / (2.0 * h);
}

} // namespace fsi::motion
