"""Helpers of the two-way coupled tests with the OpenFOAM fluid (tests/coupled_openfoam): copies of
the shipped cases in a temporary folder, OpenFOAM's ascii fields read with numpy, the cell
centres of a one-block blockMesh channel, and the trapezoidal measure of the Lagrangian points.

Builds on tests/support/coupled_support.py (where the executables are, how a run is launched).
"""

import os
import re
import shutil
import sys


# Re-exported for the tests: EPS, StructureResults, TempDirTest, write_case.
from coupled_support import (BIN_DIR, EPS, StructureResults, TempDirTest, case_dir,  # noqa: E402,F401
                             load_case, np, reference, write_case)

import h5py  # noqa: E402  (coupled_support has checked that it is installed)
from fsi.foam_case import set_foam_entry  # noqa: E402

OPENFOAM_FLUID = os.path.join(BIN_DIR, "fsi-openfoam-fluid")


def require_openfoam_fluid():
    """Exit code 77 (ctest: skipped) when the OpenFOAM participant was not built."""
    if not os.access(OPENFOAM_FLUID, os.X_OK):
        print("SKIP: %s not built (OpenFOAM not available)" % OPENFOAM_FLUID)
        sys.exit(77)


# ---- cases -----------------------------------------------------------------------------------

def copy_case(name, target, write_format="ascii"):
    """cases/<name> (case.yaml and its OpenFOAM folder, not output/) copied to target, with
    OpenFOAM's writeFormat set so that numpy can read the written fields."""
    source = case_dir(name)
    os.makedirs(target)
    shutil.copy(os.path.join(source, "case.yaml"), target)
    foam = load_case(source)["fluid"]["openfoam"]["case_directory"]
    shutil.copytree(os.path.join(source, foam), os.path.join(target, foam))
    set_foam_entry(os.path.join(target, foam, "system", "controlDict"), "writeFormat", write_format)
    return target


# ---- OpenFOAM fields and mesh ----------------------------------------------------------------

def read_vector_field(path):
    """internalField of an ascii volVectorField: [n_cells, 3]."""
    with open(path) as f:
        text = f.read()
    match = re.search(r"internalField\s+nonuniform\s+List<vector>\s*(\d+)\s*\(", text)
    if match is None:
        raise ValueError("%s: no nonuniform ascii internalField (writeFormat binary?)" % path)
    n_cells = int(match.group(1))
    body = text[match.end():]
    body = body[:body.index("\n)")]
    values = np.array(body.replace("(", " ").replace(")", " ").split(), dtype=float)
    return values.reshape(n_cells, 3)


def block_mesh_cell_centres(foam_dir):
    """Cell centres [n_cells, 3] of a one-block, axis-aligned, uniformly graded blockMeshDict,
    in blockMesh's order (x fastest, then y, then z); also the cell counts (nx, ny, nz)."""
    with open(os.path.join(foam_dir, "system", "blockMeshDict")) as f:
        text = re.sub(r"//.*", "", f.read())
    vertices = re.search(r"vertices\s*\((.*?)\)\s*;", text, re.S).group(1)
    points = np.array([p.split() for p in re.findall(r"\(([^()]*)\)", vertices)], dtype=float)
    block = re.search(r"hex\s*\([^)]*\)\s*\((\d+)\s+(\d+)\s+(\d+)\)\s*simpleGrading\s*\(1 1 1\)", text)
    if block is None:
        raise ValueError("%s: not a single uniformly graded hex block" % foam_dir)
    counts = [int(block.group(k)) for k in (1, 2, 3)]
    low, high = points.min(axis=0), points.max(axis=0)
    axes = [low[d] + (np.arange(counts[d]) + 0.5) * (high[d] - low[d]) / counts[d] for d in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    return np.column_stack([x.ravel(), y.ravel(), z.ravel()]), tuple(counts)


def latest_time_folder(foam_dir):
    times = [d for d in os.listdir(foam_dir) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0]
    if not times:
        raise ValueError("%s: no time folder written" % foam_dir)
    return os.path.join(foam_dir, max(times, key=float)), max(float(t) for t in times)


# ---- results ---------------------------------------------------------------------------------

def point_measures(out, name):
    """Trapezoidal area (or length) of each Lagrangian point, in the order of structure.h5
    (row-major over (s1, s2)), from the structure's grid and effective size."""
    with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
        n1, n2 = (int(v) for v in f["structures"][name].attrs["grid_shape"])
    case = load_case(os.path.join(out, "config.effective.yaml"))
    structure = next(s for s in case["structures"] if s["name"] == name)
    l1, l2 = (float(v) for v in structure["size_m"])

    def weights(n, length):
        w = np.full(n, length / (n - 1))
        w[0] = w[-1] = w[0] / 2
        return w

    return np.outer(weights(n1, l1), weights(n2, l2)).ravel()


def coupling_forces(out):
    """(time_s [steps], total_force_on_fluid_n [steps, 3]) from coupling.h5."""
    with h5py.File(os.path.join(out, "coupling.h5"), "r") as f:
        return f["time_s"][:], f["total_force_on_fluid_n"][:]
