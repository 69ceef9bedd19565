// The one translation unit of the fluid adapter that includes OpenFOAM: pimpleFoam's PIMPLE
// step (OpenFOAM v1912, applications/solvers/incompressible/pimpleFoam: UEqn.H, pEqn.H) on a
// static mesh, with one extra momentum source, the FSI acceleration f_fsi / rho_f of Eq. (1).
// Not kept from pimpleFoam: mesh motion, MRF and fvOptions (the immersed boundaries replace
// them here).

#include "fluid_adapter/FoamFlow.hpp"

#include "fvCFD.H"
#include "pimpleControl.H"
#include "regionSplit.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "wallDist.H"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace fsi::fluid {

namespace {

/// Calls visit(face, body_cell, free_cell, body_is_owner) for every internal face between a
/// penalized cell (rate > 0) and a free one (this rank's faces).
template <class Visit>
void for_each_interface_face(const Foam::fvMesh &mesh, const Foam::scalarField &rate, Visit visit) {
  const auto &owner = mesh.owner();
  const auto &neighbour = mesh.neighbour();
  forAll(neighbour, f) {
    const Foam::label o = owner[f], n = neighbour[f];
    const bool in_o = rate[o] > 0.0, in_n = rate[n] > 0.0;
    if (in_o != in_n)
      visit(f, in_o ? o : n, in_o ? n : o, in_o);
  }
}

/// The same across the coupled patches (MPI ranks' processor patches): calls
/// visit(patch, patch_face, cell, cell_is_body) for every face of a coupled patch between a
/// penalized cell and a free one, with this rank's cell. Each such face is visited once on
/// either rank; its patch Sf points out of this rank's cell. `rate`'s coupled patch values must
/// be current (correctBoundaryConditions).
template <class Visit>
void for_each_coupled_interface_face(const Foam::volScalarField &rate, Visit visit) {
  const auto &boundary = rate.boundaryField();
  forAll(boundary, patch) {
    const auto &patch_field = boundary[patch];
    if (!patch_field.coupled())
      continue;
    const Foam::scalarField other(patch_field.patchNeighbourField());
    const Foam::labelUList &cells = patch_field.patch().faceCells();
    forAll(cells, i) {
      const bool in_here = rate[cells[i]] > 0.0, in_there = other[i] > 0.0;
      if (in_here != in_there)
        visit(patch, i, cells[i], in_here);
    }
  }
}

/// The other rank's cell values on the coupled patches of a field, fetched once per patch.
template <class Type> class NeighbourValues {
public:
  explicit NeighbourValues(const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh> &field)
      : field_(field), values_(field.boundaryField().size()) {}
  const Type &at(Foam::label patch, Foam::label i) {
    if (!values_[patch].valid())
      values_[patch] = field_.boundaryField()[patch].patchNeighbourField();
    return values_[patch]()[i];
  }

private:
  const Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh> &field_;
  std::vector<Foam::tmp<Foam::Field<Type>>> values_;
};

/// OpenFOAM reports fatal errors by throwing Foam::error when asked to (instead of aborting).
struct ThrowOnFatalError {
  ThrowOnFatalError() {
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
  }
};

class OpenFoamFlow final : public FoamFlow {
public:
  explicit OpenFoamFlow(const FoamFlowSettings &settings);

