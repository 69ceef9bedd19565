#!/usr/bin/python3
"""Generates this case's inputs before a run: geometry/impeller.stl (the 7 blades of Table 2
extruded through the slab, python/fsi/ercoftac_pump.py) and the mesh of the preset run
(FSI_RESOLUTION, which the launcher sets from --resolution; case.yaml's coarse without one):
<level> meshes openfoam-<level> (the blades penalized in a rotor zone turning with them behind an
AMI), <level>-fixed-mesh openfoam-fixed-<level> (one fixed mesh; gmsh:
python/fsi/ercoftac_mesh.py), each when it is missing
or was made from other inputs (a stamp, generated-from, holds the hash of the data, the two
modules and the level's sizes). Quiet when there is nothing to do; a level takes 10-60 s.

    prepare.py CASE_DIR BIN_DIR     (python/fsi/fsi_launch.py runs it before every run of the case)
"""

import fcntl
import hashlib
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from fsi import ercoftac_mesh, ercoftac_pump  # noqa: E402
from fsi.foam_case import _stl_solid  # noqa: E402
import make_case  # noqa: E402

STL_Z_M = (-0.01, 0.02)   # through the slab of every level (at most 3.3 mm thick)
FIXED_MESH = "-fixed-mesh"  # presets <level>-fixed-mesh: the blades penalized in one fixed mesh


def inputs_hash(*extra):
    digest = hashlib.sha256()
    for path in [ercoftac_mesh.__file__, ercoftac_pump.__file__] + sorted(
            os.path.join(ercoftac_pump.DATA, name) for name in os.listdir(ercoftac_pump.DATA)):
        with open(path, "rb") as f:
            digest.update(f.read())
    digest.update(repr(extra).encode())
    return digest.hexdigest()[:16]


def stamp_matches(path, key):
    try:
        with open(path) as f:
            return f.read().strip() == key
    except FileNotFoundError:
        return False


def write_stamp(path, key):
    with open(path, "w") as f:
        f.write(key + "\n")


def main(case_dir):
    with open(os.path.join(case_dir, ".prepare.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)       # two runs started together prepare once
        geometry = os.path.join(case_dir, "geometry")
        key = inputs_hash("stl", STL_Z_M)
        stamp = os.path.join(geometry, "generated-from")
        if not stamp_matches(stamp, key):
            os.makedirs(geometry, exist_ok=True)
            partial = os.path.join(geometry, "impeller.stl.partial")
            with open(partial, "w") as f:
                f.write(_stl_solid("blades", ercoftac_pump.impeller_triangles(*STL_Z_M)))
            os.replace(partial, os.path.join(geometry, "impeller.stl"))   # a reader never sees half a file
            write_stamp(stamp, key)
            print("prepare: geometry/impeller.stl written (7 blades, z %g to %g m)" % STL_Z_M)
        preset = os.environ.get("FSI_RESOLUTION") or "coarse"
        level, method = preset, "turning"
        if preset.endswith(FIXED_MESH):
            level, method = preset[:-len(FIXED_MESH)], "penalized"
        if level not in make_case.LEVELS:
            return                  # not a level of this case: the coupler refuses the preset
        h_near, h_far = make_case.LEVELS[level]
        folder = make_case.FOLDER_PREFIX[method] + level
        foam_case = os.path.join(case_dir, folder)
        key = inputs_hash(method, h_near, h_far)
        stamp = os.path.join(foam_case, "constant", "polyMesh", "generated-from")
        if stamp_matches(stamp, key):
            return
        cells = ercoftac_mesh.foam_mesh(foam_case, method, h_near, h_far, os.path.join(foam_case, "logs"))
        write_stamp(stamp, key)
        print("prepare: %s meshed (%s): %d cells (h %g to %g m)" % (folder, method, cells, h_near, h_far))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit("usage: prepare.py CASE_DIR BIN_DIR")
    main(os.path.abspath(sys.argv[1]))
