#pragma once
// A prescribed fluid velocity field u(x, t): the "fluid" of one-way coupled scenes, where a
// structure moves in a known flow instead of a Navier-Stokes solution (a model choice, much
// cheaper than OpenFOAM, for flows the structure does not disturb).

#include "common/Types.hpp"

#include <string>

namespace fsi::prescribed_flow {

class FlowField {
public:
  virtual ~FlowField() = default;
  virtual std::string describe() const = 0;
  /// Velocity (m/s) at position x (m) and time t (s).
  virtual Vec3 velocity_m_per_s(const Vec3 &x_m, double time_s) const = 0;
  /// Velocities at many points (N x 3); the default loops over velocity_m_per_s().
  virtual void velocities(const PointArray &x_m, double time_s, PointArray &u_m_per_s) const;
};

} // namespace fsi::prescribed_flow
