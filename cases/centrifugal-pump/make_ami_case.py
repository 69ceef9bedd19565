#!/usr/bin/python3
"""Writes the OpenFOAM case folders of the body-fitted sliding-mesh (AMI) reference of the
centrifugal pump: the same casing, flow rate, turbulence, schemes, solver settings, time step and
function objects as make_case.py's penalized cases, but the impeller is cut out of the mesh (its
regions are wall patches, group `impeller`) and turns with a rotor cell zone that slides on the
stator through a cyclicAMI pair (AMI1 on the rotor's side, AMI2 on the stator's), run by stock pimpleFoam:

    /usr/bin/python3 cases/centrifugal-pump/make_ami_case.py [--geometry DIR]
    /usr/bin/python3 python/fsi/pump_ami_run.py cases/centrifugal-pump -o OUT   (meshes and runs)

One folder per resolution: openfoam-ami-coarse and openfoam-ami-medium (the background cubes of
h = D2/25, D2/50, as the penalized ones). The mesh is made by python/fsi/pump_ami_run.py (or by hand):
    blockMesh; snappyHexMesh -overwrite; createBaffles -overwrite; mergeOrSplitBaffles -split -overwrite
snappyHexMesh carves the impeller (constant/triSurface/impeller.stl) out of the casing
(casing.stl) and marks the rotor, a cylinder (searchableCylinder) around the impeller: radius
half-way between the impeller tip and the volute base circle, z half-way between the impeller
and the casing's chamber (the volute's base width, centred on the impeller channel), as the
faceZone and cellZone `rotor`. createBaffles turns the faceZone into the cyclicAMI pair and
mergeOrSplitBaffles -split gives the two sides their own points, so the rotor can turn
(constant/dynamicMeshDict: solidBody rotatingMotion of the cellZone, case.yaml's axis and rate).
The gaps between impeller and casing (5 mm radially and axially) are thinner than a coarse
cell (8 mm): the cells within GAP_BAND of the rotor cylinder are refined to GAP_CELL (2 mm, the
paper's cell size) so that each half-gap has a cell between wall and interface; elsewhere the
cells are the penalized mesh's h (the impeller surface one level finer, IMPELLER_LEVELS).
It also writes openfoam-coarse-turning-mesh (preset coarse-turning-mesh): that penalized case with
the rotor's faceZone made the AMI pair and its cells turning with the impeller, so that the blades
never switch cells (docs/model.md); openfoam-coarse-fine-blade-turning-mesh (preset
coarse-fine-blade-turning-mesh) is the same with the blade's cells refined (FINE_BLADE, below).
Both methods' turning cases integrate the energy flux out of the rotor every step (ROTOR_BUDGET):
over a revolution, the shaft power less that flux is the power lost in the rotor's water. And
openfoam-coarse-ami-mesh, the penalized case (preset coarse-ami-mesh) meshed by
the same snappyHexMeshDict except for the impeller, kept and refined as a region (IMPELLER_REGION):
the same background cells and the same 2 mm band in the gaps as the AMI mesh, the impeller's
surroundings one level finer in both (measured on the single blade: 177,626 cells, the AMI mesh
183,412 with the impeller cut out: its surface refinement reaches a little farther).
The pair openfoam-ami-coarse-fine-blade / openfoam-coarse-fine-blade-ami-mesh (preset
coarse-fine-blade-ami-mesh) is the coarse pair with the blade's cells refined further, the same in
both (FINE_BLADE): every cell within BLADE_BAND of the blade's own faces (impeller-blade.stl, the
impeller's blade_* regions, written next to impeller.stl) is 2 mm, 4 cells across an 8 mm blade
(issue 30 asks at least 3), and the time step is halved, so that the blade's tip moves about
one of those cells per step.
"""

import argparse
import math
import os
import re
import sys

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
import make_case  # noqa: E402
from fsi.foam_case import write_foam_file  # noqa: E402

