#pragma once
// The prescribed flow as a fluid model (fsi-prescribed-flow): the velocity at the Lagrangian
// points comes from a FlowField, and the FSI force has no effect on the flow (one-way
// coupling). The coupler still records the total force the structures exert on the fluid
// (coupling.h5), which a two-way model would feel.

#include "FlowField.hpp"
#include "participant/FluidModel.hpp"

#include <filesystem>
#include <memory>

namespace fsi::prescribed_flow {

class PrescribedFlowModel final : public participant::FluidModel {
  using PointsView = participant::PointsView;

public:
  /// checkpoints: the run's <output>/checkpoints, where its part of each set goes.
  PrescribedFlowModel(std::unique_ptr<FlowField> flow, std::filesystem::path checkpoints);

  std::string describe() const override;
  void start(const participant::RunPlan &) override {}
  void interpolate(double time_s, PointsView x_m, participant::MutablePointsView u_m_per_s) override;
  /// One-way coupling: the flow is prescribed, so F_fsi (Eq. 8) is not spread, wherever.
  void spread_at(PointsView) override {}
  /// A function of time and place: a repeated step is the same step.
  void save_step_start() override {}
  void restore_step_start() override {}
  void advance(const participant::FluidStep &, PointsView, std::vector<participant::BodyLoad> &) override {}
  void finish(const participant::RunEnd &) override {}
  /// The flow is a function of time and place: the part (fluid.ckpt) holds the step and the
  /// flow's description only, so that a restart checks that the flow is the same one.
  checkpoint::CheckpointPart write_checkpoint(long n_completed) override;
  void resume(long step, const std::string &checksum) override;

private:
  std::filesystem::path checkpoints_;
  std::unique_ptr<FlowField> flow_;
  PointArray positions_, velocities_;
};

} // namespace fsi::prescribed_flow
