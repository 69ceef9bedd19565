"""Helpers of the rigid-body penalization tests (tests/fluid_penalization): OpenFOAM case files
written from Python (one hex block, blockMesh), closed STL solids (cylinder, thick tube, box),
case.yaml with the rigid bodies as `mesh` collision surfaces, a coupled run through the launcher,
and reading the ascii fields back at the cell centres of the block.

Debian's /usr/bin/python3 with python3-h5py, python3-numpy and python3-yaml. The executables come
from FSI_BIN_DIR (set by ctest; default <source>/build/bin); OpenFOAM's environment
(WM_PROJECT_DIR) from ctest's ENVIRONMENT. Each test writes into its own temporary folder.
"""

import math
import os
import re
import shutil
import subprocess
import tempfile
import time
import unittest

# The packages (a missing one skips the test, exit 77) and the paths of every coupled test.
from coupled_support import BIN_DIR, LAUNCHER, PYTHON, SOURCE_DIR, h5py, np, yaml  # noqa: F401
from fsi.foam_case import LAMINAR_FV_SCHEMES, foam_header  # noqa: E402

# ---- OpenFOAM case files ---------------------------------------------------------------------



class Block:
    """One axis-aligned hex block of blockMesh, uniform cells: lo, hi (m), n cells per axis.
    blockMesh numbers the cells of a single block x fastest, then y, then z."""

    def __init__(self, lo, hi, n):
        self.lo = np.asarray(lo, float)
        self.hi = np.asarray(hi, float)
        self.n = tuple(int(v) for v in n)
        self.h = (self.hi - self.lo) / np.asarray(self.n)

    @property
    def n_cells(self):
        return self.n[0] * self.n[1] * self.n[2]

    def centres(self):
        """Cell centres (N x 3) in OpenFOAM's cell order."""
        axes = [self.lo[d] + (np.arange(self.n[d]) + 0.5) * self.h[d] for d in range(3)]
        z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
        return np.column_stack([x.ravel(), y.ravel(), z.ravel()])

    def block_mesh_dict(self, patches):
        """patches: {name: (type, [face names among xmin xmax ymin ymax zmin zmax])}."""
        (x0, y0, z0), (x1, y1, z1) = self.lo, self.hi
        faces = {"xmin": "(0 4 7 3)", "xmax": "(1 2 6 5)", "ymin": "(0 1 5 4)", "ymax": "(3 7 6 2)",
                 "zmin": "(0 3 2 1)", "zmax": "(4 5 6 7)"}
        boundary = "\n".join("    %s { type %s; faces (%s); }" % (name, kind, " ".join(faces[f] for f in which))
                             for name, (kind, which) in patches.items())
        return f"""
convertToMeters 1;
vertices
(
    ({x0!r} {y0!r} {z0!r}) ({x1!r} {y0!r} {z0!r}) ({x1!r} {y1!r} {z0!r}) ({x0!r} {y1!r} {z0!r})
    ({x0!r} {y0!r} {z1!r}) ({x1!r} {y0!r} {z1!r}) ({x1!r} {y1!r} {z1!r}) ({x0!r} {y1!r} {z1!r})
);
blocks ( hex (0 1 2 3 4 5 6 7) ({self.n[0]} {self.n[1]} {self.n[2]}) simpleGrading (1 1 1) );
edges ();
boundary
(
{boundary}
);
mergePatchPairs ();
"""


