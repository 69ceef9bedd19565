#pragma once
// The case's `fluid.openfoam` section: the OpenFOAM fluid (Navier-Stokes, PIMPLE) with the
// diffuse immersed-boundary forcing of Eqs. (6-8). Header-only data, no OpenFOAM header.

#include "OperatingPoint.hpp"
#include "common/ConfigReader.hpp"

#include <filesystem>

namespace fsi::fluid {

enum class InterpolationChoice { kernel, closest_cell_linear };
enum class InterfaceFlux { interpolated, body_normal };
enum class BodyIndicatorChoice { sharp, inside_smoothed };
enum class ViscousLimitChoice { refuse, warn };
enum class ImmersedWallModelChoice { none, spalding };
enum class ImmersedWallTurbulenceChoice { automatic, none, omega_wall_function };

struct OpenFoamConfig {
  std::string case_directory = "openfoam";
  double density_kg_per_m3 = 1000.0;
  InterpolationChoice interpolation = InterpolationChoice::kernel;
  bool normalise_kernel = true;
  double penalization_time_s = 1.0e-6;
  int mpi_ranks = 1;
  double precursor_time_s = 0.0;
  double precursor_time_step_s = 0.0;
  std::string initial_fields_from;
  InterfaceFlux interface_flux = InterfaceFlux::interpolated;
  BodyIndicatorChoice body_indicator = BodyIndicatorChoice::sharp;
  double body_indicator_depth_cells = 1.0;
  std::optional<OperatingPoint> operating_point;
  ViscousLimitChoice viscous_limit = ViscousLimitChoice::refuse;
  ImmersedWallModelChoice immersed_wall_model = ImmersedWallModelChoice::none;
  ImmersedWallTurbulenceChoice immersed_wall_turbulence = ImmersedWallTurbulenceChoice::automatic;

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
    v.number("penalization_time_s", penalization_time_s, common::Range::positive("s"),
             "Rigid bodies (every closed STL mesh of collisions.surfaces, with its motion) are penalized in the fluid "
             "(Eqs. 9-10): f_ibm / rho_f = -chi (u - u_rib) / tau, implicit. The paper's K_ibm = 1e-6 read as this "
             "time (read as a permeability in m^2 with water's viscosity it would give a 1/s sponge, not a solid).");
    v.integer("mpi_ranks", mpi_ranks, common::Range::at_least(1, "1"),
              "MPI ranks of the fluid: > 1 decomposes the OpenFOAM case (decomposePar, hierarchical along x) and "
              "runs the fluid with mpirun; only rank 0 talks to the coupler.");
    v.number("precursor_time_s", precursor_time_s, common::Range::non_negative("s"),
             "Precursor run (section 3.2): the flow with the rigid bodies alone (no structure, no coupler) for this "
             "time before the coupled run starts; its last fields (U, p, phi, turbulence) are the coupled run's "
             "initial fields. Kept in <output>/precursor and reused while the fluid, the collision surfaces and the "
             "OpenFOAM case are unchanged. 0: none.");
    v.text("initial_fields_from", initial_fields_from,
           "A warm start: an OpenFOAM case folder (e.g. an earlier run's <output>/openfoam, of this case at another "
           "resolution), relative to the case folder or absolute, whose latest fields are mapped onto this mesh "
           "(OpenFOAM's mapFields -consistent: the same patches) as the initial fields. The run still starts at t = "
           "0, so a rotating body should be where it was: end the source run after whole revolutions. With "
           "precursor_time_s the mapped fields start the precursor (a finer mesh spins up from a coarser run's "
           "developed flow, e.g. <output>/precursor/openfoam, instead of from rest), and a change of the source's "
           "fields makes the precursor run again. Empty: the case's own 0/ fields.");
    v.choice("interface_flux", interface_flux,
             {{"interpolated", InterfaceFlux::interpolated}, {"body_normal", InterfaceFlux::body_normal}},
             "Rigid bodies: the flux through the faces between penalized and free cells. interpolated (the "
             "paper's): the solver's, from the velocities on both sides, with the penalized cells in the pressure "
             "equation; a staircase body moving along its own surface (a turning impeller) then swallows and "
             "returns water through its faces (penalization.csv's transpiration). body_normal (not the "
             "paper's; any number of MPI ranks): the penalized cells are holes of the pressure equation and those faces carry the "
             "flux of the body velocity's component along the surface normal, so that only the true surface's "
             "normal motion moves water through the staircase; water the bodies cut off from the open boundaries "
             "keeps its pressure held (docs/model.md).");
    v.choice("body_indicator", body_indicator,
             {{"sharp", BodyIndicatorChoice::sharp}, {"inside_smoothed", BodyIndicatorChoice::inside_smoothed}},
             "Rigid bodies: chi of Eq. (10) at the cell centres. sharp (the paper's): 1 strictly inside the STL "
             "surface, else 0. inside_smoothed: a ramp from 0 at the surface to 1 at body_indicator_depth_cells cell "
             "sizes inside it, 0 everywhere outside (the body never grows); with penalization_time_s much below the "
             "time step it is nearly sharp in effect (a rotating body: 9 % fewer pressure iterations; docs/model.md).");
    v.number("body_indicator_depth_cells", body_indicator_depth_cells, common::Range::positive("cells"),
             "inside_smoothed only: depth of chi's ramp inside the surface, in cell sizes (cube root of the cell "
             "volume).");
    v.number("precursor_time_step_s", precursor_time_step_s, common::Range::non_negative("s"),
             "Time step of the precursor run (no structure, so only the flow's Courant number limits it). 0: "
             "run.time_step_s.");
    v.choice("viscous_limit", viscous_limit,
             {{"refuse", ViscousLimitChoice::refuse}, {"warn", ViscousLimitChoice::warn}},
             "A time step over the measured limit of OpenFOAM's PISO loop for the case's largest viscous number "
             "nu_eff dt sum 1/dx^2 (with a momentum predictor: 0.55 with nCorrectors 1, 30.5 with 2; "
             "docs/verification.md): refuse (the run stops before its first step, naming the largest stable time "
             "step and the settings without the limit) or warn (it runs; the divergence checks stop it when its "
             "velocity or a body's load runs away).");
    v.choice("immersed_wall_model", immersed_wall_model,
             {{"none", ImmersedWallModelChoice::none}, {"spalding", ImmersedWallModelChoice::spalding}},
             "Rigid bodies: the shear of their walls. none (the paper's): the resolved velocity difference between "
             "the first free cell and the body's cell, i.e. a wall at the body's last cell centre, and in a "
             "turbulent flow far too little shear wherever that free cell is not in the viscous sublayer (nut = 0 "
             "inside the bodies). spalding: the mesh walls' wall function at the immersed ones: every face between a "
             "body cell and a free one gets the viscosity that makes its viscous flux the wall shear of Spalding's "
             "law (as nutUSpaldingWallFunction) for the free cell's velocity relative to the body, tangential to the "
             "face, at its distance from the true surface; laminar or turbulent (docs/model.md). Faces between MPI "
             "ranks keep the resolved shear.");
    v.choice("immersed_wall_turbulence", immersed_wall_turbulence,
             {{"auto", ImmersedWallTurbulenceChoice::automatic}, {"none", ImmersedWallTurbulenceChoice::none},
              {"omega_wall_function", ImmersedWallTurbulenceChoice::omega_wall_function}},
             "Rigid bodies in a k-omega model (kOmegaSST): none: omega and k see no wall at an immersed surface "
             "(nut = 0 inside the bodies only; nu_t next to them grows to 11 times a mesh wall's). "
             "omega_wall_function: in the free cells next to a body, omega and its production G held as OpenFOAM's "
             "omegaWallFunction holds them next to a mesh wall (blended viscous and log-layer omega at the cell's "
             "distance from the true surface; G from Spalding's wall shear) and kOmegaSST's nu_t computed with "
             "the body's velocity on the interface faces (docs/model.md); refused with a model without omega. "
             "auto: omega_wall_function with a k-omega model, none with any other (Spalart-Allmaras has its "
             "immersed walls through the wall distance, section 2.6). Faces between MPI ranks are left out.");
    v.optional_section("operating_point", operating_point,
                       "The inlet's volume flow rate, for an OpenFOAM case whose 0/U takes it from "
                       "constant/operatingPoint (the pump cases): required there, refused elsewhere.");
    if constexpr (std::is_same_v<V, common::ConfigReader>)
      check_operating_point(v);
  }

private:
  /// The template's inlet takes its flow rate from constant/operatingPoint exactly when the
  /// case gives operating_point (a template not there yet, e.g. generated later: not checked).
  void check_operating_point(const common::ConfigReader &v) const {
    const auto foam_case = v.file().parent_path() / case_directory;
    if (!std::filesystem::is_directory(foam_case / "0"))
      return;
    const bool required = OperatingPoint::required_by(foam_case);
    if (required && !operating_point)
      v.fail_value("operating_point", "is absent, but " + (foam_case / "0" / "U").string() +
                                          " takes its inlet flow rate from constant/operatingPoint: give "
                                          "operating_point: {flow_rate_m3_per_s: Q} (m^3/s, > 0).");
    if (!required && operating_point)
      v.fail_value("operating_point", "is given, but " + (foam_case / "0" / "U").string() +
                                          " does not take its inlet flow rate from constant/operatingPoint "
                                          "(flowRateInletVelocity with volumetricFlowRate $flowRate): it would "
                                          "have no effect.");
  }
};

} // namespace fsi::fluid
