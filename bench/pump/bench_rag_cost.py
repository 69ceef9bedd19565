#!/usr/bin/python3
"""bench_rag_cost.py: what the rag costs the pump run (issue 13, "Speed"; run by `./fsi bench
pump_rag`): the coupled rag run of cases/rag-in-pump (coupler, structure, OpenFOAM fluid) against
the clean pump (the same case with no structure: the fluid alone), the same mesh, time step and
initial fields (one precursor of the flow alone, made first and shared), interleaved in one run:

    bench_rag_cost.py --bin-dir BIN [--resolution coarse] [--time 0.1] [--rounds 2] [-o DIR]

Each round runs clean then rag, or rag then clean (alternating), for --time seconds of flow from
the release (0.1 s: the rag rises from the sump into the eye). The figure is the wall time per
step of the step loop (the coupler's progress line for the rag run, the fluid's for the clean
one), the median over rounds, and the ratio rag / clean. Goal (issue 13): at most 1.10.
Output: DIR/results.md, DIR/results.yaml, the runs in DIR/runs/.
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys

import yaml

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import fsi_launch  # noqa: E402

CASE = os.path.join(ROOT, "cases", "rag-in-pump")
COUPLED = re.compile(r"step (\d+)/(\d+)\s.*\s([0-9.]+) ms/step: fluid ([0-9.]+)")
ALONE = re.compile(r"flow: t = [0-9.eE+-]+ of [0-9.eE+-]+ s, step (\d+)/(\d+), ([0-9.]+) ms/step")


def launch(bin_dir, case, out, end_time, resolution):
    command = [sys.executable, os.path.join(ROOT, "scripts", "fsi_launch.py"), "--bin-dir", bin_dir, "-o", out,
               "--end-time", repr(end_time)] + (["--resolution", resolution] if resolution else []) + [case]
    made = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if made.returncode != 0:
        sys.exit("bench_rag_cost: %s failed:\n%s" % (" ".join(command), made.stdout.decode(errors="replace")[-3000:]))


def last_match(path, pattern):
    found = None
    with open(path) as f:
        for line in f:
            m = pattern.search(line)
            if m:
                found = m
    if not found:
        sys.exit("bench_rag_cost: no progress line in %s" % path)
    return found


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
    parser.add_argument("--rounds", type=int, default=2)
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
    fluid_share = []
    for r in range(args.rounds):
        for name in (("clean", "rag") if r % 2 == 0 else ("rag", "clean")):
            run = os.path.join(out, "runs", "%s-%d" % (name, r))
            shutil.rmtree(run, ignore_errors=True)
            launch(args.bin_dir, cases[name], run, args.time, args.resolution)
            if name == "rag":
                m = last_match(os.path.join(run, "coupler.log"), COUPLED)
                fluid_share.append(float(m.group(4)))
            else:
                m = last_match(os.path.join(run, "fluid.log"), ALONE)
            per_step[name].append(float(m.group(3)))
            print("round %d %s: %.1f ms/step" % (r + 1, name, per_step[name][-1]), flush=True)
    clean, rag = statistics.median(per_step["clean"]), statistics.median(per_step["rag"])
    result = {"resolution": args.resolution, "time_s": args.time, "rounds": args.rounds,
              "clean_ms_per_step": per_step["clean"], "rag_ms_per_step": per_step["rag"],
              "rag_fluid_ms_per_step": fluid_share, "ratio_rag_over_clean": rag / clean, "goal": 1.10}
    with open(os.path.join(out, "results.yaml"), "w") as f:
        yaml.safe_dump(result, f, sort_keys=False)
    table = ("| run (%s, %.3g s from the release) | ms/step (rounds) | median |\n|---|---|---|\n"
             "| clean pump (the fluid alone) | %s | %.1f |\n| rag (coupler, structure, fluid) | %s | %.1f |\n\n"
             "Ratio rag / clean: **%.3f** (goal at most 1.10). The rag run's fluid alone: %s ms/step.\n"
             % (args.resolution, args.time, ", ".join("%.1f" % v for v in per_step["clean"]), clean,
                ", ".join("%.1f" % v for v in per_step["rag"]), rag, rag / clean,
                ", ".join("%.1f" % v for v in fluid_share)))
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write(table)
    print(table)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
