#!/usr/bin/python3
"""bench_pump.py: the cost of a revolution of the centrifugal pump (issue 11, "Speed"; run by
`./fsi bench pump`), the penalized impeller (ours) side by side with the same geometry meshed
body-fitted with the impeller in a rotating zone and an AMI to the casing (stock pimpleFoam,
python/fsi/pump_ami_run.py), at the same cell size and time step, interleaved in one run:

    bench_pump.py --bin-dir BIN [--resolution coarse] [--ours-resolution coarse-turning-mesh] [--ranks 1]
                  [--revolutions 1] [--rounds 1] [-o DIR]

Both start from water at rest at the design flow rate (pump.yaml) and run `--revolutions` on
--ranks MPI ranks each (default 1: the machine's other core idle), one after the other. Ours runs
by default on the AMI reference's own mesh with the impeller's cells kept and turning with it
behind the same AMI (preset <resolution>-turning-mesh, `./fsi pump-compare`'s default: the same
background, gap cells and refinement; the impeller's cells added); <resolution>-ami-mesh holds
that mesh still and turns the impeller through it. What the numbers contain:
  ours  timings.csv of fsi-openfoam-fluid (per step, wall): penalization = chi and u_rib of the
        rotated impeller (Eq. 10) and the immersed wall distance; fluid solve = the PIMPLE step
        with turbulence, writing and the function objects; loads = the penalization force and the
        impeller's force and torque; rest = the step loop's wall time (from the progress line)
        minus those (forces.csv, timings.csv, the loop).
  AMI   pimpleFoam's wall time per step (ExecutionTime differences); mesh motion + AMI =
        moveDynamicMesh alone on the same mesh (the rotation and the AMI's addressing and
        weights), measured separately; solve = the rest.
Output: DIR/results.md (the table), DIR/results.yaml, the runs in DIR/runs/.
"""

import argparse
import math
import os
import re
import subprocess
import sys
import time

import numpy as np
import yaml

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from fsi import fsi_launch  # noqa: E402
from fsi import pump_ami_run  # noqa: E402

CASE = os.path.join(ROOT, "cases", "centrifugal-pump")
CELLS = re.compile(r"PIMPLE, (\d+) cells")  # the fluid's description (the mesh may come from the cache)
LOOP = re.compile(r"flow: t = [0-9.eE+-]+ of [0-9.eE+-]+ s, step (\d+)/(\d+), ([0-9.]+) ms/step")


