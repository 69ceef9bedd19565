#include "fluid_adapter/rigid/RigidVelocity.hpp"

namespace fsi::fluid::rigid {

RigidVelocity RigidVelocity::of(const motion::RigidMotion &motion, double time_s) {
  if (motion.is_static())
    return {};
  RigidVelocity velocity;
  velocity.origin_velocity_m_per_s = motion.velocity_at(Vec3::Zero(), time_s);
  Eigen::Matrix3d gradient; // column i: du/dx_i
  for (int i = 0; i < 3; ++i)
    gradient.col(i) = motion.velocity_at(Vec3::Unit(i), time_s) - velocity.origin_velocity_m_per_s;
  velocity.angular_velocity_rad_per_s = 0.5 * Vec3(gradient(2, 1) - gradient(1, 2),
                                                   gradient(0, 2) - gradient(2, 0),
                                                   gradient(1, 0) - gradient(0, 1));
  return velocity;
}

} // namespace fsi::fluid::rigid
