// The immersed rigid bodies in the OpenFOAM fluid: the penalization fields of Eqs. (9-10),
// the interface velocity of body_normal fluxes, the wall distance and turbulence inside the
// bodies, and the water the staircase swallows (OpenFoamFlow.H).

#include "OpenFoamFlow.H"

#include "InterfaceFaces.H"

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

void OpenFoamFlow::penalization_acceleration(PointArray &a) const {
  a.setZero(mesh_->nCells(), 3);
  if (!penalizationRate_)
    return;
  const auto &rate = penalizationRate_->primitiveField();
  const auto &u = U_->primitiveField();
  const auto &u_rib = rigidVelocity_->primitiveField();
  forAll(rate, c) {
    if (rate[c] == 0.0)
      continue;
    const Foam::vector f = -rate[c] * (u[c] - u_rib[c]);
    a.row(c) << f.x(), f.y(), f.z();
  }
}

bool OpenFoamFlow::uses_wall_distance() const {
  return mesh_->thisDb().foundObject<Foam::wallDist>(Foam::wallDist::typeName);
}

void OpenFoamFlow::set_immersed_walls(const Eigen::VectorXd &wall_distance_m, const Eigen::VectorXd &inside_fraction) {
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

} // namespace fsi::fluid
