#!/usr/bin/python3
"""stability.py: driver of the numerical stability suite (issue 5, `./fsi test --stability`).

Builds hard cases as Python dictionaries, writes them as case.yaml, runs them with
python/fsi/fsi_launch.py (structure alone, or coupler + structure + prescribed flow), reads
structure.h5 back and checks it: finite state, bounded energy and stretch, no point inside a
rigid body, a clean stop (exit 1, status 'diverged: step N ... point ...', last state finite)
where a case is meant to diverge. Thresholds found by bisection are stored as JSON rows under
OUT/rows/ and collected into the Markdown table OUT/stability.md.

    stability.py report [OUT]    collect OUT/rows/*.json into OUT/stability.md and print it

Environment: FSI_BIN_DIR (default build/bin), FSI_STABILITY_OUT (default build/stability).
Debian's /usr/bin/python3 with python3-numpy, python3-h5py, python3-yaml.
"""

import copy
import glob
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np
import yaml

from fsi import ROOT
BIN_DIR = os.environ.get("FSI_BIN_DIR", os.path.join(ROOT, "build", "bin"))
OUT = os.environ.get("FSI_STABILITY_OUT", os.path.join(ROOT, "build", "stability"))
LAUNCHER = os.path.join(ROOT, "python", "fsi", "fsi_launch.py")
DIVERGED = re.compile(r"^diverged: step (\d+) \(t = [0-9.e+-]+ s\): structure '[^']+', point \d+")


# ----------------------------------------------------------------------------------------------
# Running a case
# ----------------------------------------------------------------------------------------------
class Result:
    """One run: exit code, status attribute and the saved history of every structure."""

    def __init__(self, name, rc, status, time_s, structures, wall_s, log, case):
        self.name, self.rc, self.status, self.time_s = name, rc, status, time_s
        self.structures, self.wall_s, self.log, self.case = structures, wall_s, log, case

    @property
    def completed(self):
        return self.rc == 0 and self.status == "completed"

    def total_energy(self, name):
        s = self.structures[name]
        return s["kinetic_energy_j"] + s["elastic_energy_j"] + s["potential_energy_j"]

    def __repr__(self):
        return "%s: rc %s, status %r, %d saved steps, %.1f s" % (self.name, self.rc, self.status[:200],
                                                                 len(self.time_s), self.wall_s)


def run_case(case, name, timeout_s=600):
    """Writes OUT/runs/NAME/case.yaml, runs it and returns a Result (structure.h5 read back)."""
    case_dir = os.path.join(OUT, "runs", name)
    if os.path.isdir(case_dir):
        shutil.rmtree(case_dir)
    os.makedirs(case_dir)
    with open(os.path.join(case_dir, "case.yaml"), "w") as f:
        yaml.safe_dump(case, f, sort_keys=False)
    out_dir = os.path.join(case_dir, "out")
    start = time.monotonic()
    proc = subprocess.run([sys.executable, LAUNCHER, "--bin-dir", BIN_DIR, "-o", out_dir, case_dir],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout_s)
    wall = time.monotonic() - start
    log = proc.stdout.decode(errors="replace")
    results = os.path.join(out_dir, "structure.h5")
    if not os.path.isfile(results):
        raise RuntimeError("%s: no structure.h5 (exit %d)\n%s" % (name, proc.returncode, log[-3000:]))
    structures = {}
    with h5py.File(results, "r") as f:
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)
        time_s = f["time_s"][:]
        for sname, g in f["structures"].items():
            structures[sname] = {k: g[k][:] for k in ("position_m", "velocity_m_per_s", "max_stretch_ratio",
                                                       "kinetic_energy_j", "elastic_energy_j",
                                                       "potential_energy_j")}
    return Result(name, proc.returncode, status, time_s, structures, wall, log, case)


# ----------------------------------------------------------------------------------------------
# Case builders (SI units; Delta s = 4 mm, the paper's resolution, unless said otherwise)
# ----------------------------------------------------------------------------------------------
def membrane(name="sheet", size=(0.1, 0.1), n=(26, 26), origin=(0, 0, 0), s1=(1, 0, 0), s2=(0, 1, 0),
             rho=0.08, damping=0.0, phi=10.0, zeta=1e-4, edges="free", velocity=(0, 0, 0), curvature=0.0,
             tension="frozen"):
    if isinstance(edges, str):
        edges = {e: edges for e in ("s1_min", "s1_max", "s2_min", "s2_max")}
    return {"solver": {"tension": tension}, "name": name, "model": "membrane", "size_m": list(size), "n_points": list(n),
            "origin_m": list(origin), "s1_direction": list(s1), "s2_direction": list(s2),
            "material": {"mass_per_area_kg_per_m2": rho, "damping_kg_per_m2_s": damping,
                         "coefficients": {"tension_coefficient_n_per_m": phi, "bending_rigidity_n_m": zeta}},
            "edges": edges, "initial": {"velocity_m_per_s": list(velocity), "curvature_1_per_m": curvature}}


