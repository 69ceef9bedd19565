#include "OpenFoamFluidModel.hpp"

#include "fluid_adapter/ibm/ClosestCellLinear.hpp"

#include <spdlog/spdlog.h>

namespace fsi::fluid {

OpenFoamFluidModel::OpenFoamFluidModel(const OpenFoamConfig &config, FoamFlow &flow)
    : config_(config), flow_(flow), cells_(flow.cell_centres_m(), flow.cell_volumes_m3()), index_(cells_) {}

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
                                 proto::v1::AdvanceReply &) {
  // Eq. (8) at the points of this step's interpolation (X^n): N/m^2 x m^2 -> N/m^3 per cell,
  // then per unit density for OpenFOAM's kinematic momentum equation (Eq. 1: +f_fsi).
  force_density_ = force_density_n_per_m2;
  acceleration_ = stencil_->spread(force_density_, point_measures_) / config_.density_kg_per_m3;
  flow_.set_fsi_acceleration(acceleration_);
  flow_.advance(request.dt_s());
}

void OpenFoamFluidModel::finish(bool success) {
  flow_.write_now();
  spdlog::info("fluid fields written at t = {} s ({})", flow_.time_s(), success ? "completed" : "stopped");
}

} // namespace fsi::fluid