RESOLUTIONS = {"coarse": 25, "medium": 50}   # cells across D2, as make_case.RESOLUTIONS
# Where the cells turn, backward in time: implicit Euler keeps cos(omega dt) of a turning cell's
# swirl a step, about 1.96 N m of torque in this rotor's water at omega dt = 0.038 (docs/model.md,
# "The time scheme on turning cells"). The fixed-mesh cases keep make_case.SCHEMES.
TURNING_SCHEMES = make_case.SCHEMES.replace("ddtSchemes      { default Euler; }", "ddtSchemes      { default backward; }")
assert TURNING_SCHEMES != make_case.SCHEMES
# Where the cells turn, the stations are sampled every STATION_INTERVAL steps: each sample of a
# station builds an octree of all the cells (python/fsi/pump_stations.py), a third of every step
# when they were sampled every step. 16.7 samples a revolution at the coarse step.
STATION_INTERVAL = 10
GAP_CELL = 0.002                             # m: the cells in the impeller-casing gaps
GAP_BAND = 0.004                             # m: refined within this distance of the rotor cylinder
IMPELLER_LEVELS = 1                          # levels finer than h on the impeller surface
# Variants with the blade's surroundings finer, the same in both methods: name: (the resolution
# it refines, cell size within BLADE_BAND of the blade, time step factor).
FINE_BLADE = {"coarse-fine-blade": ("coarse", 0.002, 0.5)}
BLADE_BAND = 0.004                           # m: on both sides of the blade's faces


def stl_max_radius(path):
    r = 0.0
    with open(path) as f:
        for line in f:
            words = line.split()
            if words and words[0] == "vertex":
                r = max(r, math.hypot(float(words[1]), float(words[2])))
    return r


SNAPPY = """// Generated by make_ami_case.py: the casing body-fitted with the impeller cut out (its regions
// are wall patches in group impeller) and the rotor cylinder as faceZone + cellZone `rotor`
// (createBaffles makes it the cyclicAMI pair). Cells of h = %(h)g m, the impeller surface
// %(imp)d level(s) finer, the cells within %(band)g m of the rotor cylinder at level %(gap)d
// (%(gapcell)g m): the gaps between impeller and casing are thinner than h.
castellatedMesh true;
snap            true;
addLayers       false;
geometry
{
    casing.stl
    {
        type triSurfaceMesh;
        name casing;
        regions
        {
%(casing_regions)s
        }
    }
    impeller.stl
    {
        type triSurfaceMesh;
        name impeller;
        regions
        {
%(impeller_regions)s
        }
    }
%(blade_geometry)s    rotor
    {
        type   searchableCylinder;
        point1 (0 0 %(z0)r);
        point2 (0 0 %(z1)r);
        radius %(r)r;
    }
}
castellatedMeshControls
{
    maxLocalCells 4000000;
    maxGlobalCells 20000000;
    minRefinementCells 0;
    nCellsBetweenLevels 2;
    features ();
    refinementSurfaces
    {
        casing
        {
            level (0 0);
            patchInfo { type wall; }
            regions
            {
                inlet  { level (0 0); patchInfo { type patch; } }
                outlet { level (0 0); patchInfo { type patch; } }
            }
        }
        impeller
        {
            level (%(imp)d %(imp)d);
            patchInfo { type wall; inGroups (impeller); }
        }
        rotor
        {
            level (%(gap)d %(gap)d);
            faceZone rotor;
            cellZone rotor;
            cellZoneInside inside;
        }
    }
    resolveFeatureAngle 30;
    refinementRegions
    {
        rotor { mode distance; levels ((%(band)r %(gap)d)); }
%(blade_region)s    }
    locationInMesh (%(inside)s);   // in the suction pipe
    allowFreeStandingZoneFaces false;
}
""" + make_case.SNAPPY_CONTROLS

CREATE_BAFFLES = """// Generated by make_ami_case.py: the rotor faceZone of snappyHexMesh becomes the cyclicAMI pair
// (then mergeOrSplitBaffles -split gives each side its own points), as the propeller and
// mixerVessel tutorials.
internalFacesOnly true;
baffles
{
    rotor
    {
        type        faceZone;
        zoneName    rotor;
        patches
        {
            master
            {
                name            AMI1;
                type            cyclicAMI;
                matchTolerance  0.0001;
                neighbourPatch  AMI2;
                transform       noOrdering;
            }
            slave
            {
                name            AMI2;
                type            cyclicAMI;
                matchTolerance  0.0001;
                neighbourPatch  AMI1;
                transform       noOrdering;
            }
        }
    }
}
"""