def ours(bin_dir, resolution, end_time, out, ranks):
    command = [sys.executable, os.path.join(ROOT, "python", "fsi", "fsi_launch.py"), "--bin-dir", bin_dir, "-o", out,
               "--end-time", repr(end_time), "--resolution", resolution, "--set",
               "fluid.openfoam.mpi_ranks=%d" % ranks, CASE]
    start = time.monotonic()
    subprocess.run(command, check=True, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.monotonic() - start
    steps, per_step_ms, cells = 0, 0.0, 0
    with open(os.path.join(out, "fluid.log")) as f:
        for line in f:
            m = LOOP.search(line)
            if m:
                steps, per_step_ms = int(m.group(1)), float(m.group(3))
            m = CELLS.search(line)
            if m:
                cells = int(m.group(1))
    t = np.loadtxt(os.path.join(out, "timings.csv"), delimiter=",", skiprows=1, ndmin=2)
    loop = steps * per_step_ms * 1e-3
    parts = {"penalization": t[:, 1].sum(), "fluid solve": t[:, 2].sum(), "loads": t[:, 3].sum()}
    parts["rest"] = loop - sum(parts.values())
    return {"cells": cells, "steps": steps, "loop_s": loop, "process_wall_s": wall, "parts_s": parts}


def ami(resolution, end_time, flow_rate, out, ranks):
    pump_ami_run.run_ami_point(CASE, flow_rate, out, end_time, resolution, ranks=ranks)
    with open(os.path.join(out, "cost.yaml")) as f:
        cost = yaml.safe_load(f)
    steps = cost["steps"]
    loop = cost["pimpleFoam_wall_s"]
    motion = cost.get("mesh_motion_and_ami_s_per_step", float("nan")) * steps
    return {"cells": cost["cells"], "steps": steps, "loop_s": loop, "process_wall_s": loop,
            "parts_s": {"mesh motion + AMI": motion, "fluid solve": loop - motion}}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--resolution", default="coarse", help="the AMI reference's mesh (coarse, medium)")
    parser.add_argument("--ours-resolution", default="",
                        help="our preset (default: <resolution>-turning-mesh, the AMI reference's own mesh "
                             "turning with the impeller)")
    parser.add_argument("--ranks", type=int, default=1, help="MPI ranks of each run")
    parser.add_argument("--revolutions", type=float, default=1.0)
    parser.add_argument("--rounds", type=int, default=1)
    parser.add_argument("-o", "--output", default=os.path.join(ROOT, "build", "bench-pump"))
    args = parser.parse_args(argv)
    ours_preset = args.ours_resolution or args.resolution + "-turning-mesh"
    if not os.path.isfile(os.path.join(CASE, "presets", ours_preset + ".yaml")):
        have = sorted(p[:-5] for p in os.listdir(os.path.join(CASE, "presets")) if p.endswith(".yaml"))
        raise SystemExit("bench pump: our preset %s does not exist in %s/presets (it has %s): give "
                         "--ours-resolution" % (ours_preset, CASE, ", ".join(have)))
    fsi_launch.prepare_case(CASE, args.bin_dir)  # the geometry, from pump.yaml (both runs use it)
    with open(os.path.join(CASE, "pump.yaml")) as f:
        design = yaml.safe_load(f)
    omega = design["operation"]["rotation_rate_rad_per_s"]
    q = design["operation"]["design_flow_rate_m3_per_s"]
    period = 2 * math.pi / omega
    end_time = args.revolutions * period
    rows = {"ours": [], "AMI": []}
    for r in range(args.rounds):
        for name in ("ours", "AMI"):
            out = os.path.join(args.output, "runs", "%s-%s-r%d" % (name.lower(), args.resolution, r))
            sys.stderr.write("bench pump: %s, round %d, %g revolutions (%s)\n" % (name, r + 1, args.revolutions, out))
            rows[name].append(ours(args.bin_dir, ours_preset, end_time, out, args.ranks)
                              if name == "ours"
                              else ami(args.resolution, end_time, q, out, args.ranks))
    lines = ["# Cost per revolution of the centrifugal pump, %s, %d rank%s each (%s)" % (
                 args.resolution, args.ranks, "s" if args.ranks > 1 else "", time.strftime("%Y-%m-%d %H:%M")),
             "", "| run | cells | steps per revolution | wall s per revolution | split (s per revolution) |",
             "|---|---|---|---|---|"]
    summary = {}
    for name, runs in rows.items():
        per_rev = np.mean([run["loop_s"] / args.revolutions for run in runs])
        split = {k: np.mean([run["parts_s"][k] for run in runs]) / args.revolutions for k in runs[0]["parts_s"]}
        summary[name] = {"cells": runs[0]["cells"], "wall_s_per_revolution": float(per_rev),
                         "split_s_per_revolution": {k: float(v) for k, v in split.items()}}
        lines.append("| %s | %d | %.0f | %.1f | %s |" % (name, runs[0]["cells"], runs[0]["steps"] / args.revolutions,
                                                      per_rev, ", ".join("%s %.1f" % kv for kv in split.items())))
    ratio = summary["ours"]["wall_s_per_revolution"] / summary["AMI"]["wall_s_per_revolution"]
    lines += ["", "ours / AMI = %.2f per revolution (goal: <= 1 at the same cells and time step)" % ratio]
    summary["ours_over_ami"] = ratio
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "results.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(args.output, "results.yaml"), "w") as f:
        yaml.safe_dump(summary, f, sort_keys=False)
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
