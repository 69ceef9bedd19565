"""A disc turning in a closed cylindrical housing (cases/rotating-disc): its geometry and meshes
for both methods, and the references its torque is measured against.

The disc (radius R, thickness t) turns at omega about the z axis, centred in a housing of radius
R + c and height t + 2 s (axial gap s on each face, radial tip clearance c). The flow is
axisymmetric: both methods run on the same 5-degree wedge mesh (one cell in theta, `wedge`
front and back) of uniform square cells h, from an inner radius r0 (a slip wall on the axis
side: the disc's centre, r < r0, carries (r0 / R)^4 of its torque) out to the housing:
  - penalized: the disc is a closed STL turning with `motion: rotation` inside the full mesh
    (Eqs. 9-10); the housing is the mesh's no-slip walls;
  - body-fitted: the same blocks less the disc's, whose faces are `rotatingWallVelocity`
    patches (stock pimpleFoam): every fluid cell is the same cell in both meshes.
Both place the disc's faces on cell faces (s, t, c and R - r0 multiples of h).

References (C_M = 2 M / (rho omega^2 R^5), M the torque on both faces, Re = omega R^2 / nu,
G = s / R):
  - laminar, merged boundary layers (Daily & Nece 1960, regime I): between infinite parallel
    discs the flow is self-similar (von Karman's ansatz with a finite gap, Stewartson /
    Batchelor); its ODEs are solved here for the wall shear: C_M = 2 pi |g'(0)| / (G Re), with
    |g'(0)| -> 1 (Couette flow, Daily & Nece's C_M = 2 pi / (G Re)) as R_s = omega s^2 / nu -> 0;
  - Daily & Nece's empirical correlations of the four regimes (both faces):
      I   2 pi / (G Re)            II  3.70 G^0.1 Re^-0.5
      III 0.080 G^(-1/6) Re^-0.25  IV  0.102 G^0.1 Re^-0.2
  - the rim: circular Couette flow between R and R + c over the thickness t (laminar).
Daily, J. W. & Nece, R. E. (1960), Chamber dimension effects on induced flow and frictional
resistance of enclosed rotating disks, J. Basic Eng. 82(1), 217-230.

Standard library, plus numpy and scipy for the similarity solution."""

import math
import os
from dataclasses import dataclass

from fsi.foam_case import cylinder_stl, foam_header

WEDGE_DEG = 5.0      # the wedge's opening angle (both methods; loads are scaled by 360 / WEDGE_DEG)
STL_FACETS = 512     # around the disc: the polygon misses the circle by (pi / n)^2 R / 2 = 1.9e-6 m (h/260 at the finest)


@dataclass(frozen=True)
class Disc:
    """Geometry (m), speed (rad/s) and fluid (SI) of one rotating-disc case."""
    radius_m: float = 0.1
    thickness_m: float = 0.004
    axial_gap_m: float = 0.005
    tip_clearance_m: float = 0.005
    inner_radius_m: float = 0.01
    omega_rad_per_s: float = 1.0
    nu_m2_per_s: float = 2.5e-5
    rho_kg_per_m3: float = 1000.0

    @property
    def housing_radius_m(self):
        return self.radius_m + self.tip_clearance_m

    @property
    def reynolds(self):
        """Re = omega R^2 / nu."""
        return self.omega_rad_per_s * self.radius_m ** 2 / self.nu_m2_per_s

    @property
    def gap_ratio(self):
        """G = s / R."""
        return self.axial_gap_m / self.radius_m

    @property
    def gap_reynolds(self):
        """R_s = omega s^2 / nu: the gap's Reynolds number of the similarity solution."""
        return self.omega_rad_per_s * self.axial_gap_m ** 2 / self.nu_m2_per_s

    def torque_scale_n_m(self):
        """rho omega^2 R^5 / 2: the torque of C_M = 1."""
        return 0.5 * self.rho_kg_per_m3 * self.omega_rad_per_s ** 2 * self.radius_m ** 5

    def cells(self, h):
        """(radial cells inside the disc, in the tip clearance; axial cells in a gap, across the
        disc) at cell size h; refused unless every length is a whole number of cells."""
        lengths = {"R - r0": self.radius_m - self.inner_radius_m, "tip clearance": self.tip_clearance_m,
                   "axial gap": self.axial_gap_m, "thickness": self.thickness_m}
        counts = {}
        for name, length in lengths.items():
            n = length / h
            if abs(n - round(n)) > 1e-6 or round(n) < 1:
                raise ValueError("rotating disc: the %s (%g m) is not a whole number of cells of %g m" % (name, length, h))
            counts[name] = int(round(n))
        return counts["R - r0"], counts["tip clearance"], counts["axial gap"], counts["thickness"]


