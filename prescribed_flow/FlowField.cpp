#include "FlowField.hpp"

namespace fsi::prescribed_flow {

void FlowField::velocities(const PointArray &x_m, double time_s, PointArray &u_m_per_s) const {
  u_m_per_s.resize(x_m.rows(), 3);
  for (Eigen::Index i = 0; i < x_m.rows(); ++i)
    u_m_per_s.row(i) = velocity_m_per_s(x_m.row(i).transpose(), time_s).transpose();
}

} // namespace fsi::prescribed_flow
