#!/usr/bin/python3
"""bench_fluid.py: time per step of the OpenFOAM fluid, side by side with Debian's stock pimpleFoam
(issue 4, "Speed"; run by `./fsi bench fluid`).

    bench_fluid.py [--bin-dir DIR] [-o DIR] [--cells NX NY NZ] [--steps N] [--warmup W]
                   [--rounds R] [--dt S] [--variants stock,a,b,c,b0,c0,c1,c2,cs,cn] [--ranks 1,2]

One mesh (a 0.4 x 0.1 x 0.1 m channel, blockMesh, 168 x 42 x 42 = 296,352 cubic cells by
default), one set of PIMPLE settings and schemes (those of cases/sheet-in-openfoam-channel:
Euler, linearUpwind, GAMG p, smoothSolver U, 1 outer x 2 pressure correctors), a uniform
0.1 m/s stream. Variants, interleaved (stock, a, b, c, stock, a, b, c, ...) for R rounds:
  stock  /usr/bin/pimpleFoam on the same case (no coupling at all)
  stockt stock with the allocator settings our executables set for themselves (common/Allocator.hpp, here
         through GLIBC_TUNABLES): without them glibc hands OpenFOAM's per-step fields back to the kernel and
         page-faults them in again every step, about 2x slower on this machine. With stockt in the
         variants, ratios are to stockt (the methods compared, not the allocators).
  a      fsi-openfoam-fluid, no structure in the flow: the coupled run needs one, so a 3 x 3-point (the smallest membrane)
         fixed sheet (2 mm) sits 2 cm before the outlet, softly coupled
  b      fsi-openfoam-fluid, a free 50 x 50-point sheet (2,500 points, 6 x 6 cm) across the stream
  c      fsi-openfoam-fluid, the 3 x 3 sheet of (a) plus a rigid torus STL (~100k triangles) tumbling
         about a diameter (z axis) at 10 rad/s in mid-channel, penalized by the fluid (Eqs. 9-10)
  b0, c0 controls: (b) with the coupling stiffness x 1e-9 (forces ~0), (c) with penalization_time_s
         1e3 s (rate 1e-3 1/s): every step does the same IBM / penalization work, but the flow, hence
         the linear solvers' work, stays that of stock; (b) and (c) also pay for the harder pressure
         equation their forcing makes (more GAMG iterations: see the iteration columns)
  c1, c2 (c) with fluid.openfoam.body_indicator inside_smoothed over 1 and 2 cells (chi ramps from 0 at the
         surface to 1 at that depth inside, 0 outside: the body does not grow)
  cs     (c) with the torus static (same place, no rotation): what the body alone costs the pressure
  cn     (c) with fluid.openfoam.interface_flux body_normal (the penalized cells are holes of the pressure
         equation; the faces to free cells carry the body velocity's normal component)
--ranks 1,2 runs every variant on each number of MPI ranks (stock: decomposePar hierarchical along x
as our fluid does it, then mpirun -np N pimpleFoam -parallel; ours: fluid.openfoam.mpi_ranks N) and adds a
speedup table (time per step on 1 rank / on N, each variant against itself) and the master's log of the
time in the Lagrangian broadcasts and reductions per step.
What the numbers contain (per time step, the first W steps of each run dropped):
  stock  wall time between consecutive `ExecutionTime = ...` lines of its log, time-stamped as
         they arrive through a pipe (OpenFOAM flushes each): Courant number, the PIMPLE loop
         (momentum predictor, 2 pressure corrections), turbulence->correct() (laminar: none),
         runTime.write() (nothing written: writeInterval > steps), continuity errors. Also its
         CPU time (differences of ExecutionTime) as a cross-check.
  ours   coupling.h5 /timings/fluid_solve_s + /timings/interpolation_s, wall times measured inside
         the fluid process around its two requests (no messaging, no coupler, no structure):
         interpolation_s = kernel widths (nearest cell per point), KernelStencil build, weight
         normalisation, copy of U, kernel interpolation; fluid_solve_s = spreading (Eq. 8) into
         a cell field, copy into fsiAcceleration, rigid bodies: chi/u_rib update + copy into
         penalizationRate/rigidVelocity, the PIMPLE step (same code as pimpleFoam's UEqn.H/pEqn.H
         plus the sources), then (bodies) the penalization force and body loads.
The structure and the coupler run concurrently in their own processes (the machine's other core).
Output: <out>/results.md (the table), <out>/results.json (every per-step time), the runs in
<out>/runs/<variant>-r<round>/ (stock: log.pimpleFoam; ours: coupling.h5, logs/fluid.console).
Python standard library + numpy + h5py + yaml (Debian's python3-* packages).
"""