def write_openfoam_case(folder, block, patches, nu, u_internal, u_boundary, p_boundary, solver_tolerance=1e-9):
    """An OpenFOAM case for fsi-openfoam-fluid: laminar, ascii output written once at the end
    (the participant writes the final fields itself), blockMesh run by the participant.
    u_boundary / p_boundary: {patch: 'type ...;' body}."""
    def u_patches(spec):
        return "\n".join("    %s { %s }" % (name, body) for name, body in spec.items())

    files = {
        "system/blockMeshDict": ("dictionary", block.block_mesh_dict(patches)),
        "system/controlDict": ("dictionary", """
application     fsi-openfoam-fluid;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         1e9;
deltaT          1;
writeControl    timeStep;
writeInterval   1000000000;
purgeWrite      0;
writeFormat     ascii;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
"""),
        "system/fvSchemes": ("dictionary", "\n" + LAMINAR_FV_SCHEMES),
        "system/fvSolution": ("dictionary", f"""
solvers
{{
    p      {{ solver GAMG; smoother GaussSeidel; tolerance {solver_tolerance}; relTol 0.01; }}
    pFinal {{ $p; relTol 0; }}
    "(U|UFinal)" {{ solver smoothSolver; smoother symGaussSeidel; tolerance {solver_tolerance}; relTol 0; }}
}}
PIMPLE
{{
    nOuterCorrectors 1;
    nCorrectors      2;
    nNonOrthogonalCorrectors 0;
    momentumPredictor yes;
    pRefCell 0;
    pRefValue 0;
}}
"""),
        "constant/transportProperties": ("dictionary", f"\ntransportModel  Newtonian;\nnu              {nu!r};\n"),
        "constant/turbulenceProperties": ("dictionary", "\nsimulationType  laminar;\n"),
        "0/U": ("volVectorField", """
dimensions      [0 1 -1 0 0 0 0];
internalField   uniform (%r %r %r);
boundaryField
{
%s
}
""" % (tuple(u_internal) + (u_patches(u_boundary),))),
        "0/p": ("volScalarField", """
dimensions      [0 2 -2 0 0 0 0];
internalField   uniform 0;
boundaryField
{
%s
}
""" % u_patches(p_boundary)),
    }
    for name, (cls, body) in files.items():
        path = os.path.join(folder, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(foam_header(cls, os.path.basename(name)) + body)


def latest_time_dir(foam_case):
    times = []
    for entry in os.listdir(foam_case):
        try:
            value = float(entry)
        except ValueError:
            continue
        if value > 0 and os.path.isdir(os.path.join(foam_case, entry)):
            times.append((value, entry))
    if not times:
        raise AssertionError("no time folder written in " + foam_case)
    return os.path.join(foam_case, max(times)[1])


def read_internal_field(path, n_cells):
    """internalField of an ascii volScalarField or volVectorField: (N,) or (N, 3); n_cells None:
    as many as the file holds (not uniform)."""
    with open(path) as f:
        text = f.read()
    uniform = re.search(r"internalField\s+uniform\s+(\([^)]*\)|[^;\s]+)\s*;", text)
    if uniform:
        value = uniform.group(1).strip("()").split()
        row = np.array([float(v) for v in value])
        return np.tile(row, (n_cells, 1)) if row.size > 1 else np.full(n_cells, row[0])
    match = re.search(r"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", text)
    if not match:
        raise AssertionError(path + ": no ascii internalField (writeFormat ascii?)")
    n = int(match.group(2))
    if n_cells is not None and n != n_cells:
        raise AssertionError("%s: %d values, expected %d cells" % (path, n, n_cells))
    body = text[match.end():]
    if match.group(1) == "scalar":
        return np.array(body.split(None, n)[:n], float)
    numbers = re.findall(r"\(\s*(\S+)\s+(\S+)\s+([^\s()]+)\s*\)", body)  # the list comes first
    values = np.array(numbers[:n], float)
    if values.shape != (n, 3):
        raise AssertionError("%s: could not read %d vectors" % (path, n))
    return values


# ---- closed STL solids (outward normals) -----------------------------------------------------

def _ring(radius, z, n):
    a = 2.0 * math.pi * np.arange(n) / n
    return np.column_stack([radius * np.cos(a), radius * np.sin(a), np.full(n, z)])


def cylinder_triangles(radius, z0, z1, n):
    """Solid cylinder about the z axis: side, bottom and top caps (fans from the axis)."""
    bottom, top = _ring(radius, z0, n), _ring(radius, z1, n)
    cb, ct = np.array([0.0, 0.0, z0]), np.array([0.0, 0.0, z1])
    tris = []
    for i in range(n):
        j = (i + 1) % n
        tris += [(bottom[i], bottom[j], top[j]), (bottom[i], top[j], top[i])]
        tris += [(cb, bottom[j], bottom[i]), (ct, top[i], top[j])]
    return tris


def tube_triangles(r_in, r_out, z0, z1, n):
    """Thick tube (closed annular solid) about the z axis: outer and inner walls, annular caps."""
    ob, ot, ib, it = _ring(r_out, z0, n), _ring(r_out, z1, n), _ring(r_in, z0, n), _ring(r_in, z1, n)
    tris = []
    for i in range(n):
        j = (i + 1) % n
        tris += [(ob[i], ob[j], ot[j]), (ob[i], ot[j], ot[i])]      # outer wall, normal +r
        tris += [(ib[i], it[j], ib[j]), (ib[i], it[i], it[j])]      # inner wall, normal -r
        tris += [(ob[i], ib[i], ib[j]), (ob[i], ib[j], ob[j])]      # bottom cap, normal -z
        tris += [(ot[i], it[j], it[i]), (ot[i], ot[j], it[j])]      # top cap, normal +z
    return tris


def box_triangles(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                  [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]], float)
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2), (0, 4, 7, 3), (1, 2, 6, 5)]
    tris = []
    for a, b, c, d in quads:
        tris += [(v[a], v[b], v[c]), (v[a], v[c], v[d])]
    return tris