def daily_nece_moment_coefficient(regime, gap_ratio, reynolds):
    """Daily & Nece's C_M (both faces) of regime 'I', 'II', 'III' or 'IV'."""
    g, re = gap_ratio, reynolds
    if regime == "I":
        return 2.0 * math.pi / (g * re)
    if regime == "II":
        return 3.70 * g ** 0.1 * re ** -0.5
    if regime == "III":
        return 0.080 * g ** (-1.0 / 6.0) * re ** -0.25
    if regime == "IV":
        return 0.102 * g ** 0.1 * re ** -0.2
    raise ValueError("Daily & Nece regime %r: one of I, II, III, IV" % (regime,))


def similarity_solution(gap_reynolds):
    """The flow between a disc turning at omega (eta = 0) and a wall at rest
    (eta = z / s = 1), both infinite: u_r = r omega f'(eta), u_theta = r omega g(eta),
    u_z = -2 omega s f(eta), continuity exact; the radial momentum equation differentiated once
    to remove its unknown pressure constant:
        f'''' = -2 R_s (f f''' + g g'),   g'' = 2 R_s (f' g - f g'),
        f = f' = 0, g = 1 at eta = 0;     f = f' = g = 0 at eta = 1.
    Returns eta -> (f, f', f'', f''', g, g') (scipy's collocation solution, tolerance 1e-8).
    Couette flow (R_s -> 0) is g = 1 - eta."""
    import numpy as np
    from scipy.integrate import solve_bvp

    def rhs(_eta, y):
        f, f1, f2, f3, g, g1 = y
        return np.vstack([f1, f2, f3, -2.0 * gap_reynolds * (f * f3 + g * g1), g1,
                          2.0 * gap_reynolds * (f1 * g - f * g1)])

    def bc(a, b):
        return np.array([a[0], a[1], a[4] - 1.0, b[0], b[1], b[4]])

    eta = np.linspace(0.0, 1.0, 201)
    guess = np.zeros((6, eta.size))
    guess[4], guess[5] = 1.0 - eta, -1.0
    solution = solve_bvp(rhs, bc, eta, guess, tol=1e-8, max_nodes=100000)
    if not solution.success:
        raise RuntimeError("rotating disc: the similarity solution did not converge at R_s = %g (%s)"
                           % (gap_reynolds, solution.message))
    return solution.sol


def similarity_wall_shear(gap_reynolds):
    """|g'(0)| of similarity_solution: the disc's wall shear is mu r omega |g'(0)| / s."""
    return abs(float(similarity_solution(gap_reynolds)(0.0)[5]))


