#include "CoupledStructure.hpp"

#include <cmath>

namespace fsi::structure {

CoupledStructure::CoupledStructure(StructureRun &run) : run_(run) {
  run_.start(StructureRun::Resume::when_told); // the coupler says where the run starts
  for (const auto &s : run_.scene().structures())
    loads_.push_back(PointArray::Zero(s->n_points(), 3));
}

std::string CoupledStructure::describe() const {
  std::string names;
  for (const auto &s : run_.scene().structures())
    names += (names.empty() ? "" : ", ") + s->name() + " (" + s->model() + ")";
  return "the membrane solver: " + names;
}

std::vector<participant::StructureTopology> CoupledStructure::topology() const {
  std::vector<participant::StructureTopology> out;
  const auto specs = life_specs(run_.config().structures);
  for (std::size_t i = 0; i < run_.scene().structures().size(); ++i) {
    const auto &s = run_.scene().structures()[i];
    const auto [n1, n2] = s->grid_shape();
    out.push_back({s->name(), s->model(), static_cast<int>(n1), static_cast<int>(n2), s->point_measures(),
                   s->mass_per_measure(), specs[i]});
  }
  return out;
}

void CoupledStructure::start(const participant::RunPlan &plan) {
  const double dt = run_.config().run.time_step_s;
  if (std::abs(plan.time_step_s - dt) > 1e-12 * dt || plan.n_steps != run_.n_steps())
    throw std::runtime_error("the coupler runs " + std::to_string(plan.n_steps) + " steps of " +
                             std::to_string(plan.time_step_s) + " s; this case has " + std::to_string(run_.n_steps()) +
                             " steps of " + std::to_string(dt) + " s");
  if (plan.first_step == 0)
    run_.begin_fresh();
}

void CoupledStructure::resume(long step, const std::string &checksum) { run_.resume_from(step, checksum); }

checkpoint::CheckpointPart CoupledStructure::write_checkpoint(long n_completed) {
  const auto folder = run_.checkpoints().folder(n_completed);
  std::filesystem::create_directories(folder);
  return run_.write_checkpoint_part(folder, n_completed);
}

void CoupledStructure::accept_step(long step) {
  // Accepted: now the stretch and speed guards, and the output.
  if (const StepOutcome outcome = run_.accept_step(step); outcome.kind == StepOutcome::Kind::diverged)
    throw participant::Diverged(outcome.message);
}

template <class Field> void CoupledStructure::concatenate(proto::MutablePointsView out, Field field) const {
  Eigen::Index at = 0;
  for (const auto &s : run_.scene().structures()) {
    out.middleRows(at, s->n_points()) = field(*s);
    at += s->n_points();
  }
}

void CoupledStructure::positions(proto::MutablePointsView x_m) const {
  concatenate(x_m, [](const auto &s) -> const PointArray & { return s.positions_m(); });
}

void CoupledStructure::velocities(proto::MutablePointsView v_m_per_s) const {
  concatenate(v_m_per_s, [](const auto &s) -> const PointArray & { return s.velocities_m_per_s(); });
}

double CoupledStructure::time_s() const { return run_.scene().time_s(); }

void CoupledStructure::advance(const participant::StructureStep &step, proto::PointsView load_density_n_per_measure) {
  Eigen::Index at = 0;
  for (auto &l : loads_) {
    l = load_density_n_per_measure.middleRows(at, l.rows());
    at += l.rows();
  }
  take_rigid_poses(step);
  check_idle(step);
  const StepOutcome outcome = run_.advance_step(step.step, &loads_, step.record);
  if (outcome.kind == StepOutcome::Kind::diverged)
    throw participant::Diverged(outcome.message);
  // A coupled run leaves a stop signal to the coupler (StructureRun::start(Resume::when_told)):
  // advance_step never stops on one here.
}

void CoupledStructure::check_idle(const participant::StructureStep &step) const {
  // The coupler keeps the same life cycle on the same accepted positions: its idle list for the
  // step is this scene's after the releases due at the step's start.
  const auto own = run_.scene().life().idle_after_release(run_.scene().time_s());
  if (step.idle_structures == own)
    return;
  const auto list = [](const std::vector<std::uint32_t> &v) {
    std::string s;
    for (const auto i : v)
      s += (s.empty() ? "" : ", ") + std::to_string(i);
    return "[" + s + "]";
  };
  throw std::runtime_error("step " + std::to_string(step.step) + ": the coupler holds structures " +
                           list(step.idle_structures) + " idle, this solver " + list(own) +
                           ": the two life cycles disagree (a coupler of another build?)");
}

void CoupledStructure::take_rigid_poses(const participant::StructureStep &step) {
  // Eq. (11) corrects against the surfaces at the end of the step, where the coupler put them.
  const double end_time_s = step.time_s + step.dt_s;
  for (const proto::BodyPose &pose : step.surfaces) {
    motion::CoupledMotion *motion = run_.scene().coupled_motion(pose.name);
    if (!motion)
      throw std::runtime_error("the coupler sent the pose of '" + pose.name +
                               "', which is not a moving surface of this case");
    motion->set(end_time_s, pose.pose, pose.origin_velocity_m_per_s, pose.angular_velocity_rad_per_s);
  }
  if (step.surfaces.size() != run_.scene().n_coupled_motions())
    throw std::runtime_error("the coupler sent " + std::to_string(step.surfaces.size()) +
                             " rigid-body poses; this case has " + std::to_string(run_.scene().n_coupled_motions()) +
                             " moving surfaces");
}

} // namespace fsi::structure
