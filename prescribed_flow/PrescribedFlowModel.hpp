#pragma once
// The prescribed flow as a fluid model (fsi-prescribed-flow): the velocity at the Lagrangian
// points comes from a FlowField, and the FSI force has no effect on the flow (one-way
// coupling). The coupler still records the total force the structures exert on the fluid
// (coupling.h5), which a two-way model would feel.

#include "FlowField.hpp"
#include "proto/FluidModel.hpp"

#include <memory>

namespace fsi::prescribed_flow {

class PrescribedFlowModel final : public proto::FluidModel {
public:
  explicit PrescribedFlowModel(std::unique_ptr<FlowField> flow);

  std::string describe() const override;
  void start(const proto::v2::Welcome &) override {}
  void interpolate(const proto::v2::InterpolateRequest &request, proto::PointsView x_m,
                   proto::MutablePointsView u_m_per_s) override;
  /// One-way coupling: the flow is prescribed, so F_fsi (Eq. 8) is not spread.
  void advance(const proto::v2::FluidAdvance &, proto::PointsView, proto::v2::AdvanceReply &) override {}
  void finish(bool) override {}

private:
  std::unique_ptr<FlowField> flow_;
  PointArray positions_, velocities_;
};

} // namespace fsi::prescribed_flow