def case(structures, end_time_s, dt, output_interval_s=None, gravity=(0, 0, -9.81), collisions=None,
         flow=None, stiffness=None, coupling=None):
    """coupling: the whole coupling section (a law other than penalty, implicit coupling)."""
    c = {"run": {"end_time_s": float(end_time_s), "time_step_s": float(dt),
                 "output_interval_s": float(output_interval_s or end_time_s / 50.0),
                 "progress_interval_s": 60},
         "gravity_m_per_s2": list(gravity)}
    if collisions is not None:
        c["collisions"] = collisions
    c["structures"] = structures
    if flow is not None:
        c["fluid"] = {"prescribed": flow}
        c["coupling"] = coupling or {"law": "penalty", "stiffness_n_per_m_per_measure": float(stiffness)}
    return c


def with_time_step(c, dt, min_steps=3000, min_time_s=None):
    """The case at time step dt, run for at least min_steps steps and min_time_s (short runs)."""
    c = copy.deepcopy(c)
    end = max(min_steps * dt, min_time_s if min_time_s is not None else c["run"]["end_time_s"])
    c["run"]["time_step_s"] = float(dt)
    c["run"]["end_time_s"] = float(end)
    c["run"]["output_interval_s"] = float(max(dt, end / 50.0))
    return c


# ----------------------------------------------------------------------------------------------
# Geometry: signed distance of points to the rigid surfaces (negative: inside the solid)
# ----------------------------------------------------------------------------------------------
def rotate(points, axis_point, axis_dir, angle):
    """Rodrigues rotation of points (N x 3) by angle about the axis."""
    k = np.asarray(axis_dir, float)
    k = k / np.linalg.norm(k)
    p = points - np.asarray(axis_point, float)
    c, s = math.cos(angle), math.sin(angle)
    p = p * c + np.cross(k, p) * s + np.outer(p @ k, k) * (1 - c)
    return p + np.asarray(axis_point, float)


def signed_distance(surface, points, t):
    """Signed distance (m) of points to one collision surface at time t (fluid side positive)."""
    motion = surface.get("motion", {}).get("rotation")
    if motion is not None:  # into the body frame: rotate back by rate * t
        points = rotate(points, motion["axis_point_m"], motion["axis_direction"], -motion["rate_rad_per_s"] * t)
    if "plane" in surface:
        n = np.asarray(surface["plane"]["normal"], float)
        return (points - np.asarray(surface["plane"]["point_m"], float)) @ (n / np.linalg.norm(n))
    if "box" in surface:  # walls seen from inside
        lo, hi = np.asarray(surface["box"]["min_m"], float), np.asarray(surface["box"]["max_m"], float)
        return np.minimum(points - lo, hi - points).min(axis=1)
    if "cylinder" in surface:
        a = np.asarray(surface["cylinder"]["axis_start_m"], float)
        b = np.asarray(surface["cylinder"]["axis_end_m"], float)
        r = surface["cylinder"]["radius_m"]
        length = np.linalg.norm(b - a)
        e = (b - a) / length
        d = points - a
        axial = d @ e
        radial = np.linalg.norm(d - np.outer(axial, e), axis=1)
        out_r = radial - r
        out_a = np.maximum(-axial, axial - length)
        outside = np.sqrt(np.maximum(out_r, 0) ** 2 + np.maximum(out_a, 0) ** 2)
        inside = np.minimum(np.maximum(out_r, out_a), 0.0)
        return outside + inside
    raise ValueError("no signed distance for surface %r" % surface)


def min_wall_distance(result):
    """Smallest signed distance of any point to any collision surface over the saved steps."""
    surfaces = result.case.get("collisions", {}).get("surfaces", [])
    best = math.inf
    for s in result.structures.values():
        for k, t in enumerate(result.time_s):
            for surf in surfaces:
                best = min(best, float(signed_distance(surf, s["position_m"][k], t).min()))
    return best


def min_self_distance(result, name, grid, skip=2):
    """Smallest distance between two points of one sheet that are more than `skip` grid steps
    apart (Chebyshev) over the saved steps: a proxy for self-penetration."""
    n1, n2 = grid
    i1, i2 = np.divmod(np.arange(n1 * n2), n2)  # point index = i1 * n2 + i2 (as the solver names them)
    far = np.maximum(np.abs(i1[:, None] - i1[None, :]), np.abs(i2[:, None] - i2[None, :])) > skip
    best = math.inf
    for x in result.structures[name]["position_m"]:
        d = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2)
        best = min(best, float(d[far].min()))
    return best