def write_stl(path, triangles, name="solid"):
    with open(path, "w") as f:
        f.write("solid %s\n" % name)
        for a, b, c in triangles:
            a, b, c = np.asarray(a), np.asarray(b), np.asarray(c)
            normal = np.cross(b - a, c - a)
            normal = normal / np.linalg.norm(normal)
            f.write("  facet normal %.17g %.17g %.17g\n    outer loop\n" % tuple(normal))
            for p in (a, b, c):
                f.write("      vertex %.17g %.17g %.17g\n" % tuple(p))
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid %s\n" % name)


# ---- case.yaml -------------------------------------------------------------------------------

def bystander_sheet(origin, s1, s2, size=0.002):
    """The flexible structure a coupled run needs, held still (every edge fixed; the middle point
    free), tiny, slack (stretching-wave speed sqrt(2 phi / rho_1) = 0.014 m/s, below Delta s / Delta t
    for the time steps used here) and softly coupled (penalty 10 N/m^3: coupling limit ~0.6 s), placed
    where it does not touch the flow under test: its force on the fluid is ~1e-6 N at most."""
    return {"name": "bystander", "model": "membrane", "size_m": [size, size], "n_points": [3, 3],
            "origin_m": list(map(float, origin)), "s1_direction": list(map(float, s1)),
            "s2_direction": list(map(float, s2)),
            "material": {"mass_per_area_kg_per_m2": 1.0,
                         "coefficients": {"tension_coefficient_n_per_m": 1.0e-4, "bending_rigidity_n_m": 0.0}},
            "edges": {"s1_min": "fixed", "s1_max": "fixed", "s2_min": "fixed", "s2_max": "fixed"}}


def write_case(folder, dt, end_time, sheet, surfaces, penalization_time_s, density=1000.0):
    case = {
        "run": {"end_time_s": float(end_time), "time_step_s": float(dt), "output_interval_s": float(end_time)},
        "gravity_m_per_s2": [0.0, 0.0, 0.0],
        "collisions": {"threshold_m": 5.0e-4, "target_distance_m": 5.0e-4, "surfaces": surfaces},
        "structures": [sheet],
        "fluid": {"openfoam": {"case_directory": "openfoam", "density_kg_per_m3": float(density),
                               "penalization_time_s": float(penalization_time_s)}},
        "coupling": {"law": "penalty", "stiffness_n_per_m_per_measure": 10.0},
    }
    with open(os.path.join(folder, "case.yaml"), "w") as f:
        yaml.safe_dump(case, f, default_flow_style=None, sort_keys=False)


def status_of(h5_path):
    with h5py.File(h5_path, "r") as f:
        status = f.attrs["status"]
    return status.decode() if isinstance(status, bytes) else str(status)


def rigid_body_loads(coupling_h5):
    """{body name: (force N x 3, torque N x 3)} per coupled step, from the coupler's results."""
    loads = {}
    with h5py.File(coupling_h5, "r") as f:
        if "rigid_bodies" in f:
            for name, g in f["rigid_bodies"].items():
                loads[name] = (g["force_n"][:], g["torque_n_m"][:])
    return loads


