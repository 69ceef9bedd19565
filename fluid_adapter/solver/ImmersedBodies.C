// The immersed rigid bodies in the OpenFOAM fluid: the penalization fields of Eqs. (9-10),
// the interface velocity of body_normal fluxes, the wall distance and turbulence inside the
// bodies, and the water the staircase swallows (OpenFoamFlow.H).

#include "OpenFoamFlow.H"

#include "InterfaceFaces.H"

#include "common/UserError.hpp"
#include "fluid_adapter/rigid/SpaldingLaw.hpp"

#include "fvOptions.H"

#include <array>
#include <map>

namespace fsi::fluid {

void OpenFoamFlow::set_penalization(const Eigen::VectorXd &rate_per_s, const PointArray &u_rib) {
  using namespace Foam;
  if (!penalizationRate_) {
    penalizationRate_ = std::make_unique<volScalarField>(
        IOobject("penalizationRate", runTime_->timeName(), *mesh_, IOobject::NO_READ, IOobject::AUTO_WRITE), *mesh_,
        dimensionedScalar(dimless / dimTime, Zero));
    rigidVelocity_ = std::make_unique<volVectorField>(
        IOobject("rigidVelocity", runTime_->timeName(), *mesh_, IOobject::NO_READ, IOobject::NO_WRITE), *mesh_,
        dimensionedVector(dimVelocity, Zero));
  }
  auto &rate = penalizationRate_->primitiveFieldRef();
  auto &velocity = rigidVelocity_->primitiveFieldRef();
  forAll(rate, c) {
    rate[c] = rate_per_s[c];
    velocity[c] = vector(u_rib(c, 0), u_rib(c, 1), u_rib(c, 2));
  }
  penalizationRate_->correctBoundaryConditions(); // the other ranks' values on the processor patches
  rigidVelocity_->correctBoundaryConditions();
}

void OpenFoamFlow::set_interface_velocity(const PointArray &u) {
  using namespace Foam;
  if (!interfaceVelocity_)
    interfaceVelocity_ = std::make_unique<volVectorField>(
        IOobject("interfaceVelocity", runTime_->timeName(), *mesh_, IOobject::NO_READ, IOobject::NO_WRITE), *mesh_,
        dimensionedVector(dimVelocity, Zero));
  auto &field = interfaceVelocity_->primitiveFieldRef();
  forAll(field, c) field[c] = vector(u(c, 0), u(c, 1), u(c, 2));
  interfaceVelocity_->correctBoundaryConditions(); // the other ranks' values on the processor patches
}

void OpenFoamFlow::immersed_transpiration(double &inflow, double &power) const {
  inflow = power = 0.0;
  if (!penalizationRate_)
    return;
  const auto &rate = penalizationRate_->primitiveField();
  const auto &u = U_->primitiveField();
  const auto &u_rib = rigidVelocity_->primitiveField();
  const auto &phi = phi_->primitiveField(); // owner -> neighbour
  for_each_interface_face(*mesh_, rate, [&](Foam::label f, Foam::label body, Foam::label free, bool body_is_owner) {
    const double into_body = body_is_owner ? -phi[f] : phi[f];
    if (into_body <= 0.0)
      return;
    inflow += into_body;
    power += 0.5 * into_body * Foam::magSqr(u[free] - u_rib[body]);
  });
  // Across the ranks, on the body's side only (the sum over ranks counts each face once).
  NeighbourValues<Foam::vector> u_across(*U_);
  for_each_coupled_interface_face(*penalizationRate_, [&](Foam::label patch, Foam::label i, Foam::label body,
                                                          bool cell_is_body) {
    if (!cell_is_body)
      return;
    const double into_body = -phi_->boundaryField()[patch][i]; // the patch's phi points out of this cell
    if (into_body <= 0.0)
      return;
    inflow += into_body;
    power += 0.5 * into_body * Foam::magSqr(u_across.at(patch, i) - u_rib[body]);
  });
}

void OpenFoamFlow::record_penalization_residual(const Foam::fvVectorMatrix &UEqn) {
  // The penalized cells' momentum equation, A u - H = -grad(p) with the penalization in A and
  // H, holds for the velocities it was solved with: the predictor's u* in H's neighbours and the
  // correctors' pressure. Its residual with the step's final u and p is the momentum the body
  // cells exchange with the final flow that -rate (u - u_rib) does not show (the fluid's cells
  // beside the body moved from u* to u in the correctors; the body's own cells did not).
  using namespace Foam;
  const auto &rate = penalizationRate_->primitiveField();
  const volScalarField A(UEqn.A());
  const volVectorField H(UEqn.H());
  const tmp<volVectorField> gradient = pressure_gradient();
  const auto &u = U_->primitiveField();
  penalizationResidual_.setSize(rate.size());
  penalizationResidual_ = Zero;
  forAll(rate, c) if (rate[c] > 0.0) penalizationResidual_[c] = A[c] * u[c] - H[c] + gradient()[c];
}

void OpenFoamFlow::penalization_acceleration(PointArray &a) const {
  a.setZero(mesh_->nCells(), 3);
  if (!penalizationRate_)
    return;
  const auto &rate = penalizationRate_->primitiveField();
  const auto &u = U_->primitiveField();
  const auto &u_rib = rigidVelocity_->primitiveField();
  const bool with_residual = penalizationResidual_.size() == rate.size();
  forAll(rate, c) {
    if (rate[c] == 0.0)
      continue;
    // The force on the fluid: Eq. (9)'s -rate (u - u_rib) from the final u, plus the residual
    // of the cell's momentum equation with the final u and p (record_penalization_residual):
    // together, A0 u - H0 + grad(p) of the equation without penalization, the force that
    // balances the body cell's momentum against the final flow around it.
    Foam::vector f = -rate[c] * (u[c] - u_rib[c]);
    if (with_residual)
      f += penalizationResidual_[c];
    a.row(c) << f.x(), f.y(), f.z();
  }
}

void OpenFoamFlow::interior_pressure_acceleration(PointArray &a, PointArray &couple) const {
  a.setZero(mesh_->nCells(), 3);
  couple.setZero(mesh_->nCells(), 3);
  if (!penalizationRate_)
    return;
  const auto &rate = penalizationRate_->primitiveField();
  const Foam::surfaceScalarField pf(Foam::fvc::interpolate(*p_));
  const auto &owner = mesh_->owner();
  const auto &neighbour = mesh_->neighbour();
  const auto &sf = mesh_->Sf();
  const auto &cf = mesh_->Cf();
  const auto &cc = mesh_->C();
  const auto &volume = mesh_->V();
  const auto row = [](const Foam::vector &v) { return Eigen::RowVector3d(v.x(), v.y(), v.z()); };
  forAll(neighbour, f) {
    const Foam::label o = owner[f], n = neighbour[f];
    if (rate[o] == 0.0 || rate[n] == 0.0)
      continue;
    const Foam::vector ps = pf[f] * sf[f]; // S_f points out of the owner
    a.row(o) += row(ps) / volume[o];
    a.row(n) -= row(ps) / volume[n];
    couple.row(o) += row((cf[f] - cc[o]) ^ ps) / volume[o];
    couple.row(n) -= row((cf[f] - cc[n]) ^ ps) / volume[n];
  }
}

void OpenFoamFlow::interface_pressure_faces(std::vector<InterfaceFace> &faces) const {
  faces.clear();
  if (!penalizationRate_)
    return;
  const auto &p = p_->primitiveField();
  const auto add = [&faces](Foam::label cell, const Foam::vector &centre, double pressure, const Foam::vector &s_out) {
    faces.push_back({cell, Vec3(centre.x(), centre.y(), centre.z()),
                     -pressure * Vec3(s_out.x(), s_out.y(), s_out.z())});
  };
  const auto &sf = mesh_->Sf();
  const auto &cf = mesh_->Cf();
  for_each_interface_face(*mesh_, penalizationRate_->primitiveField(),
                          [&](Foam::label face, Foam::label body, Foam::label free, bool body_is_owner) {
                            add(body, cf[face], p[free], body_is_owner ? sf[face] : Foam::vector(-sf[face]));
                          });
  // Across the ranks: the body's rank counts the face, with the free side's pressure.
  NeighbourValues<Foam::scalar> p_across(*p_);
  for_each_coupled_interface_face(*penalizationRate_, [&](Foam::label patch, Foam::label i, Foam::label cell,
                                                          bool cell_is_body) {
    if (cell_is_body)
      add(cell, cf.boundaryField()[patch][i], p_across.at(patch, i), sf.boundaryField()[patch][i]);
  });
}

bool OpenFoamFlow::uses_wall_distance() const {
  return mesh_->thisDb().foundObject<Foam::wallDist>(Foam::wallDist::typeName);
}

void OpenFoamFlow::set_immersed_walls(const Eigen::VectorXd &wall_distance_m, const Eigen::VectorXd &inside_fraction) {
  immersedWallDistance_ = wall_distance_m;
  insideCells_.clear();
  for (Eigen::Index c = 0; c < inside_fraction.size(); ++c)
    if (inside_fraction[c] >= 0.5)
      insideCells_.push_back(static_cast<Foam::label>(c));
  if (!uses_wall_distance())
    return;
  // The Spalart-Allmaras models hold a reference to this field (wallDist::New(mesh).y()).
  auto &y = const_cast<Foam::volScalarField &>(Foam::wallDist::New(*mesh_).y());
  if (!patchWallDistance_)
    patchWallDistance_ = std::make_unique<Foam::scalarField>(y.primitiveField());
  auto &field = y.primitiveFieldRef();
  forAll(field, c) field[c] = Foam::min((*patchWallDistance_)[c], Foam::scalar(wall_distance_m[c]));
}

void OpenFoamFlow::zero_turbulence_inside_bodies() {
  if (insideCells_.empty())
    return;
  for (const char *name : {"nuTilda", "nut"}) {
    if (!mesh_->thisDb().foundObject<Foam::volScalarField>(name))
      continue;
    auto &field = mesh_->thisDb().lookupObjectRef<Foam::volScalarField>(name);
    auto &values = field.primitiveFieldRef();
    for (const Foam::label c : insideCells_)
      values[c] = 0.0;
    field.correctBoundaryConditions();
  }
}

void OpenFoamFlow::update_immersed_wall_viscosity() {
  using namespace Foam;
  if (!immersedWallViscosity_)
    immersedWallViscosity_ = std::make_unique<surfaceScalarField>(
        IOobject("immersedWallViscosity", runTime_->timeName(), *mesh_, IOobject::NO_READ, IOobject::NO_WRITE), *mesh_,
        dimensionedScalar(dimViscosity, Zero));
  auto &extra = immersedWallViscosity_->primitiveFieldRef();
  extra = 0.0;
  const tmp<volScalarField> tnu_eff = turbulence_->nuEff();
  const auto &nu_eff = tnu_eff().primitiveField();
  const tmp<volScalarField> tnu = laminarTransport_->nu();
  const auto &nu = tnu().primitiveField();
  const auto &rate = penalizationRate_->primitiveField();
  const auto &u = U_->primitiveField();
  const auto &u_rib = rigidVelocity_->primitiveField();
  const auto &weights = mesh_->weights().primitiveField();       // the owner's share of a face value
  const auto &delta = mesh_->nonOrthDeltaCoeffs().primitiveField(); // 1 / the centres' distance along Sf
  const auto &sf = mesh_->Sf().primitiveField();
  const rigid::SpaldingLaw law;
  for_each_interface_face(*mesh_, rate, [&](label f, label body, label free, bool body_is_owner) {
    const double y = free < immersedWallDistance_.size() ? immersedWallDistance_[free] : 0.0;
    if (!(y > 0.0) || !std::isfinite(y))
      return;
    const vector n = sf[f] / mag(sf[f]);
    vector slip = u[free] - u_rib[body];
    slip -= (slip & n) * n;
    const double speed = mag(slip);
    // The face's nu_eff for which nu_eff |slip| delta = tau_w (in the sublayer nu / (y delta)),
    // less what the laplacian of divDevReff already has there (linear between the two cells).
    const double wanted = speed > 0.0 ? law.wall_shear_per_density(speed, y, nu[free]) / (speed * delta[f])
                                      : nu[free] / (y * delta[f]);
    const double w_owner = weights[f];
    const double resolved = w_owner * nu_eff[body_is_owner ? body : free] +
                            (1.0 - w_owner) * nu_eff[body_is_owner ? free : body];
    extra[f] = wanted - resolved;
  });
}

bool OpenFoamFlow::use_immersed_omega_wall_function(bool required) {
  const bool has_omega =
      mesh_->foundObject<Foam::volScalarField>("omega") && mesh_->foundObject<Foam::volScalarField>("k");
  if (!has_omega && !required)
    return false;
  if (!has_omega)
    throw common::UserError("fluid.openfoam.immersed_wall_turbulence: omega_wall_function needs a k-omega turbulence "
                            "model (constant/turbulenceProperties); this case runs " +
                            std::string(turbulence_->type()) + ", which has no omega: use none");
  immersedWallOmega_ = new ImmersedWallOmega(*mesh_, turbulence_->GName());
  // The options own it (a PtrList; its other base, IOdictionary, has an append too).
  static_cast<Foam::PtrList<Foam::fv::option> &>(Foam::fv::options::New(*mesh_)).append(immersedWallOmega_);
  return true;
}

void OpenFoamFlow::update_immersed_wall_omega() {
  using namespace Foam;
  constexpr double kappa = 0.41, beta1 = 0.075;       // omegaWallFunction's, kOmegaSST's beta1
  const double cmu25 = std::pow(0.09, 0.25);
  const auto &rate = penalizationRate_->primitiveField();
  const auto &u = U_->primitiveField();
  const auto &u_rib = rigidVelocity_->primitiveField();
  const auto &sf = mesh_->Sf().primitiveField();
  const auto &k = mesh_->lookupObject<volScalarField>("k").primitiveField();
  const tmp<volScalarField> tnu = laminarTransport_->nu();
  const auto &nu = tnu().primitiveField();
  const rigid::SpaldingLaw law;
  // Per free cell next to a body: the sums of omega and G over its interface faces, and their
  // number (each face weighs 1/n, as omegaWallFunction's corner weights).
  std::map<label, std::array<double, 4>> sums;
  const auto &delta = mesh_->nonOrthDeltaCoeffs().primitiveField(); // 1 / the centres' distance along Sf
  for_each_interface_face(*mesh_, rate, [&](label f, label body, label free, bool) {
    const double measured = free < immersedWallDistance_.size() ? immersedWallDistance_[free] : 0.0;
    if (!(measured > 0.0) || !std::isfinite(measured))
      return;
    // A free centre a staircase leaves next to a thin edge can be any distance from the surface:
    // no closer than a quarter of the centres' spacing (a face-aligned wall is at half), where
    // G ~ 1 / y^2 would make k without bound (omegaWallFunction's y is never below a cell's half).
    const double y = std::max(measured, 0.25 / delta[f]);
    const vector n = sf[f] / mag(sf[f]);
    vector slip = u[free] - u_rib[body];
    slip -= (slip & n) * n;
    const double sqrt_k = std::sqrt(std::max(k[free], 0.0));
    const double omega_vis = 6.0 * nu[free] / (beta1 * y * y), omega_log = sqrt_k / (cmu25 * kappa * y);
    const double tau_w = law.wall_shear_per_density(mag(slip), y, nu[free]);
    auto &sum = sums[free];
    sum[0] += std::hypot(omega_vis, omega_log);
    sum[1] += tau_w * cmu25 * sqrt_k / (kappa * y);
    sum[2] += 1.0;
    sum[3] = y;
  });
  immersedWallCells_.clear();
  labelList cells(static_cast<label>(sums.size()));
  scalarField omega(cells.size()), production(cells.size());
  label i = 0;
  for (const auto &[cell, sum] : sums) {
    cells[i] = cell;
    immersedWallCells_.emplace_back(cell, sum[3]);
    omega[i] = sum[0] / sum[2];
    production[i] = sum[1] / sum[2];
    ++i;
  }
  immersedWallOmega_->hold(std::move(cells), std::move(omega), std::move(production));
}

void OpenFoamFlow::correct_immersed_wall_nut() {
  using namespace Foam;
  if (turbulence_->type() != "kOmegaSST" || immersedWallCells_.empty())
    return;
  constexpr double a1 = 0.31, b1 = 1.0, beta_star = 0.09; // kOmegaSST's
  auto &nut = mesh_->lookupObjectRef<volScalarField>("nut");
  const auto &k = mesh_->lookupObject<volScalarField>("k").primitiveField();
  const auto &omega = mesh_->lookupObject<volScalarField>("omega").primitiveField();
  const tmp<volTensorField> tgrad = fvc::grad(*U_);
  const auto &grad = tgrad().primitiveField();
  const auto &rate = penalizationRate_->primitiveField();
  const auto &u = U_->primitiveField();
  const auto &u_rib = rigidVelocity_->primitiveField();
  const auto &sf = mesh_->Sf().primitiveField();
  const auto &weights = mesh_->weights().primitiveField();
  const auto &volume = mesh_->V();
  const tmp<volScalarField> tnu = laminarTransport_->nu();
  const auto &nu = tnu().primitiveField();
  // The Gauss gradient's interface face values replaced by the body's velocity.
  std::map<label, tensor> correction;
  for_each_interface_face(*mesh_, rate, [&](label f, label body, label free, bool body_is_owner) {
    const label owner = body_is_owner ? body : free, neighbour = body_is_owner ? free : body;
    const vector u_face = weights[f] * u[owner] + (1.0 - weights[f]) * u[neighbour];
    const vector out_of_free = body_is_owner ? vector(-sf[f]) : sf[f];
    auto [at, fresh] = correction.try_emplace(free, Zero);
    at->second += out_of_free * (u_rib[body] - u_face) / volume[free];
  });
  auto &values = nut.primitiveFieldRef();
  for (const auto &[cell, y] : immersedWallCells_) {
    const auto found = correction.find(cell);
    const tensor g = grad[cell] + (found != correction.end() ? found->second : tensor(Zero));
    const double s = std::sqrt(2.0) * mag(symm(g));
    const double w = std::max(omega[cell], VSMALL);
    const double arg2 = std::max(2.0 * std::sqrt(std::max(k[cell], 0.0)) / (beta_star * w * y),
                                 500.0 * nu[cell] / (y * y * w));
    const double f2 = std::tanh(arg2 * arg2);
    values[cell] = a1 * std::max(k[cell], 0.0) / std::max(a1 * w, b1 * f2 * s);
  }
  nut.correctBoundaryConditions();
}

} // namespace fsi::fluid
