#!/usr/bin/python3
"""Writes the ERCOFTAC pump's OpenFOAM folders (issue 31): openfoam-<level>, the penalized
impeller's (the fluid of ./fsi run, case.yaml), and openfoam-ami-<level>, the body-fitted
reference (stock pimpleFoam, the rotor turning behind an AMI at r = 217 mm). The meshes are not
written here: prepare.py makes them with gmsh (python/fsi/ercoftac_mesh.py) before a run, from
the level's sizes in LEVELS. Air at 298 K, k-omega SST with wall functions (Re = 6.5e5), the test's
2000 rpm and flow coefficient 0.0475. Run it after changing a parameter below; the files it
writes are committed.

    PYTHONPATH=python /usr/bin/python3 cases/ercoftac-pump/make_case.py
"""

import math
import os

from fsi import ercoftac_mesh as mesh
from fsi import ercoftac_pump as ecp
from fsi.foam_case import TURBULENT_FV_SCHEMES, write_foam_file

HERE = os.path.dirname(os.path.abspath(__file__))

# level: (h near the blades, vanes and in the whole rotor; h at 8 cm from them, up to the outlet) in m.
# coarse: 3 cells across the 10 mm blade, 2.4 across the 8 mm vane; medium: 4 and 3.2.
LEVELS = {"coarse": (0.0033, 0.0132), "medium": (0.0025, 0.01)}
NU_M2_PER_S = 1.5e-5            # air at 298 K (the test's fluid; the description's Re = 6.5e5)
# The inflow's turbulence: the test case's own 2-D OpenFOAM cases (k = 0.48735 m^2/s^2, I = 5 %;
# epsilon = 138.342 m^2/s^3), as omega = epsilon / (C_mu k).
K_IN = 0.48735
OMEGA_IN = 138.342 / (0.09 * K_IN)
REVOLUTIONS = 10


def inlet_velocity_m_per_s():
    """The radial inflow at r = 0.100 m that carries the test's Q through the 40 mm channel."""
    return ecp.design_flow_rate_m3_per_s() / (2 * math.pi * mesh.R_INLET_M * ecp.SPAN_M)


def time_step_s(h):
    """The blade tip (43.98 m/s) moves h/2 per step at most."""
    return 0.5 * h / ecp.tip_speed_m_per_s()


FIELDS = {
    "U": ("volVectorField", "[0 1 -1 0 0 0 0]", "uniform (0 0 0)", {
        "inlet": "type surfaceNormalFixedValue; refValue uniform %.6g; value uniform (0 0 0);" % -inlet_velocity_m_per_s(),
        "outlet": "type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 0);",
        "blades": "type movingWallVelocity; value uniform (0 0 0);",
        "vanes": "type noSlip;"}),
    "p": ("volScalarField", "[0 2 -2 0 0 0 0]", "uniform 0", {
        "inlet": "type zeroGradient;", "outlet": "type fixedValue; value uniform 0;",
        "blades": "type zeroGradient;", "vanes": "type zeroGradient;"}),
    "k": ("volScalarField", "[0 2 -2 0 0 0 0]", "uniform %.6g" % K_IN, {
        "inlet": "type fixedValue; value uniform %.6g;" % K_IN,
        "outlet": "type inletOutlet; inletValue uniform %.6g; value uniform %.6g;" % (K_IN, K_IN),
        "blades": "type kqRWallFunction; value uniform %.6g;" % K_IN, "vanes": "type kqRWallFunction; value uniform %.6g;" % K_IN}),
    "omega": ("volScalarField", "[0 0 -1 0 0 0 0]", "uniform %.6g" % OMEGA_IN, {
        "inlet": "type fixedValue; value uniform %.6g;" % OMEGA_IN,
        "outlet": "type inletOutlet; inletValue uniform %.6g; value uniform %.6g;" % (OMEGA_IN, OMEGA_IN),
        "blades": "type omegaWallFunction; value uniform %.6g;" % OMEGA_IN,
        "vanes": "type omegaWallFunction; value uniform %.6g;" % OMEGA_IN}),
    "nut": ("volScalarField", "[0 2 -1 0 0 0 0]", "uniform 0", {
        "inlet": "type calculated; value uniform 0;", "outlet": "type calculated; value uniform 0;",
        "blades": "type nutkWallFunction; value uniform 0;", "vanes": "type nutkWallFunction; value uniform 0;"}),
}