DYNAMIC_MESH = """// Generated by make_ami_case.py from case.yaml: the rotor cell zone turns as a solid body.
dynamicFvMesh   dynamicMotionSolverFvMesh;
motionSolverLibs ("libfvMotionSolvers.so");
motionSolver    solidBody;
cellZone        rotor;
solidBodyMotionFunction rotatingMotion;
origin          (%(o)s);
axis            (%(a)s);
omega           %(w)r;   // rad/s
"""

FUNCTIONS_MORE = """    // The fluid's force (N) and torque (N m, about the origin on the axis) on the impeller's
    // patches, pressure and viscous parts, every step: python/fsi/pump_ami_run.py writes them
    // to forces.csv.
%(forces)s%(part_forces)s    // The sums of the AMI weights (1 where the two sides overlap fully), min/max/average.
    AMIWeights
    {
        type            AMIWeights;
        libs            ("libfieldFunctionObjects.so");
        writeFields     false;
        writeControl    timeStep;
        writeInterval   1;
    }
%(rotor_budget)s"""

MOVING = """
    // The moving mesh (pimpleFoam with a dynamicMotionSolverFvMesh): the flux on the AMI is
    // corrected after each motion (correctPhi, pcorr); the ddt flux correction (ddtCorr) is
    // always on in v1912 (ddtPhiCoeff by default, the v1712 coefficient).
    correctPhi       yes;
    moveMeshOuterCorrectors no;
    checkMeshCourantNo no;
"""

PCORR = "    \"pcorr.*\" { $p; tolerance 1e-5; relTol 0; }\n"   # correctPhi's pressure solver

# The total-pressure energy flux out of the rotor's water through its AMI face (W: phi in m^3/s
# times p + rho |U|^2 / 2 in Pa, AMI1's faces point out of the rotor), every step, in both methods'
# turning cases. Over a revolution the rotor's water stores nothing, so the shaft power less this
# flux is what the water in the rotor dissipates (python/fsi/pump_point.py: rotor.loss_w).
ROTOR_BUDGET = """    rotorEnergyFlux
    {
        type            surfaceFieldValue;
        libs            ("libfieldFunctionObjects.so");
        regionType      patch;
        name            AMI1;
        operation       weightedSum;
        weightField     phi;
        fields          (totalPressure);
        writeFields     false;
        log             false;
        writeControl    timeStep;
        writeInterval   1;
    }
"""

AMI_ENTRIES = """    AMI1   { type cyclicAMI; value $internalField; }
    AMI2   { type cyclicAMI; value $internalField; }
"""


def add_before_last_brace(text, more):
    k = text.rstrip().rfind("}")
    return text[:k] + more + text[k:]