def laminar_reference(disc):
    """The laminar torques (N m) of the disc: its two faces from the similarity solution (r0 to
    R), the same by Couette flow (Daily & Nece's regime I), and its rim by circular Couette flow
    in the tip clearance; plus the C_M of each."""
    mu = disc.rho_kg_per_m3 * disc.nu_m2_per_s
    w, r, r0, s = disc.omega_rad_per_s, disc.radius_m, disc.inner_radius_m, disc.axial_gap_m
    shear = similarity_wall_shear(disc.gap_reynolds)
    couette_faces = math.pi * mu * w * (r ** 4 - r0 ** 4) / s
    rh = disc.housing_radius_m
    rim = 4.0 * math.pi * mu * w * r ** 2 * rh ** 2 / (rh ** 2 - r ** 2) * disc.thickness_m
    scale = disc.torque_scale_n_m()
    return {"faces_similarity_n_m": shear * couette_faces, "faces_couette_n_m": couette_faces, "rim_couette_n_m": rim,
            "wall_shear_factor": shear, "cm_faces_similarity": shear * couette_faces / scale,
            "cm_regime_I": daily_nece_moment_coefficient("I", disc.gap_ratio, disc.reynolds),
            "cm_rim": rim / scale}


def _wedge_point(r, z, side):
    half = math.radians(0.5 * WEDGE_DEG)
    return (r * math.cos(half), (-1 if side == 0 else 1) * r * math.sin(half), z)


def block_mesh_dict(disc, h, body_fitted):
    """blockMeshDict of the wedge: 2 x 3 blocks (r: disc, tip clearance; z: lower gap, disc,
    upper gap) of square cells h; without the disc's block when body_fitted (its faces become the
    patches disc_faces and disc_rim)."""
    n_in, n_tip, n_gap, n_disc = disc.cells(h)
    rs = [disc.inner_radius_m, disc.radius_m, disc.housing_radius_m]
    half_t = 0.5 * disc.thickness_m
    zs = [-half_t - disc.axial_gap_m, -half_t, half_t, half_t + disc.axial_gap_m]

    def v(i, side, k):
        return i + 3 * side + 6 * k

    vertices = "\n".join("    (%.12g %.12g %.12g)" % _wedge_point(rs[i], zs[k], side)
                         for k in range(4) for side in range(2) for i in range(3))
    blocks, patches = [], {"housing": [], "axis": [], "wedge_front": [], "wedge_back": [], "disc_faces": [],
                           "disc_rim": []}
    for k in range(3):
        for i in range(2):
            if body_fitted and i == 0 and k == 1:
                continue
            c = [v(i, 0, k), v(i + 1, 0, k), v(i + 1, 1, k), v(i, 1, k),
                 v(i, 0, k + 1), v(i + 1, 0, k + 1), v(i + 1, 1, k + 1), v(i, 1, k + 1)]
            nr = (n_in, n_tip)[i]
            nz = (n_gap, n_disc, n_gap)[k]
            blocks.append("    hex (%s) (%d 1 %d) simpleGrading (1 1 1)" % (" ".join(map(str, c)), nr, nz))

            def face(a, b, cc, d):
                return "(%d %d %d %d)" % (c[a], c[b], c[cc], c[d])
            patches["wedge_front"].append(face(0, 1, 5, 4))
            patches["wedge_back"].append(face(3, 7, 6, 2))
            if i == 0:
                patches["axis"].append(face(0, 4, 7, 3))
            else:
                patches["housing"].append(face(1, 2, 6, 5))
            if k == 0:
                patches["housing"].append(face(0, 3, 2, 1))
            if k == 2:
                patches["housing"].append(face(4, 5, 6, 7))
            if body_fitted and i == 0 and k == 0:
                patches["disc_faces"].append(face(4, 5, 6, 7))
            if body_fitted and i == 0 and k == 2:
                patches["disc_faces"].append(face(0, 3, 2, 1))
            if body_fitted and i == 1 and k == 1:
                patches["disc_rim"].append(face(0, 4, 7, 3))
    types = {"housing": "wall", "axis": "wall", "wedge_front": "wedge", "wedge_back": "wedge", "disc_faces": "wall",
             "disc_rim": "wall"}
    boundary = "\n".join("    %-12s { type %s; faces (%s); }" % (name, types[name], " ".join(faces))
                         for name, faces in patches.items() if faces)
    n_cells = (n_in + n_tip) * (2 * n_gap + n_disc) - (n_in * n_disc if body_fitted else 0)
    return foam_header("dictionary", "blockMeshDict") + """// Generated by python/fsi/rotating_disc.py (%(kind)s). A %(wedge)g-degree wedge about the z axis,
// square cells of %(h)g m, %(n)d cells. Disc R = %(R)g m, t = %(t)g m; axial gap %(s)g m, tip
// clearance %(c)g m; the axis side is a slip wall at r0 = %(r0)g m.
convertToMeters 1;
vertices
(
%(vertices)s
);
blocks
(
%(blocks)s
);
edges ();
boundary
(
%(boundary)s
);
mergePatchPairs ();
""" % {"kind": "body-fitted: the disc is a hole" if body_fitted else "penalized: the disc is an STL inside the mesh",
       "wedge": WEDGE_DEG, "h": h, "n": n_cells, "R": disc.radius_m, "t": disc.thickness_m, "s": disc.axial_gap_m,
       "c": disc.tip_clearance_m, "r0": disc.inner_radius_m, "vertices": vertices, "blocks": "\n".join(blocks),
       "boundary": boundary}