# The pump cases' schemes, second order in time (the blade passing is what is sampled).
FV_SCHEMES = TURBULENT_FV_SCHEMES.replace("default Euler", "default backward")

# The pressure to the centrifugal pump's tolerances scaled by the pressure's scale (U2^2: 1934 here,
# 227 m^2/s^2 in the pump, whose pFinal is solved to 1e-5), by CG with a GAMG V-cycle as its
# preconditioner, as the pump's penalized runs are (1e-6 took GAMG 130-175 iterations a step).
FV_SOLUTION = """solvers
{
    p      { solver PCG; preconditioner { preconditioner GAMG; smoother GaussSeidel; } tolerance 1e-4; relTol 0.01; }
    pFinal { $p; tolerance 1e-4; relTol 0; }
    "pcorr.*" { $p; tolerance 1e-4; relTol 0; }
    "(U|k|omega)(|Final)" { solver PBiCGStab; preconditioner DILU; tolerance 1e-8; relTol 0; }
}
PIMPLE
{
    nOuterCorrectors 1;
    nCorrectors      2;
    nNonOrthogonalCorrectors 1;
    momentumPredictor yes;
    correctPhi       yes;
    moveMeshOuterCorrectors no;
    checkMeshCourantNo no;
}
"""


def sample_points(n=720):
    """The measured radius (R/R2 = 1.02) every 0.5 deg, in the slab's mid-plane (z set by the
    level's thickness)."""
    return [(ecp.MEASUREMENT_RADIUS_M * math.cos(2 * math.pi * k / n),
             ecp.MEASUREMENT_RADIUS_M * math.sin(2 * math.pi * k / n)) for k in range(n)]


# The circles of the angular momentum budget (postprocess: the flux through each against the
# impeller's torque): in the blades, at their trailing edge (R2), the measured radius, the
# vaneless gap and the diffuser (its vanes begin at R/R2 = 1.048).
BUDGET_RADII_M = (0.17, 0.18, 0.19, 0.20, 0.205, 0.21, 0.2142, 0.22, 0.23, 0.25)


def budget_points(n=360):
    """BUDGET_RADII_M, every 360/n deg."""
    return [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n))
            for r in BUDGET_RADII_M for k in range(n)]


def casing_points(n=180):
    """The radii of the casing's pressure taps (R/R2 = 0.533-1.019), every 360/n deg."""
    return [(r * ecp.R2_M * math.cos(2 * math.pi * k / n), r * ecp.R2_M * math.sin(2 * math.pi * k / n))
            for r in ecp.casing_radii_over_r2() for k in range(n)]


PROBES = """    %s
    {
        type            probes;
        libs            ("libsampling.so");
        writeControl    timeStep;
        writeInterval   20;
        interpolationScheme cell;
        fixedLocations  false;
        fields          (%s);
        probeLocations
        (
%s
        );
    }
"""


