// The interfaces of the immersed rigid bodies with interface_flux: body_normal: the flux of
// the body's normal velocity through the faces between penalized and free cells, the held
// pressure of the bodies and of the water they cut off (OpenFoamFlow.H).

#include "OpenFoamFlow.H"

#include "InterfaceFaces.H"
#include "cyclicAMIPolyPatch.H"

#include <algorithm>

namespace fsi::fluid {

void OpenFoamFlow::fix_interface_fluxes(Foam::surfaceScalarField &phiHbyA, Foam::surfaceScalarField &rAtUf) const {
  // InterfaceFlux::body_normal: the faces between penalized and free cells carry the flux
  // of the body's normal velocity and no pressure coupling (a moving wall for the free
  // cells); the penalized cells are holes, their pressure held (pressure_holes).
  using namespace Foam;
  const fvMesh &mesh = *mesh_;
  const auto &rate = penalizationRate_->primitiveField();
  if (mesh.moving()) {
    sweep_interface_fluxes(phiHbyA, rAtUf);
    return;
  }
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
}

void OpenFoamFlow::sweep_interface_fluxes(Foam::surfaceScalarField &phiHbyA, Foam::surfaceScalarField &rAtUf) const {
  // The bodies turn with their cells (or stand in fixed ones): each interface face carries the
  // volume it sweeps, so that no water crosses it relative to the mesh (exactly, where the body
  // velocity at the penalized cell's centre would miss the face's by omega h / 2).
  using namespace Foam;
  const surfaceScalarField &mesh_flux = mesh_->phi();
  for_each_interface_face(*mesh_, penalizationRate_->primitiveField(), [&](label f, label, label, bool) {
    phiHbyA[f] = mesh_flux[f];
    rAtUf[f] *= 1e-9;
  });
  auto &phi_boundary = phiHbyA.boundaryFieldRef();
  auto &rAtUf_boundary = rAtUf.boundaryFieldRef();
  for_each_coupled_interface_face(*penalizationRate_, [&](label patch, label i, label, bool) {
    phi_boundary[patch][i] = mesh_flux.boundaryField()[patch][i];
    rAtUf_boundary[patch][i] *= 1e-9;
  });
}

Foam::labelList OpenFoamFlow::pressure_holes(const Foam::labelList &trapped) const {
  using namespace Foam;
  const auto &rate = penalizationRate_->primitiveField();
  DynamicList<label> cells;
  forAll(rate, c) if (rate[c] > 0.0) cells.append(c);
  cells.append(trapped);
  labelList holes;
  holes.transfer(cells);
  return holes;
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
  // (never negative; said so, or GCC's -Walloc-size-larger-than sees a negative label become a size)
  const label n_regions = std::max(regions.nRegions(), label(0));
  boolList open(n_regions, false);
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
  // regionSplit does not cross an AMI (its faces do not match one to one): the free regions on
  // either side of one are one water, open when any of them is (a rotor turning behind an AMI).
  boolList at_ami(n_regions, false);
  forAll(mesh.boundaryMesh(), patch) {
    if (!isA<cyclicAMIPolyPatch>(mesh.boundaryMesh()[patch]))
      continue;
    for (const label c : mesh.boundaryMesh()[patch].faceCells())
      if (rate[c] <= 0.0)
        at_ami[regions[c]] = true;
  }
  Pstream::listCombineGather(at_ami, orEqOp<bool>());
  Pstream::listCombineScatter(at_ami);
  bool ami_open = false;
  forAll(open, r) ami_open = ami_open || (at_ami[r] && open[r]);
  forAll(open, r) open[r] = open[r] || (ami_open && at_ami[r]);
  if (!std::any_of(open.begin(), open.end(), [](bool o) { return o; })) {
    // No fixed pressure and the reference cell inside a body: the largest free region is the water.
    labelList size(n_regions, 0);
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

} // namespace fsi::fluid
