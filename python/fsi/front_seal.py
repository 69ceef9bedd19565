#!/usr/bin/python3
"""The front seal of a generated pump (pump.yaml: impeller.front_seal) as the flow sees it: a
porous ring of cells across the front side gap at the eye, whose resistance leaks what a seal of
the design's clearance leaks. Written into every OpenFOAM folder of a pump case (make_case.py's
write_case), the penalized ones and the body-fitted reference alike, so that both methods see the
same seal:

  system/topoSetDict   the cellZone `front_seal`: the cells whose centres lie in the gap
                       (z from the chamber's floor to the shroud's face) between the suction
                       pipe's radius r_in and r_out = r_in + length_m. Run after meshing
                       (apps/fsi-openfoam-fluid/OpenFoamCase.cpp, python/fsi/pump_ami_run.py).
                       With the sharp body indicator no such cell is a penalized one.
  constant/fvOptions   an explicitPorositySource (DarcyForchheimer, Forchheimer term only) on it.
  the faceZone `front_seal_exit` (topoSetDict too): the faces between the ring and the gap's
                       cells inside r_in, oriented towards the eye; leak_function() sums the face
                       flux phi through it (the leak as the solver conserves it: cell-centred
                       velocities beside the ring's jump in resistance are not the flux).

The seal's leakage law (Gulich, Centrifugal Pumps, section 3.7.1): a gap of clearance s at the
mean radius r_s passes Q_L with the pressure drop
    dp = zeta rho/2 (Q_L / (2 pi r_s s))^2,   zeta = 1.5 + lambda L / (2 s),  lambda = 0.04
(1.5: the entry's 0.5 and the exit's 1; L the seal's length; a turbulent leak, Re_s of some
thousands). In the ring the same leak flows radially across the whole gap g, u = Q_L / (2 pi r g),
and OpenFOAM's Forchheimer term takes dp/dr = rho f / 2 |u| u, so across the ring
    dp = rho f / 2 (Q_L / (2 pi g))^2 (1 / r_in - 1 / r_out).
Equal for every Q_L when
    f = zeta (g / s)^2 / (r_s^2 (1 / r_in - 1 / r_out)),   r_s = (r_in + r_out) / 2.
The side space's swirl crosses the ring too: the isotropic term stops it there (measured: -0.15
m/s in the ring against 2.1 m/s outside it, AMI at 12 L/s), where a real seal's water turns at
about half the shroud's speed. The friction this adds on the shroud over the ring's 64 cm^2 is an
estimate, not measured: below a tenth of a newton metre.

    front_seal.py PUMP_YAML      prints the ring and its coefficient
"""

import math
import os
import sys

import yaml

LAMBDA = 0.04               # the seal's friction factor (turbulent leak)
ZETA_ENDS = 1.5             # entry 0.5 + exit 1.0
ZONE = "front_seal"
EXIT = "front_seal_exit"       # the faceZone of the ring's side towards the eye
LEAK_FUNCTION_NAME = "frontSealLeak"
# The defaults of pump/PumpDesign.hpp for the keys the ring reads (a pump.yaml may leave them
# out; pump.SealLaw checks them against fsi-pump-design --schema).
DEFAULTS = {"impeller.front_seal.clearance_m": 0.0004, "impeller.front_seal.length_m": 0.015,
            "impeller.single_channel.disc_thickness_m": 0.008, "impeller.blade_thickness_m": 0.008}


def ring(design):
    """The porous ring of a design (pump.yaml as a dict), or None without a front seal. SI:
    r_in_m, r_out_m, z_floor_m, z_face_m, gap_m, clearance_m, length_m, zeta, f_per_m."""
    imp = design["impeller"]
    seal = imp.get("front_seal")
    if seal is None:
        return None
    s = float(seal.get("clearance_m", DEFAULTS["impeller.front_seal.clearance_m"]))
    length = float(seal.get("length_m", DEFAULTS["impeller.front_seal.length_m"]))
    channel = imp.get("single_channel")
    disc = float(channel.get("disc_thickness_m", DEFAULTS["impeller.single_channel.disc_thickness_m"])) \
        if channel is not None else float(imp.get("blade_thickness_m", DEFAULTS["impeller.blade_thickness_m"]))
    z_floor = 0.5 * (float(imp["outlet_width_m"]) - float(design["volute"]["base_width_m"]))
    z_face = -disc
    gap = z_face - z_floor
    r_in = 0.5 * float(design["inlet"]["suction_pipe_diameter_m"])
    r_out = r_in + length
    zeta = ZETA_ENDS + LAMBDA * length / (2.0 * s)
    r_s = 0.5 * (r_in + r_out)
    f = zeta * (gap / s) ** 2 / (r_s ** 2 * (1.0 / r_in - 1.0 / r_out))
    return {"r_in_m": r_in, "r_out_m": r_out, "z_floor_m": z_floor, "z_face_m": z_face, "gap_m": gap,
            "clearance_m": s, "length_m": length, "zeta": zeta, "f_per_m": f}