import argparse
import datetime
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import time

import h5py
import numpy as np
import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from fsi.fsi_launch import ALLOCATOR_TUNABLES  # noqa: E402  (the settings of common/Allocator.hpp)
from fsi.foam_case import foam_header  # noqa: E402
FOAM_ENV = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))
GOALS = {"a": 1.02, "b": 1.10, "c": 1.15, "b0": 1.10, "c0": 1.15, "c1": 1.25, "c2": 1.25}
LABELS = {"stock": "stock pimpleFoam", "stockt": "stock pimpleFoam, our allocator settings (GLIBC_TUNABLES)", "a": "(a) ours, no structure (3x3 sheet far downstream)",
          "b": "(b) ours, 50x50-point sheet", "c": "(c) ours, rotating STL torus",
          "b0": "(b0) = (b), coupling stiffness x 1e-9: IBM work, flow undisturbed",
          "c0": "(c0) = (c), penalization time 1e3 s: penalization work, flow undisturbed",
          "c1": "(c1) = (c), indicator smoothed 1 cell inside the surface",
          "c2": "(c2) = (c), indicator smoothed 2 cells inside the surface",
          "cs": "(cs) = (c), the torus static",
          "cn": "(cn) = (c), interface_flux body_normal"}
TORUS_VARIANTS = ("c", "c0", "c1", "c2", "cs", "cn")


# ---- the OpenFOAM case (written once, meshed once, copied for every run) ----------------------

