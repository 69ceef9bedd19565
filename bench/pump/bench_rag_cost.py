#!/usr/bin/python3
"""bench_rag_cost.py: what the rag costs the pump run (issue 13, "Speed"; run by `./fsi bench
pump_rag`): the coupled rag run of cases/rag-in-pump (coupler, structure, OpenFOAM fluid) against
the clean pump (the same case with no structure: the fluid alone), the same mesh, time step and
initial fields (one precursor of the flow alone, made first and shared), interleaved in one run:

    bench_rag_cost.py --bin-dir BIN [--resolution coarse] [--time 0.1] [--rounds 2] [-o DIR]

Each round runs clean then rag, or rag then clean (alternating), for --time seconds of flow from
the release (0.1 s: the rag rises from the sump into the eye). The figures, per run, from the
per-step series the runs write (the rag's coupling.h5 timings, the clean fluid's timings.csv):
the median wall time of a step (a median, not a mean: a burst of another process on this shared
machine moves a mean by tens of percent), the ratio rag / clean of each round and their median.
Goal (issue 13): at most 1.10. Two figures that no neighbour can move, because they compare
within one run: the rag run's own split (the fluid's part of its step against the coupling's:
interpolation, structure solve, messages) and the pressure solver's iterations of both runs
(the same work, or the rag has changed the flow's cost). Output: DIR/results.md,
DIR/results.yaml, the runs in DIR/runs/.
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys

import h5py
import numpy
import yaml

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from fsi import fsi_launch  # noqa: E402

CASE = os.path.join(ROOT, "cases", "rag-in-pump")
ITERATIONS = re.compile(r"Solving for (\w+), Initial residual = \S+, Final residual = \S+, No Iterations (\d+)")


def launch(bin_dir, case, out, end_time, resolution):
    command = [sys.executable, os.path.join(ROOT, "python", "fsi", "fsi_launch.py"), "--bin-dir", bin_dir, "-o", out,
               "--end-time", repr(end_time)] + (["--resolution", resolution] if resolution else []) + [case]
    made = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if made.returncode != 0:
        sys.exit("bench_rag_cost: %s failed:\n%s" % (" ".join(command), made.stdout.decode(errors="replace")[-3000:]))


def rag_steps(run):
    """Per step of the rag run (s): the step's wall time and the coupling's part of it (the
    interpolation, the structure's solve and the coupler's own work: all but the fluid's solve)."""
    with h5py.File(os.path.join(run, "coupling.h5"), "r") as f:
        t = f["timings"]
        wall = numpy.asarray(t["step_wall_s"])
        coupling = numpy.asarray(t["interpolation_s"]) + numpy.asarray(t["structure_solve_s"]) + \
            numpy.asarray(t["overhead_s"])
    return wall, coupling


def clean_steps(run):
    """Per step of the clean run (s): the fluid's penalization, solve and loads (timings.csv)."""
    data = numpy.genfromtxt(os.path.join(run, "timings.csv"), delimiter=",", names=True)
    return data["penalization_s"] + data["fluid_solve_s"] + data["loads_s"]


def solver_iterations(run):
    """The OpenFOAM linear solvers' iterations over the run, per field."""
    counts = {}
    with open(os.path.join(run, "logs", "fluid.console"), errors="replace") as f:
        for m in ITERATIONS.finditer(f.read()):
            counts[m.group(1)] = counts.get(m.group(1), 0) + int(m.group(2))
    if not counts:
        sys.exit("bench_rag_cost: no solver iterations in %s/logs/fluid.console" % run)
    return counts


def variant_case(out, name, precursor_fields, clean):
    """A copy of the case starting from the shared precursor's fields, without a precursor of its
    own; `clean`: without the rag (the flow alone)."""
    case = os.path.join(out, "cases", name)
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(CASE, case, symlinks=True, ignore=shutil.ignore_patterns("output", "__pycache__"))
    with open(os.path.join(case, "case.yaml")) as f:
        config = yaml.safe_load(f)
    foam = config["fluid"]["openfoam"]
    foam.pop("precursor_time_s", None)
    foam["initial_fields_from"] = precursor_fields
    if clean:
        config["structures"] = []
        config.pop("probes", None)
        config.pop("coupling", None)
    with open(os.path.join(case, "case.yaml"), "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)
    return case


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--resolution", default="coarse")
    parser.add_argument("--time", type=float, default=0.1, help="seconds of flow per run (default 0.1)")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("-o", "--output", default=os.path.join(ROOT, "build", "bench", "pump_rag"))
    args = parser.parse_args(argv)
    out = os.path.abspath(args.output)
    os.makedirs(out, exist_ok=True)
    fsi_launch.prepare_case(CASE, args.bin_dir)
    # The shared initial fields: the case's precursor (reused when it is up to date), by a run of
    # one output interval.
    seed = os.path.join(out, "runs", "precursor")
    launch(args.bin_dir, CASE, seed, 0.0025, args.resolution)
    fields = os.path.join(seed, "precursor", "openfoam")
    cases = {"clean": variant_case(out, "clean", fields, True), "rag": variant_case(out, "rag", fields, False)}
    per_step = {"clean": [], "rag": []}
    coupling_share, iterations = [], {"clean": [], "rag": []}
    for r in range(args.rounds):
        for name in (("clean", "rag") if r % 2 == 0 else ("rag", "clean")):
            run = os.path.join(out, "runs", "%s-%d" % (name, r))
            shutil.rmtree(run, ignore_errors=True)
            launch(args.bin_dir, cases[name], run, args.time, args.resolution)
            if name == "rag":
                wall, coupling = rag_steps(run)
                coupling_share.append(float(numpy.median(coupling / wall)))
            else:
                wall = clean_steps(run)
            per_step[name].append(1e3 * float(numpy.median(wall)))
            iterations[name].append(solver_iterations(run))
            print("round %d %s: median %.1f ms/step" % (r + 1, name, per_step[name][-1]), flush=True)
    ratios = [g / c for g, c in zip(per_step["rag"], per_step["clean"])]
    ratio = statistics.median(ratios)
    p_clean = [i.get("p", 0) for i in iterations["clean"]]
    p_rag = [i.get("p", 0) for i in iterations["rag"]]
    result = {"resolution": args.resolution, "time_s": args.time, "rounds": args.rounds,
              "clean_median_ms_per_step": per_step["clean"], "rag_median_ms_per_step": per_step["rag"],
              "ratio_per_round": ratios, "ratio_rag_over_clean": ratio, "goal": 1.10,
              "rag_coupling_share_of_step": coupling_share,
              "pressure_iterations": {"clean": p_clean, "rag": p_rag}}
    with open(os.path.join(out, "results.yaml"), "w") as f:
        yaml.safe_dump(result, f, sort_keys=False)
    table = ("| run (%s, %.3g s from the release, %d rounds) | median ms/step per round |\n|---|---|\n"
             "| clean pump (the fluid alone) | %s |\n| rag (coupler, structure, fluid) | %s |\n"
             "| ratio rag / clean | %s |\n\n"
             "Ratio rag / clean, median of the rounds: **%.3f** (goal at most 1.10).\n"
             "Within the rag run (no neighbour moves it): the coupling (interpolation, structure, messages) is "
             "%s of a step. Pressure-solver iterations over the run: clean %s, rag %s.\n"
             % (args.resolution, args.time, args.rounds, ", ".join("%.1f" % v for v in per_step["clean"]),
                ", ".join("%.1f" % v for v in per_step["rag"]), ", ".join("%.3f" % v for v in ratios), ratio,
                ", ".join("%.1f %%" % (100 * v) for v in coupling_share), ", ".join(map(str, p_clean)),
                ", ".join(map(str, p_rag))))
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write(table)
    print(table)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
