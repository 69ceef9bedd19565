#pragma once
// The velocity field of a rigid body at one instant: u_rib(x) = v_o + omega x (x - o)
// (the u_rib of Eq. 9), with o the world origin. Taken once per step from the motion, so
// that evaluating it at many cells costs a cross product each, not a virtual call.

#include "motion/RigidMotion.hpp"
#include "common/Types.hpp"

namespace fsi::fluid::rigid {

struct RigidVelocity {
  Vec3 origin_velocity_m_per_s = Vec3::Zero(); ///< v_o: velocity of the body point at the world origin
  Vec3 angular_velocity_rad_per_s = Vec3::Zero(); ///< omega

  /// Reads v_o and omega off motion.velocity_at() at four points (exact: a rigid velocity
  /// field is affine in x; omega is the axial vector of its gradient's skew part).
  static RigidVelocity of(const motion::RigidMotion &motion, double time_s);

  Vec3 at(const Vec3 &point_world_m) const {
    return origin_velocity_m_per_s + angular_velocity_rad_per_s.cross(point_world_m);
  }
};

} // namespace fsi::fluid::rigid