def write_foam_case(folder, cells, dt, n_steps):
    length = (0.4, 0.1, 0.1)
    files = {
        "system/blockMeshDict": foam_header("dictionary", "blockMeshDict") + """convertToMeters 1;
vertices ((0 0 0) (%g 0 0) (%g %g 0) (0 %g 0) (0 0 %g) (%g 0 %g) (%g %g %g) (0 %g %g));
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
edges ();
boundary
(
    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    walls  { type wall;  faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }
);
mergePatchPairs ();
""" % (length[0], length[0], length[1], length[1], length[2], length[0], length[2], length[0], length[1],
       length[2], length[1], length[2], cells[0], cells[1], cells[2]),
        # writeInterval beyond the run: neither solver writes fields during the measured steps.
        "system/controlDict": foam_header("dictionary", "controlDict") + """application pimpleFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime %.10g; deltaT %.10g;
writeControl timeStep; writeInterval 1000000; purgeWrite 0; writeFormat binary; writePrecision 8;
writeCompression off; timeFormat general; timePrecision 8; runTimeModifiable false; adjustTimeStep no;
""" % (n_steps * dt, dt),
        "system/fvSchemes": foam_header("dictionary", "fvSchemes") + """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linearUpwind grad(U); div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""",
        "system/fvSolution": foam_header("dictionary", "fvSolution") + """solvers
{
    p      { solver GAMG; smoother GaussSeidel; tolerance 1e-7; relTol 0.01; }
    pFinal { $p; relTol 0; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0; }
}
PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; momentumPredictor yes; }
""",
        "constant/transportProperties": foam_header("dictionary", "transportProperties") +
        "transportModel Newtonian;\nnu 1e-06;\n",
        "constant/turbulenceProperties": foam_header("dictionary", "turbulenceProperties") + "simulationType laminar;\n",
        "0/U": foam_header("volVectorField", "U") + """dimensions [0 1 -1 0 0 0 0];
internalField uniform (0.1 0 0);
boundaryField
{
    inlet  { type fixedValue; value uniform (0.1 0 0); }
    outlet { type zeroGradient; }
    walls  { type noSlip; }
}
""",
        "0/p": foam_header("volScalarField", "p") + """dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet  { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    walls  { type zeroGradient; }
}
""",
    }
    for name, text in files.items():
        path = os.path.join(folder, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
    with open(os.path.join(folder, "log.blockMesh"), "w") as log:
        subprocess.run(["blockMesh", "-case", folder], stdout=log, stderr=subprocess.STDOUT, env=FOAM_ENV, check=True)


# ---- the rigid body: a torus, binary STL --------------------------------------------------------

def write_torus_stl(path, centre, major_r, minor_r, n_u, n_v):
    """Closed torus, outward normals, 2 n_u n_v triangles; its symmetry axis along x (rotated from z
    by a proper rotation (x, y, z) -> (z, y, -x)), centred at `centre`."""
    u = 2 * math.pi * np.arange(n_u) / n_u
    v = 2 * math.pi * np.arange(n_v) / n_v
    uu, vv = np.meshgrid(u, v, indexing="ij")
    ring = major_r + minor_r * np.cos(vv)
    local = np.stack([ring * np.cos(uu), ring * np.sin(uu), minor_r * np.sin(vv)], axis=-1)  # [n_u, n_v, 3]
    world = np.stack([local[..., 2], local[..., 1], -local[..., 0]], axis=-1) + np.asarray(centre)
    i = np.arange(n_u)[:, None]
    j = np.arange(n_v)[None, :]
    i1, j1 = (i + 1) % n_u, (j + 1) % n_v
    p00, p10 = world[i, j], world[i1, j]
    p11, p01 = world[i1, j1], world[i, j1]
    tri = np.concatenate([np.stack([p00, p10, p11], axis=2).reshape(-1, 3, 3),
                          np.stack([p00, p11, p01], axis=2).reshape(-1, 3, 3)])
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    records = np.zeros(len(tri), dtype=[("n", "<f4", 3), ("v", "<f4", 9), ("a", "<u2")])
    records["n"] = normal
    records["v"] = tri.reshape(-1, 9)
    with open(path, "wb") as f:
        f.write(b"torus for bench_fluid.py".ljust(80, b" "))
        f.write(struct.pack("<I", len(tri)))
        f.write(records.tobytes())
    return len(tri)


# ---- case.yaml of our variants ------------------------------------------------------------------

def small_sheet(x):
    """3 x 3 points (the least a membrane takes), 2 mm, every edge fixed (the middle point free), near the outlet: the structure a coupled run needs."""
    return {"name": "bystander", "model": "membrane", "size_m": [0.002, 0.002], "n_points": [3, 3],
            "origin_m": [x, 0.049, 0.049], "s1_direction": [0.0, 1.0, 0.0], "s2_direction": [0.0, 0.0, 1.0],
            "material": {"mass_per_area_kg_per_m2": 1.0,
                         "coefficients": {"tension_coefficient_n_per_m": 1.0e-4, "bending_rigidity_n_m": 0.0}},
            "edges": {"s1_min": "fixed", "s1_max": "fixed", "s2_min": "fixed", "s2_max": "fixed"}}


def big_sheet():
    """50 x 50 points, 6 x 6 cm (Delta s = 1.2 mm, half a cell), free, across the stream."""
    return {"name": "sheet", "model": "membrane", "size_m": [0.06, 0.06], "n_points": [50, 50],
            "origin_m": [0.1, 0.02, 0.02], "s1_direction": [0.0, 1.0, 0.0], "s2_direction": [0.0, 0.0, 1.0],
            "material": {"mass_per_area_kg_per_m2": 0.08,
                         "coefficients": {"tension_coefficient_n_per_m": 1.0, "bending_rigidity_n_m": 1.0e-6}},
            "edges": {"s1_min": "free", "s1_max": "free", "s2_min": "free", "s2_max": "free"}}


def write_our_case(folder, variant, template, stl, dt, n_steps, ranks=1):
    case = {
        "run": {"end_time_s": n_steps * dt, "time_step_s": dt, "output_interval_s": n_steps * dt,
                "progress_interval_s": 1000.0},
        "gravity_m_per_s2": [0.0, 0.0, 0.0],
        "structures": [big_sheet() if variant in ("b", "b0") else small_sheet(0.38)],
        "fluid": {"openfoam": {"case_directory": os.path.relpath(template, folder), "density_kg_per_m3": 1000.0,
                               "penalization_time_s": 1.0e3 if variant == "c0" else 1.0e-6}},
        "coupling": {"law": "penalty", "stiffness_n_per_m_per_measure": {"b": 3.2e4, "b0": 3.2e-5}.get(variant, 10.0)},
    }
    if variant in TORUS_VARIANTS:
        surface = {"mesh": {"file": os.path.abspath(stl), "fluid_side": "outside"}}
        if variant != "cs":
            surface["motion"] = {"rotation": {"axis_point_m": [0.2, 0.05, 0.05], "axis_direction": [0.0, 0.0, 1.0],
                                              "rate_rad_per_s": 10.0}}
        case["collisions"] = {"threshold_m": 5.0e-4, "target_distance_m": 5.0e-4, "surfaces": [surface]}
    if variant == "cn":
        case["fluid"]["openfoam"]["interface_flux"] = "body_normal"
    if ranks > 1:
        case["fluid"]["openfoam"]["mpi_ranks"] = ranks
    if variant in ("c1", "c2"):
        case["fluid"]["openfoam"].update({"body_indicator": "inside_smoothed",
                                          "body_indicator_depth_cells": 1.0 if variant == "c1" else 2.0})
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "case.yaml"), "w") as f:
        f.write("# written by bench/fluid/bench_fluid.py, variant %s: %s\n" % (variant, LABELS[variant]))
        yaml.safe_dump(case, f, default_flow_style=None, sort_keys=False)


