#include "FlowFactory.hpp"

#include "AnalyticFlows.hpp"
#include "TabulatedFlow.hpp"

#include <stdexcept>

namespace fsi::prescribed_flow {

namespace {

std::unique_ptr<FlowField> make_shear(const ShearFlowConfig &c) {
  if (c.flow_direction.norm() == 0.0 || c.gradient_direction.norm() == 0.0)
    throw common::ConfigError("fluid.prescribed.shear: flow_direction and gradient_direction must not be zero.");
  const Vec3 e = c.flow_direction.normalized(), g = c.gradient_direction.normalized();
  if (std::abs(e.dot(g)) > 1e-9)
    throw common::ConfigError("fluid.prescribed.shear: flow_direction must be perpendicular to gradient_direction "
                              "(otherwise the flow is not divergence-free).");
  const Eigen::Matrix3d gradient = c.shear_rate_1_per_s * e * g.transpose();
  return std::make_unique<LinearFlow>(c.reference_velocity_m_per_s, c.reference_point_m, gradient);
}

} // namespace

std::unique_ptr<FlowField> make_flow(const PrescribedFlowConfig &config) {
  if (config.uniform)
    return std::make_unique<UniformFlow>(config.uniform->velocity_m_per_s);
  if (config.shear)
    return make_shear(*config.shear);
  if (config.rotation) {
    if (config.rotation->axis_direction.norm() == 0.0)
      throw common::ConfigError("fluid.prescribed.rotation.axis_direction must not be the zero vector.");
    return std::make_unique<SolidBodyRotation>(config.rotation->axis_point_m, config.rotation->axis_direction,
                                               config.rotation->rate_rad_per_s);
  }
  if (config.table)
    return std::make_unique<TabulatedFlow>(TabulatedFlow::from_csv(config.table->file));
  return std::make_unique<QuiescentFlow>();
}

} // namespace fsi::prescribed_flow
