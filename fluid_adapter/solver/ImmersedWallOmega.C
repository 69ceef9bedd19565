#include "ImmersedWallOmega.H"

#include "fvMatrices.H"
#include "volFields.H"

namespace fsi::fluid {

ImmersedWallOmega::ImmersedWallOmega(const Foam::fvMesh &mesh, const Foam::word &production_name)
    : Foam::fv::option("immersedWallOmega", "immersedWallOmega", Foam::dictionary(), mesh),
      productionName_(production_name) {
  fieldNames_ = Foam::wordList(1, "omega");
  applied_.setSize(1, false);
}

void ImmersedWallOmega::hold(Foam::labelList cells, Foam::scalarField omega, Foam::scalarField production) {
  cells_ = std::move(cells);
  omega_ = std::move(omega);
  production_ = std::move(production);
}

void ImmersedWallOmega::constrain(Foam::fvMatrix<Foam::scalar> &eqn, const Foam::label) {
  using Internal = Foam::volScalarField::Internal;
  if (mesh_.foundObject<Internal>(productionName_)) {
    auto &g = mesh_.lookupObjectRef<Internal>(productionName_);
    forAll(cells_, i) g[cells_[i]] = production_[i];
  }
  eqn.setValues(cells_, omega_);
}

} // namespace fsi::fluid
