#include "PrescribedFlowModel.hpp"

namespace fsi::prescribed_flow {

PrescribedFlowModel::PrescribedFlowModel(std::unique_ptr<FlowField> flow) : flow_(std::move(flow)) {}

std::string PrescribedFlowModel::describe() const {
  return "prescribed, " + flow_->describe() + " (one-way coupling: the FSI force does not act on this flow)";
}

void PrescribedFlowModel::interpolate(const proto::v2::InterpolateRequest &request, proto::PointsView x_m,
                                      proto::MutablePointsView u_m_per_s) {
  positions_ = x_m;
  velocities_.resize(positions_.rows(), 3);
  flow_->velocities(positions_, request.time_s(), velocities_);
  u_m_per_s = velocities_;
}

} // namespace fsi::prescribed_flow