def disc_stl(disc):
    """The closed solid disc (STL text), centred at the origin, axis z; its parts `faces` and
    `rim` (the body-fitted disc's patches disc_faces and disc_rim)."""
    return cylinder_stl(disc.radius_m, -0.5 * disc.thickness_m, 0.5 * disc.thickness_m, STL_FACETS,
                        parts=("faces", "rim"))


def velocity_field(disc, body_fitted):
    """0/U: at rest; no slip on the housing, slip on the axis side, the disc's patches turning."""
    turning = ("    disc_faces { type rotatingWallVelocity; origin (0 0 0); axis (0 0 1); omega %r; value uniform (0 0 0); }\n"
               "    disc_rim   { type rotatingWallVelocity; origin (0 0 0); axis (0 0 1); omega %r; value uniform (0 0 0); }\n"
               % (disc.omega_rad_per_s, disc.omega_rad_per_s)) if body_fitted else ""
    return (foam_header("volVectorField", "U") + "dimensions      [0 1 -1 0 0 0 0];\ninternalField   uniform (0 0 0);\n"
            "boundaryField\n{\n    housing { type noSlip; }\n    axis    { type slip; }\n"
            "    \"wedge_.*\" { type wedge; }\n" + turning + "}\n")


def pressure_field(body_fitted):
    extra = "    \"disc_.*\" { type zeroGradient; }\n" if body_fitted else ""
    return (foam_header("volScalarField", "p") + "dimensions      [0 2 -2 0 0 0 0];\ninternalField   uniform 0;\n"
            "boundaryField\n{\n    housing { type zeroGradient; }\n    axis    { type zeroGradient; }\n"
            "    \"wedge_.*\" { type wedge; }\n" + extra + "}\n")


def turbulence_fields(body_fitted):
    """0/nut and 0/nuTilda of Spalart-Allmaras: Spalding's wall function on the mesh's walls
    (the housing, and the disc's patches when body_fitted), nuTilda = 0 on them; the immersed
    disc is a wall to the fluid's turbulence model by its own rule (nuTilda = 0 inside)."""
    disc_nut = "    \"disc_.*\" { type nutUSpaldingWallFunction; value uniform 0; }\n" if body_fitted else ""
    disc_nu_tilda = "    \"disc_.*\" { type fixedValue; value uniform 0; }\n" if body_fitted else ""
    common = "    axis    { type slip; }\n    \"wedge_.*\" { type wedge; }\n"
    nut = (foam_header("volScalarField", "nut") + "dimensions      [0 2 -1 0 0 0 0];\ninternalField   uniform 0;\n"
           "boundaryField\n{\n    housing { type nutUSpaldingWallFunction; value uniform 0; }\n" + common.replace(
               "type slip;", "type calculated; value uniform 0;") + disc_nut + "}\n")
    nu_tilda = (foam_header("volScalarField", "nuTilda") + "dimensions      [0 2 -1 0 0 0 0];\n"
                "internalField   uniform 0;\nboundaryField\n{\n    housing { type fixedValue; value uniform 0; }\n"
                + common.replace("type slip;", "type zeroGradient;") + disc_nu_tilda + "}\n")
    return {"0/nut": nut, "0/nuTilda": nu_tilda}


