#pragma once
// The case's `fluid.openfoam` section: the OpenFOAM fluid (Navier-Stokes, PIMPLE) with the
// diffuse immersed-boundary forcing of Eqs. (6-8). Header-only data, no OpenFOAM header.

#include "common/ConfigReader.hpp"

#include <filesystem>

namespace fsi::fluid {

enum class InterpolationChoice { kernel, closest_cell_linear };

struct OpenFoamConfig {
  std::string case_directory = "openfoam";
  double density_kg_per_m3 = 1000.0;
  InterpolationChoice interpolation = InterpolationChoice::kernel;
  bool normalise_kernel = true;

  template <class V> void visit(V &v) {
    v.text("case_directory", case_directory,
           "OpenFOAM case (system/, constant/, 0/), relative to the case folder; copied to "
           "<output>/openfoam and run there (blockMesh is run when it has no mesh).");
    v.number("density_kg_per_m3", density_kg_per_m3, common::Range::positive("kg/m^3"),
             "Fluid density rho_f: OpenFOAM's incompressible equations are per unit density, so the spread "
             "FSI force density (N/m^3) is divided by it.");
    v.choice("interpolation", interpolation,
             {{"kernel", InterpolationChoice::kernel}, {"closest_cell_linear", InterpolationChoice::closest_cell_linear}},
             "U_ib from the fluid: the 4-point kernel of Eq. (7) (adjoint to the spreading), or the paper's linear "
             "interpolation from the closest cell centre.");
    v.flag("normalise_kernel", normalise_kernel,
           "Divide kernel weights by their sum: keeps force conservation and second-order interpolation near walls "
           "and on stretched cells (the raw kernel sums to 1 only on uniform cubes).");
  }
};

} // namespace fsi::fluid
