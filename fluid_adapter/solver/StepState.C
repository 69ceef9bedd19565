// The OpenFOAM fluid's step with its last good state (put back when the step diverges or
// OpenFOAM fails), the divergence check, and the step start saved and restored for implicit
// coupling (OpenFoamFlow.H).

#include "OpenFoamFlow.H"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fsi::fluid {
namespace {

/// Fields written with every digit of a double while it lives. Binary fields hold their values
/// exactly, but OpenFOAM writes a uniform patch value as text (`value uniform 2.1043826e-07;`,
/// writePrecision digits: 8 in these cases): Spalart-Allmaras' nut on the inlet, calculated and
/// uniform, came back rounded, and a turbulent restart differed from the uninterrupted run by
/// round-off from its first step (issue 33). 17 significant digits read back to the same double.
struct FullPrecision {
  unsigned saved = Foam::IOstream::defaultPrecision(17);
  ~FullPrecision() { Foam::IOstream::defaultPrecision(saved); }
  FullPrecision() = default;
  FullPrecision(const FullPrecision &) = delete;
  FullPrecision &operator=(const FullPrecision &) = delete;
};

} // namespace

void OpenFoamFlow::start_step(double dt_s) {
  if (good_)
    throw std::logic_error("OpenFoamFlow::start_step: the step started at t = " + std::to_string(good_->time) +
                           " s was not advanced");
  // The last good state, to put back on disk if this step diverges (three field copies: a few
  // ms on 300k cells, against about a second for the step), and a moving mesh's points.
  good_.reset(new GoodState{Foam::volVectorField("U_good", *U_), Foam::volScalarField("p_good", *p_),
                            Foam::surfaceScalarField("phi_good", *phi_), runTime_->value(), runTime_->timeIndex(),
                            nullptr});
  if (mesh_->dynamic())
    good_->points = std::make_unique<Foam::pointField>(mesh_->points());
  runTime_->setDeltaT(dt_s, false); // exactly the coupled dt: never stretched to hit a write time
  ++(*runTime_);
  if (!mesh_->dynamic())
    return;
  try {
    mesh_->controlledUpdate();
    if (mesh_->changing())
      after_mesh_motion();
  } catch (const Foam::error &e) {
    const std::string when = std::to_string(runTime_->value());
    restore_good_state();
    throw std::runtime_error("OpenFOAM could not move the mesh to t = " + when + " s: " + std::string(e.message()));
  }
}

void OpenFoamFlow::restore_good_state() {
  *U_ = good_->U;
  *p_ = good_->p;
  *phi_ = good_->phi;
  runTime_->setTime(good_->time, good_->index);
  if (good_->points) {
    mesh_->movePoints(*good_->points);
    record_cells();
  }
  good_.reset();
}

void OpenFoamFlow::advance(double dt_s) {
  if (!good_)
    start_step(dt_s);
  const std::string kept =
      "; the last good state (t = " + std::to_string(good_->time) + " s) is written when the run stops";
  try {
    step();
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
  good_.reset();
  {
    const FullPrecision exact;
    runTime_->write();
  }
  runTime_->functionObjects().execute();
}

void OpenFoamFlow::write_now() {
  const FullPrecision exact;
  runTime_->writeNow();
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
  if (mesh_->dynamic())
    throw std::runtime_error("implicit coupling (repeated steps) is not available on a moving mesh (" +
                             std::string(mesh_->type()) +
                             ", constant/dynamicMeshDict): the mesh would have to move back with the fields; use an "
                             "explicit coupling law");
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

PisoSettings OpenFoamFlow::piso_settings() const {
  return {pimple_->momentumPredictor(), static_cast<int>(pimple_->nCorrPISO()),
          static_cast<int>(pimple_->nCorrPIMPLE())};
}

ViscousNumber OpenFoamFlow::max_viscous_number(double dt_s) const {
  // Per cell nu_eff dt sum_f |S_f| delta_f / (2 V): on a uniform hex, nu_eff dt sum_i 1/dx_i^2.
  // Internal and coupled (processor, cyclic) faces only: an empty direction does not count.
  using namespace Foam;
  const fvMesh &mesh = *mesh_;
  const tmp<volScalarField> nu_eff = turbulence_->nuEff();
  const surfaceScalarField &delta = mesh.deltaCoeffs();
  scalarField sum(mesh.nCells(), 0.0);
  forAll(mesh.neighbour(), f) {
    const scalar a = mesh.magSf()[f] * delta[f];
    sum[mesh.owner()[f]] += a;
    sum[mesh.neighbour()[f]] += a;
  }
  forAll(mesh.boundary(), patch) {
    if (!mesh.boundary()[patch].coupled())
      continue;
    const labelUList &cells = mesh.boundary()[patch].faceCells();
    forAll(cells, i) sum[cells[i]] += mesh.magSf().boundaryField()[patch][i] * delta.boundaryField()[patch][i];
  }
  ViscousNumber local;
  forAll(sum, c) {
    const double d = dt_s * nu_eff().primitiveField()[c] * sum[c] / (2.0 * mesh.V()[c]);
    if (d > local.value) {
      local.value = d;
      local.where_m = Vec3(mesh.C()[c].x(), mesh.C()[c].y(), mesh.C()[c].z());
    }
  }
  ViscousNumber global = local;
  global.value = returnReduce(local.value, maxOp<scalar>());
  double where[4] = {0.0, 0.0, 0.0, 0.0}; // the rank(s) holding the maximum give its cell
  if (local.value == global.value)
    where[0] = 1.0, where[1] = local.where_m.x(), where[2] = local.where_m.y(), where[3] = local.where_m.z();
  sum_over_ranks(where, 4);
  if (where[0] > 0.0)
    global.where_m = Vec3(where[1], where[2], where[3]) / where[0];
  return global;
}

} // namespace fsi::fluid