SA_RAS = """simulationType  RAS;
RAS
{
    RASModel        SpalartAllmaras;
    turbulence      on;
    printCoeffs     off;
}
"""


def write_foam_case(folder, disc, h, body_fitted, end_time_s, dt_s, fv_schemes, fv_solution, turbulent=False):
    """An OpenFOAM case folder of the disc: mesh dictionary, fields, transport, turbulence
    (laminar, or Spalart-Allmaras RANS), controlDict (for our fluid, or for pimpleFoam with a
    forces function object per disc patch when body_fitted)."""
    files = {
        "system/blockMeshDict": block_mesh_dict(disc, h, body_fitted),
        "0/U": velocity_field(disc, body_fitted),
        "0/p": pressure_field(body_fitted),
        "constant/transportProperties": foam_header("dictionary", "transportProperties")
        + "transportModel  Newtonian;\nnu              %r;\n" % disc.nu_m2_per_s,
        "constant/turbulenceProperties": foam_header("dictionary", "turbulenceProperties")
        + (SA_RAS if turbulent else "simulationType  laminar;\n"),
        "system/fvSchemes": foam_header("dictionary", "fvSchemes") + fv_schemes,
        "system/fvSolution": foam_header("dictionary", "fvSolution") + fv_solution,
        "system/controlDict": foam_header("dictionary", "controlDict") + control_dict(disc, body_fitted, end_time_s, dt_s),
    }
    if turbulent:
        files.update(turbulence_fields(body_fitted))
    for relative, text in files.items():
        path = os.path.join(folder, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)


def control_dict(disc, body_fitted, end_time_s, dt_s):
    forces = ""
    if body_fitted:
        forces = "functions\n{\n" + "".join(
            "    %s\n    {\n        type forces; libs (\"libforces.so\"); patches (%s);\n"
            "        rho rhoInf; rhoInf %r; CofR (0 0 0);\n        writeControl timeStep; writeInterval 1; log false;\n    }\n"
            % (name, name, disc.rho_kg_per_m3) for name in ("disc_faces", "disc_rim")) + "}\n"
    application = "pimpleFoam" if body_fitted else "fsi-openfoam-fluid"
    return ("// endTime and deltaT: %s.\napplication     %s;\nstartFrom       startTime;\nstartTime       0;\n"
            "stopAt          endTime;\nendTime         %r;\ndeltaT          %r;\n%s\npurgeWrite      0;\nwriteFormat     ascii;\nwritePrecision  10;\n"
            "writeCompression off;\ntimeFormat      general;\ntimePrecision   8;\nrunTimeModifiable false;\n%s"
            % ("set by the study" if body_fitted else "case.yaml's run section sets them", application, end_time_s, dt_s,
               "writeControl    runTime;\nwriteInterval   %r;" % end_time_s if body_fitted
               else "writeControl    timeStep;\nwriteInterval   1000000000;", forces))


def read_moments(foam_case, name):
    """[(t, moment about z of the fluid on the patch group, N m per wedge)] of the forces function
    object `name` (postProcessing/<name>/<start>/moment.dat; total = pressure + viscous)."""
    import glob
    from fsi.pump_ami_run import read_foam_vectors
    rows = []
    for start in sorted(glob.glob(os.path.join(foam_case, "postProcessing", name, "*")),
                        key=lambda p: float(os.path.basename(p))):
        rows += [(row[0], row[3]) for row in read_foam_vectors(os.path.join(start, "moment.dat"))]
    return rows