  std::string describe() const override { return description_; }
  const PointArray &cell_centres_m() const override { return centres_; }
  const Eigen::VectorXd &cell_volumes_m3() const override { return volumes_; }
  void cell_velocities(PointArray &u) const override;
  void cell_velocity_gradients(Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> &grad) const override;
  void set_fsi_acceleration(const PointArray &a) override;
  void set_penalization(const Eigen::VectorXd &rate_per_s, const PointArray &u_rib) override;
  void penalization_acceleration(PointArray &a) const override;
  void immersed_transpiration(double &inflow_m3_per_s, double &power_per_density) const override;
  long cut_off_cells() const override { return nCutOff_; }
  void set_interface_velocity(const PointArray &u) override;
  bool uses_wall_distance() const override;
  void set_immersed_walls(const Eigen::VectorXd &wall_distance_m, const Eigen::VectorXd &inside_fraction) override;
  void advance(double dt_s) override;
  void save_step_start() override;
  void restore_step_start() override;
  double time_s() const override { return runTime_->value(); }
  void write_now() override { runTime_->writeNow(); }
  std::string time_name() const override { return runTime_->timeName(); }
  std::filesystem::path case_directory() const override { return case_directory_; }
  int rank() const override { return Foam::Pstream::myProcNo(); }
  int n_ranks() const override { return Foam::Pstream::nProcs(); }
  void broadcast_from_master(std::vector<double> &data) const override;
  void sum_over_ranks(double *data, std::size_t n) const override;
  void min_over_ranks(double *data, std::size_t n) const override;

private:
  /// The fields of one type saved at the start of a step (implicit coupling).
  template <class FieldType> struct SavedFields {
    std::vector<std::pair<FieldType *, std::unique_ptr<FieldType>>> fields;
    void save(Foam::fvMesh &mesh);
    void restore();
  };
  SavedFields<Foam::volScalarField> savedScalars_;
  SavedFields<Foam::volVectorField> savedVectors_;
  SavedFields<Foam::volSymmTensorField> savedSymmTensors_;
  SavedFields<Foam::surfaceScalarField> savedFluxes_;
  Foam::scalar stepStartTime_ = 0.0;
  Foam::label stepStartIndex_ = -1;
  void step(double dt_s);
  std::string find_divergence(double dt_s) const;
  double speed_limit_ = 1.0;
  void solve_momentum_and_pressure();