# ---- running and timing -------------------------------------------------------------------------

ITERATIONS = re.compile(r"Solving for (\w+),.*No Iterations (\d+)")


def solver_iterations(log_text):
    """Mean linear-solver iterations per time step, by field (p counts both pressure corrections)."""
    steps = max(1, len(re.findall(r"^PIMPLE: iteration 1$", log_text, re.M)))
    totals = {}
    for field, n in ITERATIONS.findall(log_text):
        totals[field] = totals.get(field, 0) + int(n)
    return {k: v / steps for k, v in totals.items()}


def iterations_per_step(log_text, warmup):
    """[p, U] iterations of each time step after the warm-up (steps start at `PIMPLE: iteration 1`)."""
    blocks = re.split(r"^PIMPLE: iteration 1$", log_text, flags=re.M)[1:]
    rows = []
    for block in blocks:
        its = ITERATIONS.findall(block)
        rows.append([sum(int(n) for f, n in its if f == "p"), sum(int(n) for f, n in its if f.startswith("U"))])
    return rows[warmup:]


def collectives_ms(fluid_log):
    """Rank 0's time in the Lagrangian broadcasts and reductions per step (ms), from the fluid's log
    ("MPI rank 0 of P: Lagrangian data ... X ms a step"); None on one rank."""
    match = re.search(r"MPI rank 0 of \d+: Lagrangian data .*?\) ([0-9.]+) ms a step", fluid_log)
    return float(match.group(1)) if match else None