def run_body_fitted(folder, disc, h, end_time_s, dt_s, fv_schemes, fv_solution, turbulent=False, logs=None):
    """The disc as a mesh boundary in stock pimpleFoam on the wedge of cell size h: blockMesh,
    pimpleFoam. Returns {faces, rim: torque of the fluid on them over the whole disc, N m, at the
    end; wall_s; cells}."""
    import time
    from fsi.pump_ami_run import run_pimple, run_tool
    write_foam_case(folder, disc, h, True, end_time_s, dt_s, fv_schemes, fv_solution, turbulent)
    logs = logs or folder
    run_tool("blockMesh", folder, logs)
    start = time.monotonic()
    exec_times, _ = run_pimple(folder, logs, end_time_s, dt_s)
    wall = time.monotonic() - start
    scale = 360.0 / WEDGE_DEG
    faces, rim = read_moments(folder, "disc_faces"), read_moments(folder, "disc_rim")
    if not faces or not rim:
        raise RuntimeError("rotating disc: no moment output in %s/postProcessing" % folder)
    return {"faces_n_m": scale * faces[-1][1], "rim_n_m": scale * rim[-1][1], "wall_s": wall, "steps": len(exec_times),
            "history": [(t, scale * (m + r)) for (t, m), (_, r) in zip(faces, rim)]}


def read_vector_field(path):
    """The internal field of an ASCII OpenFOAM volVectorField file (nonuniform List<vector>), as
    an (n, 3) numpy array."""
    import numpy as np
    with open(path) as f:
        text = f.read()
    body = text[text.index("internalField"):]
    if body.split(None, 2)[1] == "uniform":
        raise ValueError("%s: a uniform internal field, not one value per cell" % path)
    opening = body.index("(")
    count = int(body[:opening].split()[-1])
    closing = body.index("\n)", opening)
    values = np.array(body[opening + 1:closing].replace("(", " ").replace(")", " ").split(), dtype=float)
    if values.size != 3 * count:
        raise ValueError("%s: %d numbers for %d vectors" % (path, values.size, count))
    return values.reshape(count, 3)


def gap_profile(foam_case, time_name, disc, radius_m):
    """The swirl across the upper axial gap in the column of cells nearest radius_m:
    (eta = (z - t/2) / s, u_theta / (r omega)) at the cell centres, from time_name's U (the
    centres by OpenFOAM's writeCellCentres, run here once)."""
    import subprocess
    import numpy as np
    from fsi.foam_case import OPENFOAM_ENVIRONMENT
    centres_path = os.path.join(foam_case, time_name, "C")
    if not os.path.exists(centres_path):
        done = subprocess.run(["postProcess", "-case", foam_case, "-func", "writeCellCentres", "-time", time_name],
                              stdin=subprocess.DEVNULL, capture_output=True, text=True,
                              env=dict(os.environ, **OPENFOAM_ENVIRONMENT))
        if done.returncode != 0 or not os.path.exists(centres_path):
            raise RuntimeError("rotating disc: writeCellCentres failed in %s: %s" % (foam_case, done.stdout[-500:]))
    centres = read_vector_field(centres_path)
    velocity = read_vector_field(os.path.join(foam_case, time_name, "U"))
    r = np.hypot(centres[:, 0], centres[:, 1])
    column_r = r[np.argmin(np.abs(r - radius_m))]
    half_t = 0.5 * disc.thickness_m
    pick = (np.abs(r - column_r) < 1e-9 + 1e-6 * column_r) & (centres[:, 2] > half_t) \
        & (centres[:, 2] < half_t + disc.axial_gap_m)
    order = np.argsort(centres[pick, 2])
    c, u = centres[pick][order], velocity[pick][order]
    u_theta = (-c[:, 1] * u[:, 0] + c[:, 0] * u[:, 1]) / r[pick][order]
    return (c[:, 2] - half_t) / disc.axial_gap_m, u_theta / (column_r * disc.omega_rad_per_s), column_r


