// The PIMPLE step of the OpenFOAM fluid: pimpleFoam's loop, its momentum predictor (UEqn.H)
// and pressure correctors (pEqn.H), with the FSI source of Eq. (1) and the penalization of
// Eq. (9) (OpenFoamFlow.H).

#include "OpenFoamFlow.H"

#include "InterfaceFaces.H"

#include "CorrectPhi.H"
#include "fvOptions.H"

namespace fsi::fluid {

void OpenFoamFlow::after_mesh_motion() {
  // pimpleFoam's loop after mesh.controlledUpdate() (moveMeshOuterCorrectors no: once a step).
  using namespace Foam;
  if (correctPhi_) {
    // The absolute flux from the mapped face velocity, made divergence-free, then relative.
    *phi_ = mesh_->Sf() & Uf_();
    CorrectPhi(*U_, *phi_, *p_, dimensionedScalar("rAUf", dimTime, 1), geometricZeroField(), *pimple_);
    fvc::makeRelative(*phi_, *U_);
  }
  record_cells();
  if (patchWallDistance_) {
    // wallDist recomputed the distance to the mesh's walls as the points moved (its default
    // updateInterval 1): the immersed walls' part is applied again by set_immersed_walls.
    patchWallDistance_ = std::make_unique<Foam::scalarField>(Foam::wallDist::New(*mesh_).y().primitiveField());
  }
}

void OpenFoamFlow::step() {
  while (pimple_->loop()) {
    solve_momentum_and_pressure();
    if (pimple_->turbCorr()) {
      laminarTransport_->correct();
      if (immersedWallOmega_)
        update_immersed_wall_omega();
      turbulence_->correct();
      zero_turbulence_inside_bodies();
      if (immersedWallOmega_)
        correct_immersed_wall_nut();
    }
  }
}

void OpenFoamFlow::solve_momentum_and_pressure() {
  Foam::tmp<Foam::fvVectorMatrix> tUEqn = momentum_equation();
  const Foam::labelList trapped = body_normal() ? trapped_free_cells() : Foam::labelList();
  while (pimple_->correct())
    correct_pressure(tUEqn.ref(), trapped);
  if (penalizationRate_ && pimple_->finalIter())
    record_penalization_residual(tUEqn());
}

Foam::tmp<Foam::fvVectorMatrix> OpenFoamFlow::momentum_equation() {
  using namespace Foam;
  volVectorField &U = *U_;
  const surfaceScalarField &phi = *phi_;

  // UEqn.H of pimpleFoam, with the FSI source of Eq. (1): +f_fsi / rho_f, and for rigid bodies
  // the penalization of Eq. (9), f_ibm / rho_f = -chi (u - u_rib) / tau, implicit in u (its
  // diagonal enters A(), so a tiny tau does not limit the time step).
  // The case's momentum sources (constant/fvOptions: a pump's front seal as a porous ring), as pimpleFoam.
  fv::options &options = fv::options::New(*mesh_);
  tmp<fvVectorMatrix> tUEqn(fvm::ddt(U) + fvm::div(phi, U) + turbulence_->divDevReff(U) ==
                            *fsiAcceleration_ + options(U));
  if (immersedWallFunction_ && penalizationRate_) {
    update_immersed_wall_viscosity();
    tUEqn.ref() -= fvm::laplacian(*immersedWallViscosity_, U);
  }
  if (penalizationRate_)
    tUEqn.ref() += fvm::Sp(*penalizationRate_, U) - (*penalizationRate_) * (*rigidVelocity_);
  fvVectorMatrix &UEqn = tUEqn.ref();
  UEqn.relax();
  options.constrain(UEqn);
  if (pimple_->momentumPredictor()) {
    solve(UEqn == -pressure_gradient());
    options.correct(U);
  }
  return tUEqn;
}


void OpenFoamFlow::correct_pressure(Foam::fvVectorMatrix &UEqn, const Foam::labelList &trapped) {
  // pEqn.H of pimpleFoam (no MRF): one corrector. phiHbyA is absolute (the bodies' interface
  // fluxes too); phi leaves relative to a moving mesh.
  using namespace Foam;
  fvMesh &mesh = *mesh_;
  volScalarField &p = *p_;
  volVectorField &U = *U_;
  surfaceScalarField &phi = *phi_;
  pimpleControl &pimple = *pimple_;
  volScalarField rAU(1.0 / UEqn.A());
  volVectorField HbyA(constrainHbyA(rAU * UEqn.H(), U, p));
  surfaceScalarField phiHbyA("phiHbyA", fvc::flux(HbyA) + fvc::interpolate(rAU) * fvc::ddtCorr(U, phi, Uf_));
  if (p.needReference()) {
    fvc::makeRelative(phiHbyA, U);
    adjustPhi(phiHbyA, U, p);
    fvc::makeAbsolute(phiHbyA, U);
  }
  tmp<volScalarField> rAtU(rAU);
  if (pimple.consistent()) {
    rAtU = 1.0 / max(1.0 / rAU - UEqn.H1(), 0.1 / rAU);
    phiHbyA += fvc::interpolate(rAtU() - rAU) * fvc::snGrad(p) * mesh.magSf();
    HbyA -= (rAU - rAtU()) * pressure_gradient();
  }
  constrainPressure(p, U, phiHbyA, rAtU());
  surfaceScalarField rAtUf("rAtUf", fvc::interpolate(rAtU()));
  labelList holes;
  scalarField hole_values;
  if (body_normal()) {
    fix_interface_fluxes(phiHbyA, rAtUf);
    holes = pressure_holes(trapped);
    hole_values = scalarField(p.primitiveField(), holes);
  }
  while (pimple.correctNonOrthogonal()) {
    fvScalarMatrix pEqn(fvm::laplacian(rAtUf, p) == fvc::div(phiHbyA));
    if (holes.size())
      pEqn.setValues(holes, hole_values);
    pEqn.setReference(pRefCell_, pRefValue_);
    pEqn.solve(mesh.solver(p.select(pimple.finalInnerIter())));
    if (pimple.finalNonOrthogonalIter())
      phi = phiHbyA - pEqn.flux();
  }
  if (holes.size())
    extrapolate_pressure_into_bodies();
  p.relax();
  U = HbyA - rAtU * pressure_gradient();
  U.correctBoundaryConditions();
  fv::options::New(mesh).correct(U);
  // A moving mesh: the face velocity follows, and the flux becomes relative to the mesh motion
  // (the convective flux of the next momentum equation). Nothing on a static mesh.
  fvc::correctUf(Uf_, U, phi);
  fvc::makeRelative(phi, U);
}

Foam::tmp<Foam::volVectorField> OpenFoamFlow::pressure_gradient() const {
  using namespace Foam;
  const volScalarField &p = *p_;
  if (!body_normal())
    return fvc::grad(p);
  surfaceScalarField pf(fvc::interpolate(p));
  for_each_interface_face(*mesh_, penalizationRate_->primitiveField(),
                          [&](label f, label, label free, bool) { pf[f] = p[free]; });
  auto &pf_boundary = pf.boundaryFieldRef();
  NeighbourValues<scalar> p_across(p);
  for_each_coupled_interface_face(*penalizationRate_, [&](label patch, label i, label cell, bool cell_is_body) {
    pf_boundary[patch][i] = cell_is_body ? p_across.at(patch, i) : p[cell];
  });
  tmp<volVectorField> gradient(new volVectorField("grad(p)", fvc::surfaceIntegrate(mesh_->Sf() * pf)));
  gradient.ref().correctBoundaryConditions();
  return gradient;
}

} // namespace fsi::fluid