def run_stock(template, run_dir, warmup, ranks=1, tunables=False):
    shutil.rmtree(run_dir, ignore_errors=True)
    shutil.copytree(template, run_dir)
    command = ["/usr/bin/pimpleFoam", "-case", run_dir]
    if ranks > 1:  # the decomposition our fluid makes (apps/fsi-openfoam-fluid/OpenFoamCase.cpp)
        with open(os.path.join(run_dir, "system", "decomposeParDict"), "w") as f:
            f.write(foam_header("dictionary", "decomposeParDict") +
                    "numberOfSubdomains %d;\nmethod hierarchical;\ncoeffs { n (%d 1 1); order xyz; }\n" % (ranks, ranks))
        with open(os.path.join(run_dir, "log.decomposePar"), "w") as log:
            subprocess.run(["decomposePar", "-force", "-case", run_dir], stdout=log, stderr=subprocess.STDOUT,
                           env=FOAM_ENV, check=True)
        command = ["mpirun", "-np", str(ranks), "--oversubscribe", "-x", "WM_PROJECT_DIR"] + \
                  (["-x", "GLIBC_TUNABLES"] if tunables else []) + \
                  (["--allow-run-as-root"] if os.geteuid() == 0 else []) + command + ["-parallel"]
    stamps, cpu = [], []
    start = time.perf_counter()
    with open(os.path.join(run_dir, "log.pimpleFoam"), "w") as log:
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   env=dict(FOAM_ENV, **ALLOCATOR_TUNABLES) if tunables else FOAM_ENV,
                                   text=True, bufsize=1)
        for line in process.stdout:
            now = time.perf_counter()
            log.write(line)
            if line.startswith("ExecutionTime = "):
                stamps.append(now)
                cpu.append(float(line.split()[2]))
        rc = process.wait()
    total = time.perf_counter() - start
    if rc != 0:
        raise RuntimeError("pimpleFoam failed (rc %d): see %s/log.pimpleFoam" % (rc, run_dir))
    wall = np.diff(stamps)[warmup - 1:] if warmup >= 1 else np.diff([start] + stamps)
    with open(os.path.join(run_dir, "log.pimpleFoam")) as f:
        text = f.read()
    return {"per_step_s": wall.tolist(), "cpu_per_step_s": np.diff(cpu)[warmup - 1:].tolist(),
            "total_wall_s": total, "iterations": solver_iterations(text),
            "step_iterations": iterations_per_step(text, warmup)}


def run_ours(bin_dir, case_dir, run_dir, warmup):
    shutil.rmtree(run_dir, ignore_errors=True)
    start = time.perf_counter()
    with open(os.path.join(os.path.dirname(run_dir), os.path.basename(run_dir) + ".launch.log"), "w") as log:
        rc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "python", "fsi", "fsi_launch.py"), "--bin-dir", bin_dir,
                             "-o", run_dir, case_dir], stdout=log, stderr=subprocess.STDOUT, env=FOAM_ENV).returncode
    total = time.perf_counter() - start
    h5_path = os.path.join(run_dir, "coupling.h5")
    if rc != 0 or not os.path.exists(h5_path):
        raise RuntimeError("coupled run failed (rc %d): see %s" % (rc, run_dir))
    with h5py.File(h5_path, "r") as f:
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)
        timings = {k: np.asarray(f["timings"][k])[warmup:] for k in f["timings"].keys()}
        force = np.asarray(f["total_force_on_fluid_n"])[warmup:] if "total_force_on_fluid_n" in f else None
    if status != "completed":
        raise RuntimeError("coupled run status %r: see %s" % (status, run_dir))
    with open(os.path.join(run_dir, "logs", "fluid.console"), errors="replace") as f:
        text = f.read()
    fluid = timings["fluid_solve_s"] + timings["interpolation_s"]
    return {"collectives_ms": collectives_ms(text),
            "per_step_s": fluid.tolist(), "fluid_solve_s": timings["fluid_solve_s"].tolist(),
            "interpolation_s": timings["interpolation_s"].tolist(),
            "structure_solve_s": timings["structure_solve_s"].tolist(),
            "step_wall_s": timings["step_wall_s"].tolist(), "total_wall_s": total, "iterations": solver_iterations(text),
            "step_iterations": iterations_per_step(text, warmup),
            "total_force_on_fluid_n": force.tolist() if force is not None else []}


def force_chatter(run):
    """The total force the structure spreads into the fluid (coupling.h5 total_force_on_fluid_n), per
    step: its mean magnitude (N), the RMS of its second difference F^{n+1} - 2 F^n + F^{n-1} over that
    mean (a smooth force: ~0; one flipping sign every step: ~4 x its amplitude), and the correlation
    of |second difference| with the step's p iterations."""
    force = np.asarray(run.get("total_force_on_fluid_n", []))
    if force.ndim != 2 or len(force) < 4:
        return None
    mean = float(np.linalg.norm(force, axis=1).mean())
    d2 = force[2:] - 2.0 * force[1:-1] + force[:-2]
    d2_norm = np.linalg.norm(d2, axis=1)
    rms = float(np.sqrt((d2_norm ** 2).mean()))
    p_its = np.asarray([row[0] for row in run["step_iterations"]], dtype=float)
    corr = float("nan")
    if len(p_its) == len(force) and np.std(p_its[1:-1]) > 0 and np.std(d2_norm) > 0:
        corr = float(np.corrcoef(d2_norm, p_its[1:-1])[0, 1])
    return mean, rms / mean if mean > 0 else float("nan"), corr


