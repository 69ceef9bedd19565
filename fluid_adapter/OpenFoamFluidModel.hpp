#pragma once
// The OpenFOAM fluid as a fluid model of the protocol (fsi-openfoam-fluid), OpenFOAM-free:
// each step it builds the kernel stencil of Eqs. (6-7) at X^n (cells found through a spatial
// index built once per mesh), interpolates U_ib^n, then spreads F_fsi^n (Eq. 8) at the same
// points, divides by rho_f (OpenFOAM's incompressible momentum equation is per unit density)
// and hands the acceleration to FoamFlow for one PIMPLE step. Rigid bodies (closed STL
// surfaces with a prescribed motion) are penalized (Eqs. 9-10): chi and u_rib at t^{n+1} from
// each body's swept candidate cells, the penalization implicit in the momentum matrix; the
// force and torque of the fluid on each body go back to the coupler.

#include "FoamFlow.hpp"
#include "OpenFoamConfig.hpp"
#include "fluid_adapter/ibm/CellIndex.hpp"
#include "fluid_adapter/ibm/KernelStencil.hpp"
#include "fluid_adapter/ibm/NearestCells.hpp"
#include "fluid_adapter/rigid/BodyIndicator.hpp"
#include "fluid_adapter/rigid/RigidBody.hpp"
#include "proto/FluidModel.hpp"

#include <memory>

namespace fsi::fluid {

class OpenFoamFluidModel final : public proto::FluidModel {
public:
  OpenFoamFluidModel(const OpenFoamConfig &config, FoamFlow &flow,
                     std::vector<std::unique_ptr<rigid::RigidBody>> rigid_bodies = {});

  std::string describe() const override;
  void start(const proto::v1::Welcome &welcome) override;
  void interpolate(const proto::v1::InterpolateRequest &request, proto::PointsView x_m,
                   proto::MutablePointsView u_m_per_s) override;
  void advance(const proto::v1::FluidAdvance &request, proto::PointsView force_density_n_per_m2,
               proto::v1::AdvanceReply &reply) override;
  void finish(bool success) override;

private:
  void penalize_rigid_bodies(double time_s);
  void report_rigid_body_loads(double time_s, proto::v1::AdvanceReply &reply);

  OpenFoamConfig config_;
  FoamFlow &flow_;
  ibm::EulerianCells cells_;
  ibm::CellIndex index_;
  Eigen::VectorXd point_measures_;
  PointArray positions_, cell_velocity_, force_density_, acceleration_;
  std::unique_ptr<ibm::NearestCells> nearest_;
  std::unique_ptr<ibm::KernelStencil> stencil_;
  std::vector<std::unique_ptr<rigid::RigidBody>> bodies_;
  std::vector<std::unique_ptr<rigid::BodyIndicator>> indicators_;
  Eigen::VectorXd penalization_rate_;
  PointArray rigid_velocity_, penalization_acceleration_, penalization_force_;
};

} // namespace fsi::fluid