def profile_error(eta, swirl, gap_reynolds):
    """Relative L2 difference of a measured swirl profile from the similarity solution's g(eta)."""
    import numpy as np
    exact = similarity_solution(gap_reynolds)(eta)[4]
    return float(np.sqrt(np.sum((swirl - exact) ** 2) / np.sum(exact ** 2)))


def disc_of_run(out_dir):
    """The Disc of a finished run (its speed from config.effective.yaml, its viscosity from the
    run's openfoam/constant/transportProperties; the geometry is the module's)."""
    import yaml
    from fsi.foam_case import foam_entry
    with open(os.path.join(out_dir, "config.effective.yaml")) as f:
        config = yaml.safe_load(f)
    rate = config["collisions"]["surfaces"][0]["motion"]["rotation"]["rate_rad_per_s"]
    nu = float(foam_entry(os.path.join(out_dir, "openfoam", "constant", "transportProperties"), "nu").split()[-1])
    return Disc(omega_rad_per_s=float(rate), nu_m2_per_s=nu,
                rho_kg_per_m3=float(config["fluid"]["openfoam"]["density_kg_per_m3"])), config


def window_mean(history, fraction=0.2):
    """Mean and standard deviation of [(t, value)] over the last `fraction` of the run's time."""
    import numpy as np
    t = np.array([h[0] for h in history])
    v = np.array([h[1] for h in history])
    keep = t >= t[-1] - fraction * (t[-1] - t[0])
    return float(v[keep].mean()), float(v[keep].std())


def penalized_torque(out_dir):
    """The torque of the fluid on the penalized disc over the whole disc (N m, about +z; negative:
    it brakes the disc), per step, from the run's forces.csv (body0, per wedge)."""
    import csv
    with open(os.path.join(out_dir, "forces.csv")) as f:
        rows = list(csv.DictReader(f))
    scale = 360.0 / WEDGE_DEG
    return [(float(r["time_s"]), scale * float(r["body0.tz_n_m"])) for r in rows]


def penalized_part_torques(out_dir):
    """{part: [(t, torque N m about +z over the whole disc)]} of the penalized disc's parts
    (`faces`, `rim`), from the run's parts.csv (body0; the torque of each penalized cell counts for
    the part of the surface closest to it)."""
    import csv
    with open(os.path.join(out_dir, "parts.csv")) as f:
        rows = list(csv.DictReader(f))
    scale = 360.0 / WEDGE_DEG
    parts = [k[len("body0."):-len(".tz_n_m")] for k in rows[0] if k.startswith("body0.") and k.endswith(".tz_n_m")]
    return {p: [(float(r["time_s"]), scale * float(r["body0.%s.tz_n_m" % p])) for r in rows] for p in parts}


def references(disc):
    """The C_M references of a disc: the laminar ones when Re < 1e4 (Daily & Nece's regime I/II
    boundary lies above it at G = 0.05), else regimes III and IV."""
    if disc.reynolds < 1.0e4:
        lam = laminar_reference(disc)
        return {"regime": "laminar (Daily & Nece I)", "cm_regime_I": lam["cm_regime_I"],
                "cm_faces_similarity": lam["cm_faces_similarity"], "cm_rim_couette": lam["cm_rim"],
                "cm_faces_and_rim": lam["cm_faces_similarity"] + lam["cm_rim"]}
    return {"regime": "turbulent (Daily & Nece IV)",
            "cm_regime_IV": daily_nece_moment_coefficient("IV", disc.gap_ratio, disc.reynolds),
            "cm_regime_III": daily_nece_moment_coefficient("III", disc.gap_ratio, disc.reynolds)}