# ---- report -------------------------------------------------------------------------------------

def ms(x):
    return "%.1f" % (1e3 * x)


def reference(variants):
    """The run the ratios are to: stock with our allocator settings when it was run, else stock."""
    return "stockt" if "stockt" in variants else "stock"


def adjusted_for_solver_work(results, variants):
    """Least squares over every measured step of every run: t = a_variant + b_p N_p + b_U N_U (N: that
    step's linear-solver iterations). a_variant + b . mean(N of stock) is the time the variant would
    take doing stock's linear-solver work: what the immersed boundary costs besides changing the flow
    the solvers see."""
    rows, times = [], []
    for i, v in enumerate(variants):
        for run in results[v]:
            its = run["step_iterations"]
            if len(its) != len(run["per_step_s"]):
                return ["", "(no iteration-adjusted estimate: %s has %d timed steps, %d in its log)"
                        % (v, len(run["per_step_s"]), len(its))]
            for t, (n_p, n_u) in zip(run["per_step_s"], its):
                onehot = [0.0] * len(variants)
                onehot[i] = 1.0
                rows.append(onehot + [n_p, n_u])
                times.append(t)
    coef, *_ = np.linalg.lstsq(np.asarray(rows), np.asarray(times), rcond=None)
    b_p, b_u = coef[-2], coef[-1]
    base = reference(variants)
    ref = np.mean(np.concatenate([np.asarray(r["step_iterations"], float) for r in results[base]]), axis=0)
    at_stock_work = {v: coef[i] + b_p * ref[0] + b_u * ref[1] for i, v in enumerate(variants)}
    lines = ["", "At stock's linear-solver work (fit over all measured steps: t = a_variant + %.1f ms x p iterations "
             "+ %.2f ms x U iterations; stock does %.1f p and %.1f U iterations a step):" % (1e3 * b_p, 1e3 * b_u,
                                                                                        ref[0], ref[1]), "",
             "| variant | p iters/step (measured) | U iters/step | ms/step at stock's iterations | ratio |",
             "|---|---|---|---|---|"]
    for v in variants:
        its = np.mean(np.concatenate([np.asarray(r["step_iterations"], float) for r in results[v]]), axis=0)
        lines.append("| %s | %.1f | %.1f | %s | %.3f |" % (v, its[0], its[1], ms(at_stock_work[v]),
                                                           at_stock_work[v] / at_stock_work[base]))
    return lines


