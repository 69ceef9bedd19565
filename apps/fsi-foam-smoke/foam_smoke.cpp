// fsi-foam-smoke: proves that an OpenFOAM v1912 application builds against the cached headers,
// links Debian's libraries and runs with their run-time configuration.
//
//   fsi-foam-smoke [-case DIR] [-steps N]
//
// Reads the mesh and the fields U and p of the case's start time, prints one line
//   fsi-foam-smoke: cells=<n> volume=<sum of cell volumes> maxU=<max |U| over cells and patches>
// then, with -steps N, runs N PISO steps (pisoFoam's algorithm, with the incompressible
// turbulence model of constant/turbulenceProperties) without writing anything, and prints
//   fsi-foam-smoke: steps=<N> time=<t> maxU=<...> continuity=<sum local> turbulence=<model type>
// Numbers are printed with 17 significant digits.

#include "fvCFD.H"
#include "pisoControl.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"

#include <cstdio>

namespace {

// Largest |U| over the cells and the boundary faces (the lid of a cavity lives on a patch).
Foam::scalar maxMagU(const Foam::volVectorField& U) {
  Foam::scalar m = Foam::max(Foam::mag(U.primitiveField()));
  forAll(U.boundaryField(), patchi) {
    const Foam::fvPatchVectorField& pf = U.boundaryField()[patchi];
    if (pf.size() > 0) m = Foam::max(m, Foam::max(Foam::mag(pf)));
  }
  return Foam::returnReduce(m, Foam::maxOp<Foam::scalar>());
}

}  // namespace

int main(int argc, char* argv[]) {
  using namespace Foam;
  argList::addNote("Smoke test of the OpenFOAM build: mesh and field statistics, a few PISO steps");
  argList::addOption("steps", "N", "run N PISO steps after the statistics (default 0)");

#include "setRootCase.H"
#include "createTime.H"
#include "createMesh.H"

  const label steps = args.getOrDefault<label>("steps", 0);

  volVectorField U(IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE),
                   mesh);

  const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
  const scalar volume = gSum(mesh.V());
  std::printf("fsi-foam-smoke: cells=%ld volume=%.17g maxU=%.17g\n", static_cast<long>(nCells),
              static_cast<double>(volume), static_cast<double>(maxMagU(U)));
  std::fflush(stdout);
  if (steps <= 0) return 0;

  pisoControl piso(mesh);
  volScalarField p(IOobject("p", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE),
                   mesh);
  surfaceScalarField phi(
      IOobject("phi", runTime.timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::NO_WRITE),
      fvc::flux(U));
  label pRefCell = 0;
  scalar pRefValue = 0.0;
  setRefCell(p, piso.dict(), pRefCell, pRefValue);
  mesh.setFluxRequired(p.name());

  singlePhaseTransportModel laminarTransport(U, phi);
  autoPtr<incompressible::turbulenceModel> turbulence(
      incompressible::turbulenceModel::New(U, phi, laminarTransport));
  turbulence->validate();

  scalar cumulativeContErr = 0;
  scalar sumLocalContErr = 0;
  for (label step = 0; step < steps; ++step) {
    ++runTime;
    fvVectorMatrix UEqn(fvm::ddt(U) + fvm::div(phi, U) + turbulence->divDevReff(U));
    UEqn.relax();
    if (piso.momentumPredictor()) solve(UEqn == -fvc::grad(p));

    while (piso.correct()) {
      volScalarField rAU(1.0 / UEqn.A());
      volVectorField HbyA(constrainHbyA(rAU * UEqn.H(), U, p));
      surfaceScalarField phiHbyA("phiHbyA",
                                 fvc::flux(HbyA) + fvc::interpolate(rAU) * fvc::ddtCorr(U, phi));
      adjustPhi(phiHbyA, U, p);
      constrainPressure(p, U, phiHbyA, rAU);
      while (piso.correctNonOrthogonal()) {
        fvScalarMatrix pEqn(fvm::laplacian(rAU, p) == fvc::div(phiHbyA));
        pEqn.setReference(pRefCell, pRefValue);
        pEqn.solve(mesh.solver(p.select(piso.finalInnerIter())));
        if (piso.finalNonOrthogonalIter()) phi = phiHbyA - pEqn.flux();
      }
      volScalarField contErr(fvc::div(phi));
      sumLocalContErr = runTime.deltaTValue() * mag(contErr)().weightedAverage(mesh.V()).value();
      cumulativeContErr += runTime.deltaTValue() * contErr.weightedAverage(mesh.V()).value();
      U = HbyA - rAU * fvc::grad(p);
      U.correctBoundaryConditions();
    }
    laminarTransport.correct();
    turbulence->correct();
  }

  std::printf("fsi-foam-smoke: steps=%ld time=%.17g maxU=%.17g continuity=%.17g turbulence=%s\n",
              static_cast<long>(steps), static_cast<double>(runTime.value()),
              static_cast<double>(maxMagU(U)), static_cast<double>(sumLocalContErr),
              turbulence->type().c_str());
  return 0;
}