def link(folder, name, target):
    path = os.path.join(folder, "constant", "triSurface", name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if os.path.lexists(path):
        os.remove(path)
    os.symlink(os.path.relpath(target, os.path.dirname(path)), path)


def rotor_cylinder(design, impeller):
    """(r, z0, z1) of the rotor: half-way between the impeller and the casing's chamber."""
    lo, hi = make_case.stl_bounds(impeller)
    r_tip = stl_max_radius(impeller)
    volute = design["volute"]
    z_mid = 0.5 * design["impeller"]["outlet_width_m"]        # the impeller channel's mid-plane
    chamber = (z_mid - 0.5 * volute["base_width_m"], z_mid + 0.5 * volute["base_width_m"])
    return 0.5 * (r_tip + volute["base_radius_m"]), 0.5 * (chamber[0] + lo[2]), 0.5 * (chamber[1] + hi[2])


# One forces function object (the fluid's force and torque, pressure and viscous parts, every step).
FORCES = """    %(name)s
    {
        type            forces;
        libs            ("libforces.so");
        patches         (%(patches)s);
        rho             rhoInf;
        rhoInf          %(rho)r;
        CofR            (0 0 0);
        writeControl    timeStep;
        writeInterval   1;
        log             false;
    }
"""
PART_FORCES_COMMENT = """    // The same on each part of the impeller (its STL's regions, one patch each): the torque by
    // part, python/fsi/pump_ami_run.py writes parts.csv (the penalized runs' format).
"""


# The penalized impeller on the AMI reference's mesh (the fair comparison of issue 30): the same
# snappyHexMeshDict, except that the impeller is a refinement region, not a surface: its cells are
# kept and not snapped (snapped to a zone of the impeller, the turning penalized impeller diverged
# in 6 steps in the skewed cells at its tip). The region refines the cells whose centres lie within
# half a cell's diagonal of the impeller, those the AMI mesh refines as cut by its surface and a
# few more; the rest, the gaps' band included, is the same.
IMPELLER_AS_HOLE = """        impeller
        {
            level (%(imp)d %(imp)d);
            patchInfo { type wall; inGroups (impeller); }
        }
"""
AMI_REGIONS = """        rotor { mode distance; levels ((%(band)r %(gap)d)); }
"""
IMPELLER_REGION = """        impeller { mode distance; levels ((%(cut)r %(imp)d)); }   // penalized: kept, not snapped
"""


BLADE_GEOMETRY = """    impeller-blade.stl
    {
        type triSurfaceMesh;
        name blade;
    }
"""
BLADE_REGION = """        blade { mode distance; levels ((%(band)r %(level)d)); }   // the blade's cells finer, both methods
"""


def write_blade_stl(impeller):
    """impeller-blade.stl next to impeller.stl: the impeller's blade_* solids (an ASCII STL of named
    solids, as the generator writes it); the path."""
    path = os.path.join(os.path.dirname(impeller), "impeller-blade.stl")
    with open(impeller) as f:
        text = f.read()
    solids = [(name, facets) for name, facets in re.findall(r"^solid (\S+)[^\n]*\n(.*?)^endsolid[^\n]*\n?", text,
                                                             re.S | re.M) if name.startswith("blade")]
    if not solids:
        sys.exit("make_ami_case.py: %s has no blade_* solid to refine around" % impeller)
    body = "".join("solid %s\n%sendsolid %s\n" % (name, facets, name) for name, facets in solids)
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == body:
                return path   # unchanged: not rewritten (the mesh cache keys on it)
    with open(path, "w") as f:
        f.write(body)
    return path


def snappy_dict(design, h, casing, impeller, penalized=False, blade_cell=None):
    """The AMI case's snappyHexMeshDict at cell size h (penalized: the impeller kept as a cell zone;
    blade_cell: the cells within BLADE_BAND of the blade refined to that size)."""
    r, z0, z1 = rotor_cylinder(design, impeller)
    gap = max(0, int(round(math.log2(h / GAP_CELL))))
    regions = lambda path: "\n".join("            %s { name %s; }" % (n, n) for n in make_case.stl_regions(path))
    lo, hi = make_case.stl_bounds(casing)
    inside = (0.0131, 0.0173, lo[2] + 0.05 * (hi[2] - lo[2]) + 0.37 * h)   # as make_case.py
    template = SNAPPY
    if penalized:
        assert IMPELLER_AS_HOLE in SNAPPY and AMI_REGIONS in SNAPPY
        template = SNAPPY.replace(IMPELLER_AS_HOLE, "").replace(AMI_REGIONS, AMI_REGIONS + IMPELLER_REGION)
    text = template % {
        "h": h, "imp": IMPELLER_LEVELS, "gap": gap, "gapcell": h / 2 ** gap, "band": GAP_BAND,
        "cut": round(0.5 * math.sqrt(3.0) * h, 6),
        "blade_geometry": BLADE_GEOMETRY if blade_cell else "",
        "blade_region": BLADE_REGION % {"band": BLADE_BAND, "level": int(round(math.log2(h / blade_cell)))}
        if blade_cell else "",
        "casing_regions": regions(casing), "impeller_regions": regions(impeller),
        "z0": round(z0, 6), "z1": round(z1, 6), "r": round(r, 6), "inside": "%r %r %r" % inside}
    return text, (r, z0, z1), gap


def write_penalized_case(folder, design, h, casing, impeller, fine_blade=None, solution=None,
                         schemes=make_case.SCHEMES, control=None, station_interval=1):
    """openfoam-<resolution>-ami-mesh: the penalized case (make_case.py's, with the Krylov velocity
    solver of its refined variant) meshed by the AMI case's snappyHexMeshDict."""
    make_case.write_case(folder, design, h, "ddes", casing, refine_gaps=True, solution=solution, schemes=schemes,
                         control=control, station_interval=station_interval)
    text, _rotor, _gap = snappy_dict(design, h, casing, impeller, penalized=True,
                                     blade_cell=fine_blade and fine_blade[1])
    write_foam_file(folder, "system/snappyHexMeshDict", "dictionary", text)
    if fine_blade:
        link(folder, "impeller-blade.stl", fine_blade[0])


def write_turning_case(folder, design, case, h, casing, impeller, fine_blade=None):
    """openfoam-<resolution>-turning-mesh: the penalized impeller in the AMI mesh's rotor, whose
    cells turn with it (docs/model.md, "the cells a moving body switches"): the penalized case on
    the AMI case's mesh (write_penalized_case), its rotor faceZone made the cyclicAMI pair
    (createBafflesDict: fsi-openfoam-fluid runs createBaffles and mergeOrSplitBaffles after
    snappyHexMesh), the rotor cell zone turning at case.yaml's rate (dynamicMeshDict), correctPhi
    and pcorr as the AMI case's, and the rotor's energy flux (ROTOR_BUDGET). fine_blade: as
    write_ami_case's."""
    write_penalized_case(folder, design, h, casing, impeller, fine_blade=fine_blade,
                         solution={"more_solvers": PCORR, "more_pimple": MOVING}, schemes=TURNING_SCHEMES,
                         control={"more_functions": ROTOR_BUDGET}, station_interval=STATION_INTERVAL)
    write_rotor_motion(folder, case)


def write_rotor_motion(folder, case, more_u=""):
    """What turns the rotor behind the AMI, in both cases: its faceZone made the cyclicAMI pair
    (createBafflesDict), the cell zone turning with the impeller of case.yaml (dynamicMeshDict),
    and the pair in every field of 0/ (more_u: U's further entries). Both cases are written with
    TURNING_SCHEMES."""
    write_foam_file(folder, "system/createBafflesDict", "dictionary", CREATE_BAFFLES)
    rot = case["collisions"]["surfaces"][0]["motion"]["rotation"]
    write_foam_file(folder, "constant/dynamicMeshDict", "dictionary", DYNAMIC_MESH % {
        "o": " ".join("%r" % float(v) for v in rot["axis_point_m"]),
        "a": " ".join("%r" % float(v) for v in rot["axis_direction"]), "w": float(rot["rate_rad_per_s"])})
    for name in os.listdir(os.path.join(folder, "0")):
        path = os.path.join(folder, "0", name)
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(add_before_last_brace(text, AMI_ENTRIES + (more_u if name == "U" else "")))


def write_ami_case(folder, design, case, h, casing, impeller, dt, fine_blade=None):
    """fine_blade: (impeller-blade.stl, cell size within BLADE_BAND of it), or None."""
    blade = make_case.stl_regions(impeller)
    # controlDict: pimpleFoam, the time step, the penalized case's function objects + forces.
    control = {"comment": "// make_ami_case.py: deltaT of case.yaml (scaled with h), endTime set by pump_ami_run.py.",
               "application": "pimpleFoam", "delta_t": repr(dt), "end_time": repr(case["run"]["end_time_s"]),
               "more_functions": FUNCTIONS_MORE % {
                   "forces": FORCES % {"name": "forces", "patches": " ".join(blade), "rho": make_case.RHO},
                   "part_forces": "".join(PART_FORCES_COMMENT + FORCES % {"name": "forces_" + part, "patches": part,
                                                                          "rho": make_case.RHO} for part in blade),
                   "rotor_budget": ROTOR_BUDGET}}
    # fvSolution: the penalized case's + pcorr and the moving-mesh PIMPLE controls. The
    # body-fitted mesh has no holes in its pressure equation: GAMG alone, as it was measured.
    # The rotor's cells at the gaps are 2 mm: the mesh moves up to 2 cells per step there
    # (Courant number ~2 relative to the mesh), where LUST's implicit part is no longer
    # diagonally dominant and Gauss-Seidel diverges (U to 1e268 in the first step). A Krylov
    # solver takes the same equations to the same tolerance.
    solution = {"p": "{ solver GAMG; smoother GaussSeidel; tolerance 1e-6; relTol 0.01; }",
                "more_solvers": PCORR, "u": make_case.U_KRYLOV, "more_pimple": MOVING}
    box = make_case.write_case(folder, design, h, "ddes", casing, control=control, solution=solution,
                               schemes=TURNING_SCHEMES, station_interval=STATION_INTERVAL)
    link(folder, "impeller.stl", impeller)
    text, (r, z0, z1), gap = snappy_dict(design, h, casing, impeller, blade_cell=fine_blade and fine_blade[1])
    write_foam_file(folder, "system/snappyHexMeshDict", "dictionary", text)
    if fine_blade:
        link(folder, "impeller-blade.stl", fine_blade[0])
    # 0/: the same fields, the AMI pair in each, and the impeller walls moving for U.
    write_rotor_motion(folder, case, "".join("    %s { type movingWallVelocity; value uniform (0 0 0); }\n" % b
                                             for b in blade))
    return box, (r, z0, z1), gap


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--geometry", default=os.path.join(HERE, "geometry"),
                        help="folder of casing.stl and impeller.stl (default: geometry/ of the case)")
    parser.add_argument("--output", default=HERE, help="where the openfoam-ami-* folders go (default: the case)")
    args = parser.parse_args(argv)
    with open(os.path.join(HERE, "pump.yaml")) as f:
        design = yaml.safe_load(f)
    with open(os.path.join(HERE, "case.yaml")) as f:
        case = yaml.safe_load(f)
    casing, impeller = (os.path.abspath(os.path.join(args.geometry, n)) for n in ("casing.stl", "impeller.stl"))
    for path in (casing, impeller):
        if not os.path.exists(path):
            sys.exit("make_ami_case.py: %s is missing; run ./fsi pump-design %s --write %s first"
                     % (path, os.path.join(HERE, "pump.yaml"), args.geometry))
    d2 = design["impeller"]["outer_diameter_m"]
    dt_coarse = case["run"]["time_step_s"]
    for name, n in RESOLUTIONS.items():
        h = d2 / n
        dt = dt_coarse * RESOLUTIONS["coarse"] / n
        box, (r, z0, z1), gap = write_ami_case(os.path.join(args.output, "openfoam-ami-" + name),
                                                design, case, h, casing, impeller, dt)
        print("openfoam-ami-%s: h = %.4g m (gaps %.4g m), background %d cells, rotor r <= %.4g m, "
              "z in [%.4g, %.4g] m, dt = %.3g s" % (name, h, h / 2 ** gap, box["nc"], r, z0, z1, dt))
    # The penalized impeller on the coarse AMI mesh (preset coarse-ami-mesh).
    write_penalized_case(os.path.join(args.output, "openfoam-coarse-ami-mesh"), design, d2 / RESOLUTIONS["coarse"],
                         casing, impeller)
    print("openfoam-coarse-ami-mesh: the penalized case on openfoam-ami-coarse's mesh")
    # The penalized impeller in that mesh's rotor, turning with it (preset coarse-turning-mesh).
    write_turning_case(os.path.join(args.output, "openfoam-coarse-turning-mesh"), design, case,
                       d2 / RESOLUTIONS["coarse"], casing, impeller)
    print("openfoam-coarse-turning-mesh: the penalized impeller in openfoam-ami-coarse's rotor, turning with it")
    blade_stl = write_blade_stl(impeller) if FINE_BLADE else None   # once, for every variant and both methods
    for name, (base, blade_cell, dt_factor) in FINE_BLADE.items():
        h = d2 / RESOLUTIONS[base]
        dt = dt_coarse * RESOLUTIONS["coarse"] / RESOLUTIONS[base] * dt_factor
        write_ami_case(os.path.join(args.output, "openfoam-ami-" + name), design, case, h, casing, impeller, dt,
                       fine_blade=(blade_stl, blade_cell))
        write_penalized_case(os.path.join(args.output, "openfoam-%s-ami-mesh" % name), design, h, casing, impeller,
                             fine_blade=(blade_stl, blade_cell))
        write_turning_case(os.path.join(args.output, "openfoam-%s-turning-mesh" % name), design, case, h, casing,
                           impeller, fine_blade=(blade_stl, blade_cell))
        print("openfoam-ami-%s, openfoam-%s-ami-mesh and openfoam-%s-turning-mesh: %s with %g m cells within %g m "
              "of the blade, dt = %.3g s" % (name, name, name, base, blade_cell, BLADE_BAND, dt))


if __name__ == "__main__":
    main(sys.argv[1:])