def report(results, variants, args, n_cells, n_triangles, ranks=1):
    rounds = args.rounds
    med = {v: [float(np.median(results[v][r]["per_step_s"])) for r in range(rounds) if r < len(results[v])]
           for v in variants}
    base = reference(variants)
    stock = float(np.median(med[base]))
    lines = ["# `./fsi bench fluid`: time per step of the fluid, side by side with stock pimpleFoam"
             + ("" if ranks == 1 else ", %d MPI ranks" % ranks), "",
             "%s; mesh %d x %d x %d = %d cells (0.4 x 0.1 x 0.1 m channel, blockMesh), dt = %g s, %d warm-up + %d "
             "measured steps per run, %d rounds interleaved (%s). Torus STL: %d triangles."
             % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), args.cells[0], args.cells[1], args.cells[2],
                n_cells, args.dt, args.warmup, args.steps, rounds, ", ".join(variants), n_triangles), "",
             "| variant | median ms/step (per round) | median ms/step | ratio to %s (per round) | goal | holds |" % base,
             "|---|---|---|---|---|---|"]
    for v in variants:
        m = float(np.median(med[v]))
        per_round_ratio = [med[v][r] / med[base][r] for r in range(len(med[v]))]
        ratio = m / stock
        goal = GOALS.get(v)
        lines.append("| %s | %s | %s | %.3f (%s) | %s | %s |" % (
            LABELS[v], ", ".join(ms(x) for x in med[v]), ms(m), ratio, ", ".join("%.3f" % x for x in per_round_ratio),
            "<= %.2f" % goal if goal else "-", ("yes" if ratio <= goal else "NO") if goal else "-"))
    lines += ["", "Breakdown (medians over all measured steps of all rounds, ms/step):", "",
              "| variant | fluid_solve_s | interpolation_s | structure_solve_s (concurrent) | step_wall_s | "
              "stock CPU/step | U iters/step | p iters/step | run wall s |", "|---|---|---|---|---|---|---|---|---|"]
    for v in variants:
        runs = results[v]
        pool = lambda key: ms(np.median(np.concatenate([r[key] for r in runs]))) if key in runs[0] else "-"
        its = runs[0]["iterations"]
        u_its = sum(its.get(k, 0) for k in ("Ux", "Uy", "Uz"))
        lines.append("| %s | %s | %s | %s | %s | %s | %.1f | %.1f | %s |" % (
            v, pool("fluid_solve_s"), pool("interpolation_s"), pool("structure_solve_s"), pool("step_wall_s"),
            pool("cpu_per_step_s"), u_its, its.get("p", 0.0),
            ", ".join("%.0f" % r["total_wall_s"] for r in runs)))
    lines += adjusted_for_solver_work(results, variants)
    chatter = [(v, force_chatter(results[v][0])) for v in variants if v not in ("stock", "stockt")]
    chatter = [(v, c) for v, c in chatter if c is not None and c[0] > 0]
    if chatter:
        lines += ["", "The structure's force on the fluid, per step (round 1; coupling.h5 total_force_on_fluid_n): "
                  "step-to-step chatter of the coupling shows as a large second difference:", "",
                  "| variant | mean \\|F\\| (N) | RMS \\|F^{n+1} - 2F^n + F^{n-1}\\| / mean \\|F\\| | "
                  "correlation with p iterations |", "|---|---|---|---|"]
        lines += ["| %s | %.3g | %.3g | %.2f |" % (v, c[0], c[1], c[2]) for v, c in chatter]
    lines += ["", "stock: wall time between its `ExecutionTime` lines (time-stamped as they arrive); ours: "
              "coupling.h5 /timings/fluid_solve_s + interpolation_s (inside the fluid process, no coupling). "
              "Load average at the end: %s." % " ".join("%.2f" % x for x in os.getloadavg())]
    return lines