  ThrowOnFatalError throw_on_fatal_error_;
  std::vector<std::string> argument_storage_;
  std::vector<char *> argument_pointers_;
  int argc_ = 0;
  char **argv_ = nullptr;
  // argList's destructor ends the process (UPstream::exit(0)): destroyed while an exception
  // unwinds (also one thrown by this constructor, when the members are destroyed) or before main
  // returns, it would exit with status 0 before the error is logged or the exit code returned.
  // So it is never destroyed (a raw pointer, deliberately leaked); FoamFlow::end_process ends MPI.
  Foam::argList *args_ = nullptr;
  std::filesystem::path case_directory_;
  std::unique_ptr<Foam::Time> runTime_;
  std::unique_ptr<Foam::fvMesh> mesh_;
  std::unique_ptr<Foam::pimpleControl> pimple_;
  std::unique_ptr<Foam::volScalarField> p_;
  std::unique_ptr<Foam::volVectorField> U_;
  std::unique_ptr<Foam::surfaceScalarField> phi_;
  std::unique_ptr<Foam::volVectorField> fsiAcceleration_;
  std::unique_ptr<Foam::volScalarField> penalizationRate_; ///< chi / tau (1/s); null: no rigid bodies
  std::unique_ptr<Foam::volVectorField> rigidVelocity_;    ///< u_rib (m/s)
  std::unique_ptr<Foam::volVectorField> interfaceVelocity_; ///< null: interpolated interface fluxes
  /// body_normal: the pressure of the penalized cells next to free ones, the mean of those.
  void extrapolate_pressure_into_bodies();
  /// grad(p) of the momentum equation and the velocity correction. With body_normal interfaces
  /// the faces between penalized and free cells are walls of the free water (a fixed flux, no
  /// pressure coupling), so their pressure is the free cell's, as at the mesh's walls (Gauss
  /// linear elsewhere). The extrapolated pressure of a body cell is no value of the free side:
  /// a one-cell disc between two waters (the pump's hub disc) would feed the pressure
  /// difference across it into the velocity of the cells on either side, which their fixed
  /// fluxes never feel back (the coarse two-blade pump's gap cells ran away to 100 m/s across
  /// the disc). Otherwise fvc::grad(p).
  Foam::tmp<Foam::volVectorField> pressure_gradient() const;
  /// body_normal: the free cells cut off from every open boundary (and from the pressure
  /// reference) by penalized cells and walls: a pocket of water a blade tip traps against the
  /// casing. Every face of such a pocket has a fixed flux (the body's normal flux, or a wall's
  /// zero), whose sum is not zero cell by cell, and its pressure couples to nothing but the
  /// 1e-9 of the interface faces: left in the pressure equation it takes the imbalance over
  /// 1e-9 (the medium rag-in-pump precursor ran away in one such cell at t = 0.03275 s). Its
  /// pressure is held, as the bodies' is. Empty without pockets.
  Foam::labelList trapped_free_cells() const;
  mutable long nCutOff_ = 0; ///< free cells cut off in the last step (every rank)
  std::unique_ptr<Foam::scalarField> patchWallDistance_; ///< y from the mesh's walls alone
  std::vector<Foam::label> insideCells_;                 ///< cells inside immersed bodies
  void zero_turbulence_inside_bodies();
  std::unique_ptr<Foam::singlePhaseTransportModel> laminarTransport_;
  Foam::autoPtr<Foam::incompressible::turbulenceModel> turbulence_;
  Foam::label pRefCell_ = 0;
  Foam::scalar pRefValue_ = 0.0;
  PointArray centres_;
  Eigen::VectorXd volumes_;
  std::string description_;
};

OpenFoamFlow::OpenFoamFlow(const FoamFlowSettings &settings) {
  using namespace Foam;
  case_directory_ = settings.case_directory;
  argument_storage_ = {"fsi-openfoam-fluid", "-case", settings.case_directory.string()};
  if (settings.parallel)
    argument_storage_.push_back("-parallel");
  for (auto &a : argument_storage_)
    argument_pointers_.push_back(a.data());
  argument_pointers_.push_back(nullptr);
  argc_ = static_cast<int>(argument_storage_.size());
  argv_ = argument_pointers_.data();
  argList::noBanner();
  if (!settings.parallel)
    argList::noParallel();
  args_ = new argList(argc_, argv_);
  runTime_ = std::make_unique<Time>(Time::controlDictName, *args_);
  runTime_->setDeltaT(settings.time_step_s, false);
  runTime_->setEndTime(settings.end_time_s);
  mesh_ =
      std::make_unique<fvMesh>(IOobject(fvMesh::defaultRegion, runTime_->timeName(), *runTime_, IOobject::MUST_READ));
  fvMesh &mesh = *mesh_;
  pimple_ = std::make_unique<pimpleControl>(mesh);
  p_ = std::make_unique<volScalarField>(
      IOobject("p", runTime_->timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE), mesh);
  U_ = std::make_unique<volVectorField>(
      IOobject("U", runTime_->timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE), mesh);
  phi_ = std::make_unique<surfaceScalarField>(
      IOobject("phi", runTime_->timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE), fvc::flux(*U_));
  fsiAcceleration_ = std::make_unique<volVectorField>(
      IOobject("fsiAcceleration", runTime_->timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE), mesh,
      dimensionedVector(dimAcceleration, Zero));
  setRefCell(*p_, pimple_->dict(), pRefCell_, pRefValue_);
  mesh.setFluxRequired(p_->name());
  laminarTransport_ = std::make_unique<singlePhaseTransportModel>(*U_, *phi_);
  turbulence_ = incompressible::turbulenceModel::New(*U_, *phi_, *laminarTransport_);
  turbulence_->validate();

  const label n = mesh.nCells();
  centres_.resize(n, 3);
  volumes_.resize(n);
  forAll(mesh.C(), c) {
    const vector &x = mesh.C()[c];
    centres_.row(c) << x.x(), x.y(), x.z();
    volumes_[c] = mesh.V()[c];
  }
  Foam::scalar initial_speed = 0.0;
  forAll(U_->primitiveField(), c) initial_speed = Foam::max(initial_speed, Foam::mag(U_->primitiveField()[c]));
  forAll(U_->boundaryField(), patch) {
    if (U_->boundaryField()[patch].size() > 0)
      initial_speed = Foam::max(initial_speed, Foam::max(Foam::mag(U_->boundaryField()[patch])));
  }
  speed_limit_ = 100.0 * Foam::max(Foam::returnReduce(initial_speed, Foam::maxOp<Foam::scalar>()), 1.0);
  std::ostringstream text;
  text << "OpenFOAM v1912 PIMPLE, " << returnReduce(n, sumOp<label>()) << " cells";
  if (Pstream::parRun())
    text << " on " << Pstream::nProcs() << " MPI ranks";
  text << ", turbulence " << turbulence_->type() << ", case " << settings.case_directory.string();
  description_ = text.str();
  // The case's own function objects (controlDict `functions`: surfaceFieldValue, probes, ...)
  // run as in OpenFOAM's solvers; the time loop here is ++runTime, which does not call them.
  runTime_->functionObjects().start();
}

void OpenFoamFlow::broadcast_from_master(std::vector<double> &data) const {
  if (!Foam::Pstream::parRun())
    return;
  Foam::List<Foam::scalar> list(static_cast<Foam::label>(data.size()));
  forAll(list, i) list[i] = data[i];
  Foam::Pstream::scatter(list);
  data.assign(list.begin(), list.end());
}

/// Element-wise reduction over the ranks with OpenFOAM's combine operation `op`, on every rank.
template <class CombineOp> void combine_over_ranks(double *data, std::size_t n, const CombineOp &op) {
  if (!Foam::Pstream::parRun())
    return;
  Foam::List<Foam::scalar> list(static_cast<Foam::label>(n));
  forAll(list, i) list[i] = data[i];
  Foam::Pstream::listCombineGather(list, op);
  Foam::Pstream::listCombineScatter(list);
  forAll(list, i) data[i] = list[i];
}

void OpenFoamFlow::sum_over_ranks(double *data, std::size_t n) const {
  combine_over_ranks(data, n, Foam::plusEqOp<Foam::scalar>());
}

void OpenFoamFlow::min_over_ranks(double *data, std::size_t n) const {
  combine_over_ranks(data, n, Foam::minEqOp<Foam::scalar>());
}

void OpenFoamFlow::cell_velocities(PointArray &u) const {
  const auto &field = U_->primitiveField();
  u.resize(field.size(), 3);
  forAll(field, c) u.row(c) << field[c].x(), field[c].y(), field[c].z();
}

void OpenFoamFlow::cell_velocity_gradients(Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor> &grad) const {
  // fvc::grad(U) is T_ij = d u_j / d x_i; the library wants J_ij = d u_i / d x_j = T_ji.
  const Foam::volTensorField T(Foam::fvc::grad(*U_));
  grad.resize(T.primitiveField().size(), 9);
  forAll(T.primitiveField(), c) {
    const Foam::tensor &t = T.primitiveField()[c];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        grad(c, 3 * i + j) = t[3 * j + i];
  }
}

void OpenFoamFlow::set_fsi_acceleration(const PointArray &a) {
  auto &field = fsiAcceleration_->primitiveFieldRef();
  forAll(field, c) field[c] = Foam::vector(a(c, 0), a(c, 1), a(c, 2));
  fsiAcceleration_->correctBoundaryConditions();
}

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

void OpenFoamFlow::extrapolate_pressure_into_bodies() {
  const auto &rate = penalizationRate_->primitiveField();
  auto &p = p_->primitiveFieldRef();
  Foam::scalarField sum(p.size(), 0.0), count(p.size(), 0.0);
  for_each_interface_face(*mesh_, rate, [&](Foam::label, Foam::label body, Foam::label free, bool) {
    sum[body] += p[free];
    count[body] += 1.0;
  });
  NeighbourValues<Foam::scalar> p_across(*p_);
  for_each_coupled_interface_face(*penalizationRate_, [&](Foam::label patch, Foam::label i, Foam::label cell,
                                                          bool cell_is_body) {
    if (!cell_is_body)
      return;
    sum[cell] += p_across.at(patch, i);
    count[cell] += 1.0;
  });
  forAll(p, c) if (count[c] > 0.0) p[c] = sum[c] / count[c];
  p_->correctBoundaryConditions();
}

Foam::labelList OpenFoamFlow::trapped_free_cells() const {
  using namespace Foam;
  const fvMesh &mesh = *mesh_;
  const auto &rate = penalizationRate_->primitiveField();
  // The free water split into connected regions, a face between a penalized cell and a free one
  // a wall (regionSplit numbers the regions across the MPI ranks).
  boolList blocked(mesh.nFaces(), false);
  for_each_interface_face(mesh, rate, [&](label f, label, label, bool) { blocked[f] = true; });
  for_each_coupled_interface_face(*penalizationRate_, [&](label patch, label i, label, bool) {
    blocked[mesh.boundaryMesh()[patch].start() + i] = true;
  });
  const regionSplit regions(mesh, blocked);
  // Open: a region with a face on a boundary whose pressure is fixed, or with the reference cell.
  boolList open(regions.nRegions(), false);
  const auto &p_boundary = p_->boundaryField();
  forAll(p_boundary, patch) {
    if (!p_boundary[patch].fixesValue())
      continue;
    for (const label c : p_boundary[patch].patch().faceCells())
      if (rate[c] <= 0.0)
        open[regions[c]] = true;
  }
  if (p_->needReference() && pRefCell_ >= 0 && pRefCell_ < mesh.nCells() && rate[pRefCell_] <= 0.0)
    open[regions[pRefCell_]] = true;
  Pstream::listCombineGather(open, orEqOp<bool>());
  Pstream::listCombineScatter(open);
  if (!std::any_of(open.begin(), open.end(), [](bool o) { return o; })) {
    // No fixed pressure and the reference cell inside a body: the largest free region is the water.
    labelList size(regions.nRegions(), 0);
    forAll(rate, c) if (rate[c] <= 0.0) ++size[regions[c]];
    Pstream::listCombineGather(size, plusEqOp<label>());
    Pstream::listCombineScatter(size);
    open[findMax(size)] = true;
  }
  DynamicList<label> trapped;
  forAll(rate, c) if (rate[c] <= 0.0 && !open[regions[c]]) trapped.append(c);
  nCutOff_ = returnReduce(trapped.size(), sumOp<label>());
  return labelList(std::move(trapped));
}

Foam::tmp<Foam::volVectorField> OpenFoamFlow::pressure_gradient() const {
  using namespace Foam;
  const volScalarField &p = *p_;
  if (!(interfaceVelocity_ && penalizationRate_))
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

void OpenFoamFlow::advance(double dt_s) {
  // The last good state, to put back on disk if this step diverges (three field copies: a few
  // ms on 300k cells, against about a second for the step).
  const Foam::volVectorField U_good("U_good", *U_);
  const Foam::volScalarField p_good("p_good", *p_);
  const Foam::surfaceScalarField phi_good("phi_good", *phi_);
  const Foam::scalar t_good = runTime_->value();
  const Foam::label index_good = runTime_->timeIndex();
  const auto restore_good_state = [&] {
    *U_ = U_good;
    *p_ = p_good;
    *phi_ = phi_good;
    runTime_->setTime(t_good, index_good);
  };
  const std::string kept = "; the last good state (t = " + std::to_string(t_good) + " s) is written when the run stops";
  try {
    step(dt_s);
  } catch (const Foam::error &e) {
    // OpenFOAM's own failures mid-step (a NaN read back as a token, a solver that breaks down)
    // leave fields half-updated: the last good ones go back, as for a divergence.
    const std::string when = std::to_string(runTime_->value());
    restore_good_state();
    throw std::runtime_error("OpenFOAM failed at t = " + when + " s: " + std::string(e.message()) + kept);
  }
  if (const std::string problem = find_divergence(dt_s); !problem.empty()) {
    restore_good_state();
    throw std::runtime_error(problem + kept);
  }
  runTime_->write();
  runTime_->functionObjects().execute();
}

template <class FieldType> void OpenFoamFlow::SavedFields<FieldType>::save(Foam::fvMesh &mesh) {
  // Every registered field of this type but the old-time ones ("U_0"): a copy not registered
  // (it must not be found here the next time). Saved and restored in name order on every rank.
  fields.clear();
  const auto table = mesh.thisDb().lookupClass<FieldType>();
  for (const Foam::word &name : table.sortedToc()) {
    if (name.endsWith("_0"))
      continue;
    FieldType &field = const_cast<FieldType &>(*table[name]);
    Foam::IOobject io(name + "_stepStart", mesh.time().timeName(), mesh, Foam::IOobject::NO_READ,
                      Foam::IOobject::NO_WRITE, false);
    auto copy = std::make_unique<FieldType>(io, field);
    fields.emplace_back(&field, std::move(copy));
  }
}

template <class FieldType> void OpenFoamFlow::SavedFields<FieldType>::restore() {
  for (auto &[field, copy] : fields) {
    // Values only, at the step's end time index: no old-time shift is triggered (see FoamFlow).
    field->primitiveFieldRef() = copy->primitiveField();
    field->boundaryFieldRef() == copy->boundaryField();
  }
}

void OpenFoamFlow::save_step_start() {
  savedScalars_.save(*mesh_);
  savedVectors_.save(*mesh_);
  savedSymmTensors_.save(*mesh_);
  savedFluxes_.save(*mesh_);
  stepStartTime_ = runTime_->value();
  stepStartIndex_ = runTime_->timeIndex();
}

void OpenFoamFlow::restore_step_start() {
  if (stepStartIndex_ < 0)
    throw std::logic_error("OpenFoamFlow: restore_step_start() before save_step_start()");
  // Values first, while the time index is still the step's end (the fields' own): then the
  // time goes back, and the repeated ++time comes to the same index without shifting old times.
  savedScalars_.restore();
  savedVectors_.restore();
  savedSymmTensors_.restore();
  savedFluxes_.restore();
  runTime_->setTime(stepStartTime_, stepStartIndex_);
}

std::string OpenFoamFlow::find_divergence(double dt_s) const {
  // Never leave NaNs running: a non-finite or runaway velocity stops the run, naming the cell,
  // where it is, and the Courant number there (the likely cause).
  const auto &u = U_->primitiveField();
  Foam::label worst = -1;
  Foam::scalar worst_speed = 0.0;
  forAll(u, c) {
    const Foam::scalar speed = Foam::mag(u[c]);
    if (!std::isfinite(speed)) {
      worst = c;
      worst_speed = speed;
      break;
    }
    if (speed > worst_speed) {
      worst = c;
      worst_speed = speed;
    }
  }
  if (worst < 0 || (std::isfinite(worst_speed) && worst_speed <= speed_limit_))
    return "";
  const Foam::vector &x = mesh_->C()[worst];
  const double h = std::cbrt(mesh_->V()[worst]);
  std::ostringstream text;
  text << "the fluid diverged at t = " << runTime_->value() << " s: cell " << worst << " at (" << x.x() << ", " << x.y()
       << ", " << x.z() << ") m has |U| = " << worst_speed << " m/s (limit " << speed_limit_
       << " m/s, 100 times the largest speed at the start); its Courant number |U| dt / h would be "
       << (std::isfinite(worst_speed) ? worst_speed * dt_s / h : worst_speed)
       << ". Likely cause: the time step is too large for the flow (keep the Courant number below 1) or for a "
          "stiff coupling (penalty constant K, penalization time)";
  return text.str();
}

void OpenFoamFlow::step(double dt_s) {
  runTime_->setDeltaT(dt_s, false); // exactly the coupled dt: never stretched to hit a write time
  ++(*runTime_);
  while (pimple_->loop()) {
    solve_momentum_and_pressure();
    if (pimple_->turbCorr()) {
      laminarTransport_->correct();
      turbulence_->correct();
      zero_turbulence_inside_bodies();
    }
  }
}

void OpenFoamFlow::solve_momentum_and_pressure() {
  using namespace Foam;
  fvMesh &mesh = *mesh_;
  volScalarField &p = *p_;
  volVectorField &U = *U_;
  surfaceScalarField &phi = *phi_;
  pimpleControl &pimple = *pimple_;

  // UEqn.H of pimpleFoam, with the FSI source of Eq. (1): +f_fsi / rho_f, and for rigid bodies
  // the penalization of Eq. (9), f_ibm / rho_f = -chi (u - u_rib) / tau, implicit in u (its
  // diagonal enters A(), so a tiny tau does not limit the time step).
  tmp<fvVectorMatrix> tUEqn(fvm::ddt(U) + fvm::div(phi, U) + turbulence_->divDevReff(U) == *fsiAcceleration_);
  if (penalizationRate_)
    tUEqn.ref() += fvm::Sp(*penalizationRate_, U) - (*penalizationRate_) * (*rigidVelocity_);
  fvVectorMatrix &UEqn = tUEqn.ref();
  UEqn.relax();
  if (pimple.momentumPredictor())
    solve(UEqn == -pressure_gradient());

  // pEqn.H of pimpleFoam (static mesh, no MRF).
  const labelList trapped = interfaceVelocity_ && penalizationRate_ ? trapped_free_cells() : labelList();
  while (pimple.correct()) {
    volScalarField rAU(1.0 / UEqn.A());
    volVectorField HbyA(constrainHbyA(rAU * UEqn.H(), U, p));
    surfaceScalarField phiHbyA("phiHbyA", fvc::flux(HbyA) + fvc::interpolate(rAU) * fvc::ddtCorr(U, phi));
    if (p.needReference())
      adjustPhi(phiHbyA, U, p);
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
    if (interfaceVelocity_ && penalizationRate_) {
      // InterfaceFlux::body_normal: the faces between penalized and free cells carry the flux
      // of the body's normal velocity and no pressure coupling (a moving wall for the free
      // cells); the penalized cells are holes, their pressure held.
      const auto &rate = penalizationRate_->primitiveField();
      const auto &Sf = mesh.Sf();
      const auto &u_normal = interfaceVelocity_->primitiveField();
      const auto outward = [&](label f, label body, bool body_is_owner) { // the body's normal flux out of it
        const double flux = u_normal[body] & Sf[f];
        return body_is_owner ? flux : -flux;
      };
      // A face of a processor patch: the body's normal flux out of this rank's cell, whichever
      // side the body is on (the patch's Sf points out of this rank's cell).
      NeighbourValues<vector> u_normal_across(*interfaceVelocity_);
      const auto coupled_out_of_cell = [&](label patch, label i, label cell, bool cell_is_body) {
        const vector &sf = Sf.boundaryField()[patch][i];
        return cell_is_body ? (u_normal[cell] & sf) : (u_normal_across.at(patch, i) & sf);
      };
      // Out of the bodies: the flux of the normal velocity, less its net over all the faces
      // spread by area (the staircase's sum of a rigid motion's normal flux is not zero, and
      // the free water must keep its volume). Over all ranks, each processor face counted on
      // its body's side.
      double sums[2] = {0.0, 0.0}; // net flux out of the bodies (m^3/s), interface area (m^2)
      for_each_interface_face(mesh, rate, [&](label f, label body, label, bool body_is_owner) {
        sums[0] += outward(f, body, body_is_owner);
        sums[1] += mag(Sf[f]);
      });
      for_each_coupled_interface_face(*penalizationRate_, [&](label patch, label i, label cell, bool cell_is_body) {
        if (!cell_is_body)
          return;
        sums[0] += coupled_out_of_cell(patch, i, cell, true);
        sums[1] += mag(Sf.boundaryField()[patch][i]);
      });
      sum_over_ranks(sums, 2);
      const double correction = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
      for_each_interface_face(mesh, rate, [&](label f, label body, label, bool body_is_owner) {
        const double out = outward(f, body, body_is_owner) - correction * mag(Sf[f]);
        phiHbyA[f] = body_is_owner ? out : -out;
        rAtUf[f] *= 1e-9;
      });
      auto &phi_boundary = phiHbyA.boundaryFieldRef();
      auto &rAtUf_boundary = rAtUf.boundaryFieldRef();
      for_each_coupled_interface_face(*penalizationRate_, [&](label patch, label i, label cell, bool cell_is_body) {
        // Out of this cell: the body's normal flux less the correction out of the body, so that
        // both ranks hold the same face flux.
        const double body_side = cell_is_body ? 1.0 : -1.0;
        phi_boundary[patch][i] = coupled_out_of_cell(patch, i, cell, cell_is_body) -
                                 body_side * correction * mag(Sf.boundaryField()[patch][i]);
        rAtUf_boundary[patch][i] *= 1e-9;
      });
      DynamicList<label> cells;
      forAll(rate, c) if (rate[c] > 0.0) cells.append(c);
      cells.append(trapped);
      holes.transfer(cells);
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
  }
}

} // namespace

int FoamFlow::end_process(int exit_code) {
  if (Foam::UPstream::parRun())
    Foam::UPstream::exit(exit_code); // MPI_Finalize (or abort with the code), then exit
  return exit_code;
}

std::unique_ptr<FoamFlow> FoamFlow::create(const FoamFlowSettings &settings) {
  // Floating-point traps would abort the process on the first NaN, before the divergence
  // check can name the cell and keep the last good state.
  setenv("FOAM_SIGFPE", "false", 1);
  try {
    return std::make_unique<OpenFoamFlow>(settings);
  } catch (const Foam::error &e) {
    throw std::runtime_error("OpenFOAM could not set up the case " + settings.case_directory.string() + ": " +
                             std::string(e.message()));
  }
}

} // namespace fsi::fluid
