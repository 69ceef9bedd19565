#include "OpenFoamFluidModel.hpp"

#include "fluid_adapter/ibm/ClosestCellLinear.hpp"
#include "fluid_adapter/rigid/BodyLoads.hpp"
#include "proto/PackedPoints.hpp"

#include <spdlog/spdlog.h>

namespace fsi::fluid {

OpenFoamFluidModel::OpenFoamFluidModel(const OpenFoamConfig &config, FoamFlow &flow,
                                       std::vector<std::unique_ptr<rigid::RigidBody>> rigid_bodies)
    : config_(config), flow_(flow), cells_(flow.cell_centres_m(), flow.cell_volumes_m3()), index_(cells_),
      bodies_(std::move(rigid_bodies)) {
  for (const auto &body : bodies_) {
    indicators_.push_back(std::make_unique<rigid::BodyIndicator>(*body, cells_.centres_m()));
    spdlog::info("rigid body '{}': {} candidate cells of {} (swept region)", body->name(),
                 indicators_.back()->candidate_cells().size(), cells_.n_cells());
  }
}

std::string OpenFoamFluidModel::describe() const {
  return flow_.describe() + ", immersed boundary: Peskin 4-point kernel (Eqs. 6-8), interpolation " +
         (config_.interpolation == InterpolationChoice::kernel ? "kernel" : "closest_cell_linear") +
         (config_.normalise_kernel ? ", normalised weights" : ", raw weights");
}

void OpenFoamFluidModel::start(const proto::v1::Welcome &welcome) {
  Eigen::Index n = 0;
  for (const auto &s : welcome.structures())
    n += static_cast<Eigen::Index>(s.n1()) * s.n2();
  point_measures_.resize(n);
  Eigen::Index at = 0;
  for (const auto &s : welcome.structures())
    for (const double m : s.point_measure())
      point_measures_[at++] = m;
  spdlog::info("{}", describe());
}

void OpenFoamFluidModel::interpolate(const proto::v1::InterpolateRequest &, proto::PointsView x_m,
                                     proto::MutablePointsView u_m_per_s) {
  // X_ib^n: the kernel width is the size of the cell nearest to each point (local h, Eq. 6).
  positions_ = x_m;
  nearest_ = std::make_unique<ibm::NearestCells>(index_, positions_);
  stencil_ = std::make_unique<ibm::KernelStencil>(index_, positions_, nearest_->kernel_width_m());
  if (config_.normalise_kernel)
    stencil_->normalise_weights(stencil_->weight_sums());
  flow_.cell_velocities(cell_velocity_);
  if (config_.interpolation == InterpolationChoice::kernel) {
    u_m_per_s = stencil_->interpolate(cell_velocity_);
    return;
  }
  ibm::CellGradientArray gradients;
  flow_.cell_velocity_gradients(gradients);
  u_m_per_s = ibm::ClosestCellLinear(cells_, *nearest_).interpolate(positions_, cell_velocity_, gradients);
}

void OpenFoamFluidModel::advance(const proto::v1::FluidAdvance &request, proto::PointsView force_density_n_per_m2,
                                 proto::v1::AdvanceReply &reply) {
  // Eq. (8) at the points of this step's interpolation (X^n): N/m^2 x m^2 -> N/m^3 per cell,
  // then per unit density for OpenFOAM's kinematic momentum equation (Eq. 1: +f_fsi).
  force_density_ = force_density_n_per_m2;
  acceleration_ = stencil_->spread(force_density_, point_measures_) / config_.density_kg_per_m3;
  flow_.set_fsi_acceleration(acceleration_);
  const double t_next = request.time_s() + request.dt_s();
  if (!bodies_.empty())
    penalize_rigid_bodies(t_next);
  flow_.advance(request.dt_s());
  if (!bodies_.empty())
    report_rigid_body_loads(t_next, reply);
}

void OpenFoamFluidModel::penalize_rigid_bodies(double time_s) {
  // Section 2.3, first bullet: the rigid surfaces move first. chi and u_rib at t^{n+1}, where
  // the implicit penalization enforces u = u_rib.
  const Eigen::Index n = cells_.n_cells();
  penalization_rate_.setZero(n);
  rigid_velocity_.setZero(n, 3);
  for (auto &indicator : indicators_) {
    indicator->update(time_s);
    for (const auto c : indicator->candidate_cells()) {
      const double chi = indicator->chi()[c];
      if (chi <= 0.0)
        continue;
      penalization_rate_[c] = std::min(1.0, penalization_rate_[c] + chi);
      rigid_velocity_.row(c) += chi * indicator->body_velocity_m_per_s().row(c);
    }
  }
  penalization_rate_ /= config_.penalization_time_s;
}

void OpenFoamFluidModel::report_rigid_body_loads(double time_s, proto::v1::AdvanceReply &reply) {
  flow_.penalization_acceleration(penalization_acceleration_);
  penalization_force_ = penalization_acceleration_ * config_.density_kg_per_m3; // N/m^3 on the fluid
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto &body = *bodies_[b];
    // Torque about the body's centre (the centre of its bounding box, carried by its motion).
    const Vec3 centre = body.motion().pose_at(time_s) * body.body_box_m().center();
    const rigid::BodyLoad load = rigid::BodyLoads::from_source_on_fluid(
        *indicators_[b], cells_.centres_m(), penalization_force_, cells_.volumes_m3(), centre);
    auto *out = reply.add_rigid_body_loads();
    out->set_name(body.name());
    proto::write_vector3(load.force_n, *out->mutable_force_n());
    proto::write_vector3(load.torque_n_m, *out->mutable_torque_n_m());
  }
}

void OpenFoamFluidModel::finish(bool success) {
  flow_.write_now();
  spdlog::info("fluid fields written at t = {} s ({})", flow_.time_s(), success ? "completed" : "stopped");
}

} // namespace fsi::fluid
