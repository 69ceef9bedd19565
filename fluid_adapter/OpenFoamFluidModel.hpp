#pragma once
// The OpenFOAM fluid as a fluid model of the protocol (fsi-openfoam-fluid), OpenFOAM-free:
// each step it builds the kernel stencil of Eqs. (6-7) at X^n (cells found through a spatial
// index built once per mesh), interpolates U_ib^n, then spreads F_fsi^n (Eq. 8) at the same
// points, divides by rho_f (OpenFOAM's incompressible momentum equation is per unit density)
// and hands the acceleration to FoamFlow for one PIMPLE step.

#include "FoamFlow.hpp"
#include "OpenFoamConfig.hpp"
#include "fluid_adapter/ibm/CellIndex.hpp"
#include "fluid_adapter/ibm/KernelStencil.hpp"
#include "fluid_adapter/ibm/NearestCells.hpp"
#include "proto/FluidModel.hpp"

#include <memory>

namespace fsi::fluid {

class OpenFoamFluidModel final : public proto::FluidModel {
public:
  OpenFoamFluidModel(const OpenFoamConfig &config, FoamFlow &flow);

  std::string describe() const override;
  void start(const proto::v1::Welcome &welcome) override;
  void interpolate(const proto::v1::InterpolateRequest &request, proto::PointsView x_m,
                   proto::MutablePointsView u_m_per_s) override;
  void advance(const proto::v1::FluidAdvance &request, proto::PointsView force_density_n_per_m2,
               proto::v1::AdvanceReply &reply) override;
  void finish(bool success) override;

private:
  OpenFoamConfig config_;
  FoamFlow &flow_;
  ibm::EulerianCells cells_;
  ibm::CellIndex index_;
  Eigen::VectorXd point_measures_;
  PointArray positions_, cell_velocity_, force_density_, acceleration_;
  std::unique_ptr<ibm::NearestCells> nearest_;
  std::unique_ptr<ibm::KernelStencil> stencil_;
};

} // namespace fsi::fluid