def seal_pressure_drop(seal, leak_m3_per_s, rho=1000.0):
    """The leakage law's pressure drop (Pa) of the seal at a leak (m^3/s)."""
    r_s = 0.5 * (seal["r_in_m"] + seal["r_out_m"])
    v = leak_m3_per_s / (2.0 * math.pi * r_s * seal["clearance_m"])
    return seal["zeta"] * 0.5 * rho * v * abs(v)


def seal_leak(seal, dp_pa, rho=1000.0):
    """The leak (m^3/s) of the seal under a pressure drop (Pa): the inverse of seal_pressure_drop."""
    r_s = 0.5 * (seal["r_in_m"] + seal["r_out_m"])
    return 2.0 * math.pi * r_s * seal["clearance_m"] * math.sqrt(2.0 * max(dp_pa, 0.0) / (rho * seal["zeta"]))


TOPO_SET = """// The front seal's ring (python/fsi/front_seal.py): cells with centres in the front side gap
// (z %(z_floor_m).6g .. %(z_face_m).6g m) between r = %(r_in_m).6g and %(r_out_m).6g m.
actions
(
    { name %(zone)s; type cellSet; action new; source cylinderAnnulusToCell;
      sourceInfo { p1 (0 0 %(z_floor_m)r); p2 (0 0 %(z_face_m)r); outerRadius %(r_out_m)r; innerRadius %(r_in_m)r; } }
    { name %(zone)s; type cellZoneSet; action new; source setToCellZone; sourceInfo { set %(zone)s; } }
    // Its exit: the faces between it and the cells of the gap's band just inside r_in (the eye's
    // side), a faceZone oriented out of the ring, through which the leak's face flux is summed.
    { name %(zone)s_eye_side; type cellSet; action new; source cylinderAnnulusToCell;
      sourceInfo { p1 (0 0 %(z_floor_m)r); p2 (0 0 %(z_face_m)r); outerRadius %(r_in_m)r; innerRadius %(r_eye_side_m)r; } }
    { name %(exit)s; type faceSet; action new; source cellToFace; sourceInfo { set %(zone)s; option all; } }
    { name %(exit)s; type faceSet; action subset; source cellToFace; sourceInfo { set %(zone)s_eye_side; option all; } }
    { name %(exit)s; type faceZoneSet; action new; source setsToFaceZone;
      sourceInfo { faceSet %(exit)s; cellSet %(zone)s; } }
);
"""


FV_OPTIONS = """// The front seal (python/fsi/front_seal.py): clearance %(clearance_m).6g m, length %(length_m).6g m,
// zeta = %(zeta).4g, across a gap of %(gap_m).6g m: f = zeta (g/s)^2 / (r_s^2 (1/r_in - 1/r_out)).
frontSeal
{
    type            explicitPorositySource;
    active          yes;
    explicitPorositySourceCoeffs
    {
        selectionMode   cellZone;
        cellZone        %(zone)s;
        type            DarcyForchheimer;
        d               (0 0 0);
        f               (%(f_per_m)r %(f_per_m)r %(f_per_m)r);
        coordinateSystem
        {
            type        cartesian;
            origin      (0 0 0);
            coordinateRotation { type axesRotation; e1 (1 0 0); e2 (0 1 0); }
        }
    }
}
"""


def write(folder, design):
    """Writes (or, without a front seal, removes) the OpenFOAM folder's topoSetDict and fvOptions."""
    from fsi.foam_case import write_foam_file   # noqa: E402  (here: the module's maths need no OpenFOAM)
    seal = ring(design)
    paths = [os.path.join(folder, "system", "topoSetDict"), os.path.join(folder, "constant", "fvOptions")]
    if seal is None:
        for path in paths:
            if os.path.exists(path):
                os.remove(path)
        return None
    values = dict(seal, zone=ZONE, exit=EXIT, r_eye_side_m=max(seal["r_in_m"] - seal["length_m"], 0.0))
    write_foam_file(folder, "system/topoSetDict", "dictionary", TOPO_SET % values)
    write_foam_file(folder, "constant/fvOptions", "dictionary", FV_OPTIONS % values)
    return seal


def leak_function(design, interval=1):
    """The controlDict entry (inside `functions { }`) that sums the face flux through the ring's
    exit every `interval` steps (postProcessing/frontSealLeak), or "" without a front seal."""
    if ring(design) is None:
        return ""
    from fsi.foam_case import field_value_function   # noqa: E402  (here: the module's maths need no OpenFOAM)
    every = "step" if interval == 1 else "%d steps" % interval
    return ("    // The leak through the front seal (python/fsi/front_seal.py): the face flux phi summed over\n"
            "    // the ring's exit towards the eye (m^3/s, towards the eye positive), every %s.\n" % every
            + field_value_function(LEAK_FUNCTION_NAME, "faceZone", EXIT, "sum", "phi", interval))


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__.strip().splitlines()[-1].strip())
    with open(argv[1]) as f:
        seal = ring(yaml.safe_load(f))
    if seal is None:
        print("%s: no impeller.front_seal" % argv[1])
        return 0
    for key, value in seal.items():
        print("%-12s %.6g" % (key, value))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