def speedup_table(results, variants, rank_counts):
    """Per variant: median time per step on each rank count, the speedup over one rank, and (ours) the
    master's time in the Lagrangian broadcasts and reductions per step."""
    base = rank_counts[0]
    lines = ["", "# Speedup with MPI ranks (each variant against itself on %d rank%s)" % (base, "" if base == 1 else "s"),
             "", "| variant | " + " | ".join("%d rank(s) ms/step" % n for n in rank_counts) + " | " +
             " | ".join("speedup %d" % n for n in rank_counts[1:]) + " | Lagrangian collectives ms/step (rank 0) |",
             "|---|" + "---|" * (2 * len(rank_counts) - 1) + "---|"]
    for v in variants:
        med = {n: float(np.median(np.concatenate([r["per_step_s"] for r in results[n][v]]))) for n in rank_counts}
        coll = [r.get("collectives_ms") for n in rank_counts[1:] for r in results[n][v] if r.get("collectives_ms")]
        lines.append("| %s | %s | %s | %s |" % (
            v, " | ".join(ms(med[n]) for n in rank_counts),
            " | ".join("%.2f" % (med[base] / med[n]) for n in rank_counts[1:]),
            "%.3f" % float(np.median(coll)) if coll else "-"))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin-dir", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("-o", "--output-dir", default=None,
                        help="run folder (default: <bin-dir>/../bench-fluid/<date-time>)")
    parser.add_argument("--cells", type=int, nargs=3, default=[168, 42, 42])
    parser.add_argument("--steps", type=int, default=25, help="measured steps per run")
    parser.add_argument("--warmup", type=int, default=3, help="steps dropped at the start of each run")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--dt", type=float, default=5.0e-4)
    parser.add_argument("--variants", default="stock,stockt,a,b,c,b0,c0")
    parser.add_argument("--ranks", default="1", help="comma-separated MPI rank counts, e.g. 1,2 (each variant on each)")
    args = parser.parse_args()
    variants = args.variants.split(",")
    if any(v not in LABELS for v in variants) or not {"stock", "stockt"} & set(variants):
        parser.error("--variants: a comma-separated subset of %s that includes stock or stockt" % ",".join(LABELS))
    try:
        rank_counts = [int(n) for n in args.ranks.split(",")]
    except ValueError:
        rank_counts = []
    if not rank_counts or min(rank_counts) < 1:
        parser.error("--ranks: comma-separated positive integers, e.g. 1,2 (got %r)" % args.ranks)
    if args.warmup < 1:
        parser.error("--warmup must be >= 1")
    bin_dir = os.path.abspath(args.bin_dir)
    for exe in ("fsi-coupler", "fsi-structure", "fsi-openfoam-fluid"):
        if not os.access(os.path.join(bin_dir, exe), os.X_OK):
            sys.exit("bench_fluid: %s/%s missing (build first: ./fsi build)" % (bin_dir, exe))
    out = os.path.abspath(args.output_dir or os.path.join(
        bin_dir, "..", "bench-fluid", datetime.datetime.now().strftime("%Y%m%d-%H%M%S")))
    os.makedirs(os.path.join(out, "runs"), exist_ok=True)
    n_steps = args.warmup + args.steps
    template = os.path.join(out, "template")
    print("bench_fluid: meshing %s ..." % template, flush=True)
    shutil.rmtree(template, ignore_errors=True)
    write_foam_case(template, args.cells, args.dt, n_steps)
    n_cells = args.cells[0] * args.cells[1] * args.cells[2]
    stl = os.path.join(out, "torus.stl")
    n_triangles = write_torus_stl(stl, (0.2, 0.05, 0.05), 0.025, 0.008, 320, 160)
    tag = lambda v, n: v if n == 1 else "%s-np%d" % (v, n)
    for n in rank_counts:
        for v in variants:
            if v not in ("stock", "stockt"):
                write_our_case(os.path.join(out, "cases", tag(v, n)), v, template, stl, args.dt, n_steps, n)
    results = {n: {v: [] for v in variants} for n in rank_counts}
    # A run of stock first, not counted: the first OpenFOAM run after a pause (or after other
    # processes freed their memory) was up to 2x slower on this kind of machine (fresh pages).
    # Each round then starts one place further along the order, so no variant always comes first.
    run_stock(template, os.path.join(out, "runs", "warm-up"), args.warmup, tunables="stockt" in variants)
    order = [(n, v) for n in rank_counts for v in variants]
    for r in range(args.rounds):
        shift = r % len(order)
        for n, v in order[shift:] + order[:shift]:
            run_dir = os.path.join(out, "runs", "%s-r%d" % (tag(v, n), r + 1))
            t0 = time.time()
            if v in ("stock", "stockt"):
                res = run_stock(template, run_dir, args.warmup, n, tunables=v == "stockt")
            else:
                res = run_ours(bin_dir, os.path.join(out, "cases", tag(v, n)), run_dir, args.warmup)
            results[n][v].append(res)
            print("bench_fluid: round %d %-9s median %7s ms/step (run %.0f s)"
                  % (r + 1, tag(v, n), ms(np.median(res["per_step_s"])), time.time() - t0), flush=True)
    lines = []
    for n in rank_counts:
        lines += report(results[n], variants, args, n_cells, n_triangles, n) + [""]
    if len(rank_counts) > 1:
        lines += speedup_table(results, variants, rank_counts)
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write(text)
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump({str(n): results[n] for n in rank_counts}, f, indent=1)
    print(text)
    print("bench_fluid: results in %s/results.md" % out)


if __name__ == "__main__":
    main()
