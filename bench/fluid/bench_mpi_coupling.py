#!/usr/bin/python3
"""bench_mpi_coupling.py: what the Lagrangian side of a coupled step costs the OpenFOAM fluid on 1 and
2 MPI ranks, against the number of structure points (issue 12, "the fluid on more than one core"; run by
`./fsi bench mpi_coupling`).

    bench_mpi_coupling.py [--bin-dir DIR] [-o DIR] [--points 9,50,100,200] [--steps N] [--rounds R]

The case is cases/sheet-in-openfoam-channel (32 x 16 x 16 cells, cut by decomposePar at x = 0.1 m)
with one sheet of n x n points (9 cm square) placed across the cut, so that both ranks hold part of
every kernel (the worst case for the reductions), with the case's coupling (K = 3.2e4: with K ~ 0 the
water stays uniform and OpenFOAM's normalised U residual, of a field with nothing to solve, never
reaches its tolerance: 1000 smoother sweeps a step) and a softer tension (1 N/m, for the finer sheets). Per run, medians over the steps after the first 3:
  interpolation_s  the fluid's answer to an interpolation request (kernel widths: nearest cell per
                   point and three reductions; KernelStencil; weight sums and their reduction;
                   interpolation and its reduction), coupling.h5 /timings
  collectives      rank 0's wall time in the broadcasts and reductions of the Lagrangian data (its
                   log line "MPI rank 0 of 2: Lagrangian data ..."), per step
  step_wall_s      the coupler's step (everything)
A least-squares line t = a + b n_points per quantity and rank count is printed with the table: the
per-point constants of the cost model in docs/cluster.md.
Python standard library + numpy + h5py + yaml (Debian's python3-* packages).
"""

import argparse
import datetime
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np
import yaml

from bench_fluid import FOAM_ENV, ROOT, collectives_ms  # the same fluid log and environment
WARMUP = 3


def write_case(folder, n_side, ranks, steps):
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "cases", "sheet-in-openfoam-channel"), folder,
                    ignore=shutil.ignore_patterns("output"))
    path = os.path.join(folder, "case.yaml")
    with open(path) as f:
        config = yaml.safe_load(f)
    dt = config["run"]["time_step_s"]
    config["run"].update({"end_time_s": steps * dt, "output_interval_s": steps * dt, "progress_interval_s": 1000.0})
    sheet = config["structures"][0]
    sheet.update({"size_m": [0.09, 0.09], "n_points": [n_side, n_side], "origin_m": [0.1, 0.005, 0.005]})
    sheet["material"]["coefficients"]["tension_coefficient_n_per_m"] = 1.0
    config["fluid"]["openfoam"]["mpi_ranks"] = ranks
    with open(path, "w") as f:
        yaml.safe_dump(config, f, default_flow_style=None, sort_keys=False)


def run(bin_dir, case, out):
    shutil.rmtree(out, ignore_errors=True)
    result = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "python", "fsi", "fsi_launch.py"), "--bin-dir", bin_dir,
                             "-o", out, case], stdin=subprocess.DEVNULL, capture_output=True, text=True, env=FOAM_ENV)
    if result.returncode != 0:
        raise RuntimeError("run %s failed (exit %d): %s" % (case, result.returncode, result.stderr[-2000:]))
    with h5py.File(os.path.join(out, "coupling.h5"), "r") as f:
        timings = {k: float(np.median(np.asarray(f["timings"][k])[WARMUP:])) for k in f["timings"].keys()}
    with open(os.path.join(out, "logs", "fluid.console"), errors="replace") as f:
        collectives = collectives_ms(f.read())
    timings["collectives_s"] = collectives / 1e3 if collectives is not None else 0.0
    return timings


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin-dir", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("-o", "--output-dir", default=None)
    parser.add_argument("--points", default="9,50,100,200", help="sheet sides n (n x n points)")
    parser.add_argument("--steps", type=int, default=23)
    parser.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    sides = [int(n) for n in args.points.split(",")]
    if min(sides) < 3:
        parser.error("--points: sides of at least 3")
    bin_dir = os.path.abspath(args.bin_dir)
    out = os.path.abspath(args.output_dir or os.path.join(
        bin_dir, "..", "bench-mpi-coupling", datetime.datetime.now().strftime("%Y%m%d-%H%M%S")))
    keys = ("interpolation_s", "collectives_s", "fluid_solve_s", "structure_solve_s", "step_wall_s")
    samples = {}
    for r in range(args.rounds):
        for n in sides:
            for ranks in (1, 2):
                case = os.path.join(out, "cases", "n%d-np%d" % (n, ranks))
                write_case(case, n, ranks, args.steps + WARMUP)
                t = run(bin_dir, case, os.path.join(out, "runs", "n%d-np%d-r%d" % (n, ranks, r + 1)))
                samples.setdefault((n, ranks), []).append(t)
                print("bench_mpi_coupling: round %d, %d points, %d rank(s): interpolation %.3f ms, collectives "
                      "%.3f ms, step %.2f ms" % (r + 1, n * n, ranks, 1e3 * t["interpolation_s"],
                                                 1e3 * t["collectives_s"], 1e3 * t["step_wall_s"]), flush=True)
    med = {key: {k: float(np.median([s[k] for s in v])) for k in keys} for key, v in samples.items()}
    lines = ["# `./fsi bench mpi_coupling`: the Lagrangian side of a step on 1 and 2 MPI ranks", "",
             "%s; cases/sheet-in-openfoam-channel (8,192 cells), a sheet across the ranks' cut, %d + %d steps a "
             "run, %d rounds; medians, ms a step." % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), WARMUP,
                                                      args.steps, args.rounds), "",
             "| points | ranks | interpolation | collectives (rank 0) | fluid solve | structure | step |",
             "|---|---|---|---|---|---|---|"]
    for n in sides:
        for ranks in (1, 2):
            m = med[(n, ranks)]
            lines.append("| %d | %d | %s |" % (n * n, ranks, " | ".join("%.3f" % (1e3 * m[k]) for k in keys)))
    lines += ["", "Least-squares lines t = a + b x points (a in ms, b in us a point):", "",
              "| quantity | ranks | a (ms) | b (us a point) |", "|---|---|---|---|"]
    points = np.array([n * n for n in sides], dtype=float)
    for k in ("interpolation_s", "collectives_s", "step_wall_s"):
        for ranks in (1, 2):
            if k == "collectives_s" and ranks == 1:
                continue
            y = np.array([med[(n, ranks)][k] for n in sides])
            b, a = np.polyfit(points, y, 1)
            lines.append("| %s | %d | %.3f | %.3f |" % (k, ranks, 1e3 * a, 1e6 * b))
    text = "\n".join(lines) + "\n"
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write(text)
    print(text)
    print("bench_mpi_coupling: results in %s/results.md" % out)


if __name__ == "__main__":
    try:
        main()
    except RuntimeError as e:
        sys.exit("bench_mpi_coupling: %s" % e)
