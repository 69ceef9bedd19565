// The OpenFOAM fluid's set-up, the fields the adapter reads and writes, and the MPI reductions
// (the class and how its files divide it: OpenFoamFlow.H).

#include "OpenFoamFlow.H"

#include "common/ExitCodes.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace fsi::fluid {

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
  // pimpleFoam's createDynamicFvMesh.H: a static mesh unless constant/dynamicMeshDict says otherwise.
  mesh_.reset(dynamicFvMesh::New(IOobject(fvMesh::defaultRegion, runTime_->timeName(), *runTime_, IOobject::MUST_READ))
                  .ptr());
  dynamicFvMesh &mesh = *mesh_;
  pimple_ = std::make_unique<pimpleControl>(mesh);
  correctPhi_ = pimple_->dict().lookupOrDefault<bool>("correctPhi", mesh.dynamic());
  p_ = std::make_unique<volScalarField>(
      IOobject("p", runTime_->timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE), mesh);
  U_ = std::make_unique<volVectorField>(
      IOobject("U", runTime_->timeName(), mesh, IOobject::MUST_READ, IOobject::AUTO_WRITE), mesh);
  phi_ = std::make_unique<surfaceScalarField>(
      IOobject("phi", runTime_->timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE), fvc::flux(*U_));
  fsiAcceleration_ = std::make_unique<volVectorField>(
      IOobject("fsiAcceleration", runTime_->timeName(), mesh, IOobject::NO_READ, IOobject::AUTO_WRITE), mesh,
      dimensionedVector(dimAcceleration, Zero));
  if (mesh.dynamic()) // pimpleFoam's createUfIfPresent.H
    Uf_.reset(new surfaceVectorField(
        IOobject("Uf", runTime_->timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
        fvc::interpolate(*U_)));
  read_start_penalization();
  setRefCell(*p_, pimple_->dict(), pRefCell_, pRefValue_);
  mesh.setFluxRequired(p_->name());
  create_turbulence();
  record_cells_and_limits(settings);
  // The case's own function objects (controlDict `functions`: surfaceFieldValue, probes, ...)
  // run as in OpenFOAM's solvers; the time loop here is ++runTime, which does not call them.
  runTime_->functionObjects().start();
}

void OpenFoamFlow::read_start_penalization() {
  using namespace Foam;
  const fvMesh &mesh = *mesh_;
  // A restart's set has the penalization of its last step (OpenFoamFluidModel: which cells the
  // bodies covered then). Read aside: set_penalization registers the field of the run.
  IOobject io("penalizationRate", runTime_->timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false);
  if (io.typeHeaderOk<volScalarField>(true)) {
    const volScalarField rate(io, mesh);
    startRate_.resize(rate.primitiveField().size());
    forAll(rate.primitiveField(), c) startRate_[c] = rate.primitiveField()[c];
  }
}

void OpenFoamFlow::create_turbulence() {
  using namespace Foam;
  fvMesh &mesh = *mesh_;
  // Fields a run of this solver wrote (a checkpoint, a precursor's last fields; they hold
  // fsiAcceleration, which a case's own initial fields do not): their nut is the state the run
  // stopped in. The model's validate() evaluates nut again from the other fields, and a wall
  // function that iterates (Spalding's, to 1 %) then lands elsewhere than it had, starting from
  // the value it converged to: the resumed run would differ from the uninterrupted one in the
  // last digits. Read aside, and put back after validate() when validate() gave the same cell
  // values (the same state continued; not fields mapped from another mesh).
  std::unique_ptr<volScalarField> nutWritten;
  if (IOobject("fsiAcceleration", runTime_->timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false)
          .typeHeaderOk<volVectorField>(true)) {
    IOobject io("nut", runTime_->timeName(), mesh, IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false);
    if (io.typeHeaderOk<volScalarField>(true))
      nutWritten = std::make_unique<volScalarField>(io, mesh);
  }
  laminarTransport_ = std::make_unique<singlePhaseTransportModel>(*U_, *phi_);
  turbulence_ = incompressible::turbulenceModel::New(*U_, *phi_, *laminarTransport_);
  turbulence_->validate();
  if (nutWritten && mesh.thisDb().foundObject<volScalarField>("nut")) {
    auto &nut = mesh.thisDb().lookupObjectRef<volScalarField>("nut");
    bool same = nut.primitiveField().size() == nutWritten->primitiveField().size();
    forAll(nut.primitiveField(), c) same = same && nut.primitiveField()[c] == nutWritten->primitiveField()[c];
    if (returnReduce(same, andOp<bool>()))
      nut == *nutWritten;
  }
}

void OpenFoamFlow::record_cells() {
  const Foam::fvMesh &mesh = *mesh_;
  centres_.resize(mesh.nCells(), 3);
  volumes_.resize(mesh.nCells());
  forAll(mesh.C(), c) {
    const Foam::vector &x = mesh.C()[c];
    centres_.row(c) << x.x(), x.y(), x.z();
    volumes_[c] = mesh.V()[c];
  }
}

void OpenFoamFlow::record_cells_and_limits(const FoamFlowSettings &settings) {
  using namespace Foam;
  const fvMesh &mesh = *mesh_;
  const label n = mesh.nCells();
  record_cells();
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
  if (mesh_->dynamic())
    text << ", moving mesh " << mesh_->type() << (correctPhi_ ? " (correctPhi)" : "");
  text << ", turbulence " << turbulence_->type() << ", case " << settings.case_directory.string();
  description_ = text.str();
}

void OpenFoamFlow::broadcast_from_master(std::vector<double> &data) const {
  if (!Foam::Pstream::parRun())
    return;
  Foam::List<Foam::scalar> list(static_cast<Foam::label>(data.size()));
  forAll(list, i) list[i] = data[i];
  Foam::Pstream::scatter(list);
  data.assign(list.begin(), list.end());
}

namespace {
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
} // namespace

void OpenFoamFlow::sum_over_ranks(double *data, std::size_t n) const {
  combine_over_ranks(data, n, Foam::plusEqOp<Foam::scalar>());
}

void OpenFoamFlow::min_over_ranks(double *data, std::size_t n) const {
  combine_over_ranks(data, n, Foam::minEqOp<Foam::scalar>());
}

namespace {
void copy_rows(const Foam::vectorField &field, PointArray &rows) {
  rows.resize(field.size(), 3);
  forAll(field, c) rows.row(c) << field[c].x(), field[c].y(), field[c].z();
}
} // namespace

void OpenFoamFlow::cell_velocities(PointArray &u) const { copy_rows(U_->primitiveField(), u); }

void OpenFoamFlow::cell_accelerations(PointArray &a) const {
  copy_rows(Foam::volVectorField(Foam::fvc::ddt(*U_)).primitiveField(), a);
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

namespace {
int collective_exit_code = 0;
extern "C" void exit_with_collective_code() { std::_Exit(collective_exit_code); }
} // namespace

int FoamFlow::end_process(int exit_code) {
  if (Foam::UPstream::parRun()) {
    if (exit_code == common::exit_code_interrupted) {
      // Every rank stops here together, after the checkpoint of one step (a collective
      // decision): MPI ends as on success, not by MPI_Abort, which would have mpirun kill the
      // ranks still finishing; then the process exits with the code. UPstream::exit(0) ends
      // with exit(0), whose first handler (the last registered) is this one.
      collective_exit_code = exit_code;
      std::fflush(nullptr);
      std::atexit(exit_with_collective_code);
      Foam::UPstream::exit(0);
    }
    Foam::UPstream::exit(exit_code); // MPI_Finalize (or abort with the code), then exit
  }
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