class PenalizationTest(unittest.TestCase):
    """A fresh temporary folder per test (kept with FSI_KEEP_TEST_DIRS=1) and a coupled run."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="fsi-penalization-%s-" % self._testMethodName)

    def tearDown(self):
        if os.environ.get("FSI_KEEP_TEST_DIRS") != "1":
            shutil.rmtree(self.tmp, ignore_errors=True)
        else:
            print("kept", self.tmp)

    def run_case(self, case, out, timeout=120):
        """The launcher on CASE -> OUT; asserts that every process completed. Returns the wall time."""
        start = time.monotonic()
        result = subprocess.run([PYTHON, LAUNCHER, "--bin-dir", BIN_DIR, "-o", out, case],
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                timeout=timeout)
        wall = time.monotonic() - start
        stderr = result.stderr.decode("utf-8", "replace")
        self.assertEqual(result.returncode, 0, stderr[-3000:])
        self.assertEqual(status_of(os.path.join(out, "coupling.h5")), "completed", stderr[-3000:])
        return wall


# ---- a rotor's cells turning behind an AMI --------------------------------------------------

def _gmsh_disc_region(path, r_in, r_out, h, thickness, zone, inner_patch, outer_patch):
    """One region of a quasi-2D disc slab (r_in = 0: a full disc) meshed by gmsh with quads, one
    layer of hexahedra `thickness` thick, written as gmsh 2.2: its cells the zone `zone`, its
    circles the patches inner_patch / outer_patch, its two faces frontAndBack."""
    import gmsh
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add(zone)
        occ = gmsh.model.occ
        disc = occ.addDisk(0, 0, 0, r_out, r_out)
        if r_in > 0:
            disc = occ.cut([(2, disc)], [(2, occ.addDisk(0, 0, 0, r_in, r_in))])[0][0][1]
        occ.synchronize()
        gmsh.model.mesh.setRecombine(2, disc)
        gmsh.option.setNumber("Mesh.MeshSizeMin", h)
        gmsh.option.setNumber("Mesh.MeshSizeMax", h)
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
        extruded = occ.extrude([(2, disc)], 0, 0, thickness, numElements=[1], recombine=True)
        occ.synchronize()
        volume = [tag for dim, tag in extruded if dim == 3][0]
        walls = {}
        for _dim, surface in gmsh.model.getEntities(2):
            box = gmsh.model.getBoundingBox(2, surface)     # OpenCASCADE pads it by its tolerance
            if abs(box[5] - box[2]) < 0.5 * thickness:
                walls.setdefault("frontAndBack", []).append(surface)
            else:
                radius = max(abs(box[3]), abs(box[4]))
                walls.setdefault(outer_patch if abs(radius - r_out) < 0.1 * h else inner_patch, []).append(surface)
        for name, tags in walls.items():
            gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), name)
        gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [volume]), zone)
        gmsh.model.mesh.generate(3)
        gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
        gmsh.write(path)
    finally:
        gmsh.finalize()


def write_turning_disc_mesh(foam_case, r_rotor, r_domain, h, omega, logs):
    """constant/polyMesh of a quasi-2D disc of radius r_domain (one cell h thick, walls `walls`
    around it, `empty` front and back): the cell zone `rotor` (r < r_rotor) turning at omega
    rad/s about +z behind a cyclicAMI pair (ami_rotor, ami_stator), the zone `stator` fixed
    (constant/dynamicMeshDict: pimpleFoam's solidBody rotatingMotion). gmsh, gmshToFoam and
    mergeMeshes, their logs in `logs`."""
    from fsi import ercoftac_mesh
    from fsi.pump_ami_run import run_tool
    os.makedirs(logs, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        rotor_case = os.path.join(tmp, "rotor")
        os.makedirs(os.path.join(rotor_case, "constant"))
        shutil.copytree(os.path.join(foam_case, "system"), os.path.join(rotor_case, "system"))
        for zone, case, r_in, r_out, inner, outer in (("stator", foam_case, r_rotor, r_domain, "ami_stator", "walls"),
                                                      ("rotor", rotor_case, 0.0, r_rotor, "none", "ami_rotor")):
            msh = os.path.join(tmp, zone + ".msh")
            _gmsh_disc_region(msh, r_in, r_out, h, h, zone, inner, outer)
            run_tool("gmshToFoam", case, logs, [msh], who="turning-disc")
            os.rename(os.path.join(logs, "log.gmshToFoam"), os.path.join(logs, "log.gmshToFoam." + zone))
        run_tool("mergeMeshes", foam_case, logs, ["-overwrite", foam_case, rotor_case], who="turning-disc")
    ercoftac_mesh.write_boundary_types(foam_case, {"walls": "wall", "frontAndBack": "empty"})
    with open(os.path.join(foam_case, "constant", "dynamicMeshDict"), "w") as f:
        f.write(foam_header("dictionary", "dynamicMeshDict") + """
dynamicFvMesh   dynamicMotionSolverFvMesh;
motionSolverLibs ("libfvMotionSolvers.so");
motionSolver    solidBody;
cellZone        rotor;
solidBodyMotionFunction rotatingMotion;
origin          (0 0 0);
axis            (0 0 1);
omega           %r;
""" % omega)



def cell_centres_and_volumes(foam_case, time_name, logs):
    """The cell centres (N x 3, m) and volumes (N, m^3) of a case's mesh at a time (a moving
    mesh's points of that time): OpenFOAM's writeCellCentres and writeCellVolumes."""
    from fsi.pump_ami_run import run_tool
    for function in ("writeCellCentres", "writeCellVolumes"):
        run_tool("postProcess", foam_case, logs, ["-func", function, "-time", time_name], who="turning-disc")
        os.rename(os.path.join(logs, "log.postProcess"), os.path.join(logs, "log.postProcess." + function))
    folder = os.path.join(foam_case, time_name)
    volumes = read_internal_field(os.path.join(folder, "V"), None)
    return read_internal_field(os.path.join(folder, "C"), len(volumes)), volumes
