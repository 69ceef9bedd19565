#include "LagrangianSheet.hpp"

#include "StepSystemFactory.hpp"

#include <algorithm>
#include <stdexcept>
#include <cmath>

namespace fsi::structure {

LagrangianSheet::LagrangianSheet(SheetSetup setup)
    : setup_(std::move(setup)), measure_(setup_.grid.point_measures()), prescribed_(prescribed_points()),
      has_prescribed_(std::find(prescribed_.begin(), prescribed_.end(), true) != prescribed_.end()) {
  terms_ = std::make_unique<ElasticTerms>(setup_.grid, setup_.edges, setup_.shape_body_m, setup_.tension_coefficient,
                                          setup_.bending_rigidity, setup_.curved_rest_state, setup_.compression);
  const StepSettings step{*terms_,
                          measure_,
                          setup_.mass_per_measure,
                          setup_.damping_per_measure,
                          prescribed_,
                          setup_.linear_solver,
                          setup_.time_scheme};
  system_ = StepSystemFactory::builtin().make(setup_.tension_scheme, step);
  explicit_stretching_ = system_->explicit_stretching();
  x_ = prescribed_positions(0.0);
  const double dt = setup_.time_step_s;
  x_prev_ = x_ - dt * Eigen::VectorXd::Ones(x_.rows()) * setup_.initial_velocity_m_per_s.transpose();
  const PointArray prescribed_before = prescribed_positions(-dt);
  for (int i = 0; i < x_.rows(); ++i)
    if (prescribed_[static_cast<std::size_t>(i)])
      x_prev_.row(i) = prescribed_before.row(i);
  v_ = (x_ - x_prev_) / dt;
  load_.resize(x_.rows(), 3);
}

std::vector<bool> LagrangianSheet::prescribed_points() const {
  const auto &g = setup_.grid;
  const auto &e = setup_.edges;
  std::vector<bool> fixed(static_cast<std::size_t>(g.n_points()), false);
  for (int i1 = 0; i1 < g.n1(); ++i1)
    for (int i2 = 0; i2 < g.n2(); ++i2) {
      const bool on_fixed_edge = (i1 == 0 && e.s1_min != EdgeCondition::free) ||
                                 (i1 == g.n1() - 1 && e.s1_max != EdgeCondition::free) ||
                                 (!g.is_filament() && i2 == 0 && e.s2_min != EdgeCondition::free) ||
                                 (!g.is_filament() && i2 == g.n2() - 1 && e.s2_max != EdgeCondition::free);
      fixed[static_cast<std::size_t>(g.index(i1, i2))] = on_fixed_edge;
    }
  return fixed;
}

PointArray LagrangianSheet::prescribed_positions(double time_s) const {
  if (!setup_.clamp_motion)
    return setup_.shape_body_m;
  const Eigen::Isometry3d pose = setup_.clamp_motion->pose_at(time_s);
  PointArray world(setup_.shape_body_m.rows(), 3);
  for (int i = 0; i < world.rows(); ++i)
    world.row(i) = (pose * setup_.shape_body_m.row(i).transpose()).transpose();
  return world;
}

Eigen::Matrix3d LagrangianSheet::clamp_rotation(double time_s) const {
  return setup_.clamp_motion ? Eigen::Matrix3d(setup_.clamp_motion->pose_at(time_s).linear())
                             : Eigen::Matrix3d::Identity();
}

int LagrangianSheet::advance(const PointArray &load_density) {
  if (!system_)
    throw std::logic_error("structure '" + setup_.name + "' was removed from the scene (retired) and cannot advance");
  const double dt = setup_.time_step_s;
  // Nodal loads: (rho_1 g + load density) integrated over each point's measure.
  const Eigen::RowVector3d weight_density = setup_.mass_per_measure * setup_.gravity_m_per_s2.transpose();
  load_ = measure_.asDiagonal() * (load_density.rowwise() + weight_density);
  // Prescribed positions are only needed (and only computed) when some points are pinned or clamped.
  const PointArray prescribed_next = has_prescribed_ ? prescribed_positions(time_s_ + dt) : PointArray();
  StepInputs in{&x_, &x_prev_, &load_, &prescribed_next, clamp_rotation(time_s_ + dt), dt};
  PointArray x_next;
  const int iterations = system_->solve(in, x_next);
  x_prev_ = std::move(x_);
  x_ = std::move(x_next);
  time_s_ += dt;
  v_ = (x_ - x_prev_) / dt;
  return iterations;
}

void LagrangianSheet::restore_prescribed(double time_s) {
  if (!has_prescribed_)
    return;
  const PointArray prescribed = prescribed_positions(time_s);
  for (int i = 0; i < x_.rows(); ++i)
    if (prescribed_[static_cast<std::size_t>(i)])
      x_.row(i) = prescribed.row(i);
}

void LagrangianSheet::correct_positions(const std::function<void(PointArray &)> &correction) {
  correction(x_);
  restore_prescribed(time_s_);
  v_ = (x_ - x_prev_) / setup_.time_step_s;
}

void LagrangianSheet::set_state(const PointArray &x_now, const PointArray &x_prev) {
  x_ = x_now;
  x_prev_ = x_prev;
  v_ = (x_ - x_prev_) / setup_.time_step_s;
}

void LagrangianSheet::restore_state(const PointArray &x_m, const PointArray &v_m_per_s, double time_s) {
  x_ = x_m;
  v_ = v_m_per_s;
  x_prev_ = x_ - setup_.time_step_s * v_;
  time_s_ = time_s;
}

void LagrangianSheet::save_state(checkpoint::StateArchive &archive, const std::string &prefix) const {
  archive.put_points(prefix + "x_m", x_);
  archive.put_points(prefix + "x_previous_m", x_prev_);
  archive.put_points(prefix + "velocity_m_per_s", v_);
  archive.put_double(prefix + "time_s", time_s_);
}

void LagrangianSheet::load_state(const checkpoint::StateArchive &archive, const std::string &prefix) {
  // X^{n-1} is read, not rebuilt from V^n: after a collision correction V^n = (X^n - X^{n-1}) / dt
  // holds, but X^n - dt V^n rounds differently, and the next step would not be the same step.
  const long n = x_.rows();
  x_ = archive.points(prefix + "x_m", n);
  x_prev_ = archive.points(prefix + "x_previous_m", n);
  v_ = archive.points(prefix + "velocity_m_per_s", n);
  time_s_ = archive.number(prefix + "time_s");
}

StructureEnergy LagrangianSheet::energy() const {
  StructureEnergy e;
  const Eigen::VectorXd mass = setup_.mass_per_measure * measure_;
  e.kinetic_j = 0.5 * (mass.array() * v_.rowwise().squaredNorm().array()).sum();
  e.elastic_j = terms_->energy(x_, clamp_rotation(time_s_)).total();
  e.potential_j = -(mass.transpose() * (x_ * setup_.gravity_m_per_s2))(0);
  return e;
}

int LagrangianSheet::worst_point() const {
  for (int i = 0; i < x_.rows(); ++i)
    if (!x_.row(i).allFinite())
      return i;
  return terms_->most_stretched_point(x_);
}

std::string LagrangianSheet::describe_point(int index) const {
  const int n2 = setup_.grid.n2();
  if (setup_.grid.is_filament())
    return "point " + std::to_string(index) + " (s = " + std::to_string(index * setup_.grid.ds1()) + " m)";
  return "point " + std::to_string(index) + " (i1, i2) = (" + std::to_string(index / n2) + ", " +
         std::to_string(index % n2) + ")";
}

} // namespace fsi::structure