def control_dict(h, end_time_s):
    dt = time_step_s(h)

    def probes(name, field, points):
        return PROBES % (name, field, "\n".join("            (%.9g %.9g %.9g)" % (x, y, 0.5 * h) for x, y in points))
    return """// make_case.py: the tip moves h/2 per step; %d revolutions.
application     pimpleFoam;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         %.9g;
deltaT          %.9g;
writeControl    adjustableRunTime;
writeInterval   %.9g;
purgeWrite      2;
writeFormat     binary;
writePrecision  8;
writeCompression off;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
functions
{
    // The velocity at the measured radius every 20 steps (9 deg of rotation), at 720 probes 0.5 deg
    // apart in the slab's mid-plane, each the value of the cell it lies in at the run's start
    // (postprocess: c_r, c_u against the impeller's angle, pitch- and time-averaged). On the AMI's
    // moving mesh those cells are the rotor's and turn with it (fixedLocations false): probes that
    // follow the absolute points, or sets, search the mesh anew every step, which took 3 times
    // the flow's own cost.
%s    // The pressure at the radii of the casing's taps, every 2 deg, likewise (postprocess: cp
    // across a pitch in the impeller's frame; the measurement's is on the casing over the open
    // impeller, ours in the slab's mid-plane). Probes in a body-fitted blade find no cell.
%s    // The velocity on the circles of the angular momentum budget, every 1 deg, likewise.
%s    forces
    {
        type            forces;
        libs            ("libforces.so");
        patches         (blades);
        rho             rhoInf;
        rhoInf          %.6g;
        CofR            (0 0 0);
        writeControl    timeStep;
        writeInterval   1;
        log             false;
    }
}
""" % (REVOLUTIONS, end_time_s, dt, 2 * math.pi / ecp.omega_rad_per_s(), probes("impellerOutlet", "U", sample_points()),
       probes("casing", "p", casing_points()), probes("budget", "U", budget_points()), ecp.AIR_DENSITY_KG_PER_M3)


FOLDER_PREFIX = {"penalized": "openfoam-fixed-", "turning": "openfoam-", "ami": "openfoam-ami-"}


def write_folder(level, method):
    """The OpenFOAM folder of a level and method (ercoftac_mesh.METHODS): openfoam-<level>
    (turning: the blades penalized in a rotor zone turning with them behind the AMI),
    openfoam-fixed-<level> (penalized: no blades in one fixed mesh) or openfoam-ami-<level> (ami:
    the blades cut out of the turning rotor)."""
    h, _h_far = LEVELS[level]
    folder = os.path.join(HERE, FOLDER_PREFIX[method] + level)
    end = REVOLUTIONS * 2 * math.pi / ecp.omega_rad_per_s()
    for name, (cls, dims, internal, patches) in FIELDS.items():
        body = "dimensions      %s;\ninternalField   %s;\nboundaryField\n{\n" % (dims, internal)
        for patch, value in patches.items():
            if method == "ami" or patch != "blades":
                body += "    %-8s { %s }\n" % (patch, value)
        body += "    frontAndBack { type empty; }\n"
        if method != "penalized":
            body += "    \"ami_.*\" { type cyclicAMI; }\n"
        write_foam_file(folder, os.path.join("0", name), cls, body + "}\n")
    write_foam_file(folder, "constant/transportProperties", "dictionary",
                    "transportModel  Newtonian;\nnu              %.6g;   // air at 298 K (m^2/s)\n" % NU_M2_PER_S)
    write_foam_file(folder, "constant/turbulenceProperties", "dictionary",
                    "simulationType  RAS;\nRAS\n{\n    RASModel        kOmegaSST;\n    turbulence      on;\n"
                    "    printCoeffs     off;\n}\n")
    control = control_dict(h, end)
    if method != "ami":
        # the loads on the impeller are the penalized body's (coupling.h5), not a patch's
        control = control[:control.index("    forces\n")] + "}\n"
    write_foam_file(folder, "system/controlDict", "dictionary", control)
    write_foam_file(folder, "system/fvSchemes", "dictionary", FV_SCHEMES)
    write_foam_file(folder, "system/fvSolution", "dictionary", FV_SOLUTION)
    if method == "penalized":
        return folder
    write_foam_file(folder, "constant/dynamicMeshDict", "dictionary",
                    "// make_case.py: the rotor turns toward -theta of the test's Table 2 (its blades lean back).\n"
                    "dynamicFvMesh   dynamicMotionSolverFvMesh;\nmotionSolverLibs (\"libfvMotionSolvers.so\");\n"
                    "motionSolver    solidBody;\ncellZone        rotor;\nsolidBodyMotionFunction rotatingMotion;\n"
                    "origin          (0 0 0);\naxis            (0 0 -1);\nomega           %.14g;   // rad/s (2000 rpm)\n"
                    % ecp.omega_rad_per_s())
    return folder


if __name__ == "__main__":
    for name in LEVELS:
        for how in FOLDER_PREFIX:
            print(write_folder(name, how))