# ----------------------------------------------------------------------------------------------
# Health checks
# ----------------------------------------------------------------------------------------------
def problems(result, max_stretch=1.3, energy_max_j=None, wall_min_m=None):
    """Everything wrong with a run meant to be stable ([] when healthy)."""
    out = []
    if not result.completed:
        out.append("did not complete (exit %d, status %r)" % (result.rc, result.status[:160]))
    for name, s in result.structures.items():
        for key, values in s.items():
            if not np.all(np.isfinite(values)):
                out.append("%s: %s not finite" % (name, key))
        stretch = float(np.max(s["max_stretch_ratio"]))
        if not stretch <= max_stretch:
            out.append("%s: max stretch ratio %.4g > %.4g" % (name, stretch, max_stretch))
        if energy_max_j is not None:
            e = result.total_energy(name) - result.total_energy(name)[0]
            if not float(np.max(e)) <= energy_max_j:
                out.append("%s: energy gain %.4g J > %.4g J" % (name, float(np.max(e)), energy_max_j))
    if wall_min_m is not None and result.case.get("collisions", {}).get("surfaces"):
        d = min_wall_distance(result)
        if not d >= wall_min_m:
            out.append("a point %.3g m inside a rigid body (allowed %.3g m)" % (-d, -wall_min_m))
    return out


def clean_stop_problems(result):
    """Everything wrong with a run meant to diverge: it must stop with exit 1, status
    'diverged: step N (t = ...): structure ..., point ...', the last saved state finite and
    before the end time ([] when it stopped cleanly)."""
    out = []
    if result.rc != 1:
        out.append("exit code %d, expected 1" % result.rc)
    if not DIVERGED.match(result.status):
        out.append("status %r does not name the step and the point" % result.status[:200])
    for name, s in result.structures.items():
        for key, values in s.items():
            if not np.all(np.isfinite(values[-1])):
                out.append("%s: last saved %s not finite" % (name, key))
    if len(result.time_s) and result.time_s[-1] >= result.case["run"]["end_time_s"] - 1e-12:
        out.append("ran to the end time")
    return out


def diverged_step(result):
    m = DIVERGED.match(result.status)
    return int(m.group(1)) if m else None


# ----------------------------------------------------------------------------------------------
# Bisection
# ----------------------------------------------------------------------------------------------
def largest_stable(make, lo, hi, is_stable, iterations=6, name="bisect", log=print):
    """Largest x in [lo, hi] with is_stable(run of make(x)), by geometric bisection, assuming
    stability is lost once as x grows. Returns (stable, unstable, runs): the bracket reached
    (stable None: even lo is unstable; unstable None: even hi is stable)."""
    runs = []

    def probe(x):
        r = run_case(make(x), "%s-%.6g" % (name, x))
        ok, why = is_stable(r)
        runs.append((x, ok, why, r.wall_s))
        log("  %s %.6g: %s%s (%.1f s)" % (name, x, "stable" if ok else "unstable",
                                          "" if ok else " (%s)" % why, r.wall_s))
        return ok

    if not probe(lo):
        return None, lo, runs
    if probe(hi):
        return hi, None, runs
    for _ in range(iterations):
        mid = math.sqrt(lo * hi)
        if probe(mid):
            lo = mid
        else:
            hi = mid
    return lo, hi, runs


def stable_by(**limits):
    """is_stable for largest_stable: no problems() with these limits."""
    def check(result):
        p = problems(result, **limits)
        return (not p), "; ".join(p)[:160]
    return check


# ----------------------------------------------------------------------------------------------
# Rows of the report
# ----------------------------------------------------------------------------------------------
def write_row(test, rows):
    """Stores one test's rows: dicts with keys case, quantity, fixed, stable, unstable, predicted, note."""
    os.makedirs(os.path.join(OUT, "rows"), exist_ok=True)
    with open(os.path.join(OUT, "rows", test + ".json"), "w") as f:
        json.dump(rows, f, indent=1)


def fmt(x):
    if x is None:
        return "-"
    if isinstance(x, str):
        return x
    return "%.3g" % x


def report(out=OUT):
    rows = []
    for path in sorted(glob.glob(os.path.join(out, "rows", "*.json"))):
        with open(path) as f:
            rows += json.load(f)
    lines = ["# Stability suite: measured thresholds", "",
             "Largest stable value found by bisection (short runs; stable = completed, finite, stretch "
             "and energy bounded, no point inside a rigid body), the first unstable value, and the "
             "prediction where one exists (stretching wave: Delta s / Delta t >= sqrt(2 phi / rho_1); "
             "penalty law: K_fsi Delta t^2 / rho_1 < 2).", "",
             "| case | quantity | fixed | largest stable | first unstable | predicted limit | Delta s / Delta t at limit (m/s) | note |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["case"], r["quantity"], r.get("fixed", ""), fmt(r.get("stable")), fmt(r.get("unstable")),
            fmt(r.get("predicted")), fmt(r.get("ds_over_dt")), r.get("note", "")))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "stability.md"), "w") as f:
        f.write(text)
    return text


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "report":
        sys.stdout.write(report(sys.argv[2] if len(sys.argv) > 2 else OUT))
    else:
        sys.stderr.write(__doc__)
        sys.exit(2)
