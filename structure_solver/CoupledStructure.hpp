#pragma once
// The membrane solver as the structure model of a coupled run (fsi-structure --coupled): every
// step takes the load -F_fsi^n and the moving surfaces at t^{n+1} from the coupler (through
// participant::StructureParticipant), advances Eq. (4) and Eq. (11) through StructureRun (same
// guards, output and progress as a standalone run) and keeps its results and checkpoints.

#include "StructureRun.hpp"
#include "participant/StructureModel.hpp"

namespace fsi::structure {

class CoupledStructure final : public participant::StructureModel {
public:
  /// Builds the run's scene (StructureRun::start: the results wait for the coupler's plan).
  explicit CoupledStructure(StructureRun &run);

  std::string describe() const override;
  std::vector<participant::StructureTopology> topology() const override;
  /// Refuses a plan of another time step or number of steps than the case's; a fresh run's
  /// results start from X^0.
  void start(const participant::RunPlan &plan) override;
  void resume(long step, const std::string &checksum) override;
  checkpoint::CheckpointPart write_checkpoint(long n_completed) override;
  void save_step_start() override { run_.save_step_start(); }
  void restore_step_start() override { run_.restore_step_start(); }
  void accept_step(long step) override;
  void finish(const participant::RunEnd &end) override { run_.finish(end.status(), end.steps); }

  void positions(proto::MutablePointsView x_m) const override;
  void velocities(proto::MutablePointsView v_m_per_s) const override;
  double time_s() const override;
  std::vector<double> max_stretch_ratios() const override { return run_.scene().max_stretch_ratios(); }
  void advance(const participant::StructureStep &step, proto::PointsView load_density_n_per_measure) override;

private:
  /// out: every structure's field(structure), in the order of topology().
  template <class Field> void concatenate(proto::MutablePointsView out, Field field) const;
  /// The moving rigid surfaces at the end of the step, from the coupler (section 2.3).
  /// Refuses a step whose idle structures are not the ones this scene's life cycle holds idle.
  void check_idle(const participant::StructureStep &step) const;
  void take_rigid_poses(const participant::StructureStep &step);

  StructureRun &run_;
  std::vector<PointArray> loads_;
};

} // namespace fsi::structure
