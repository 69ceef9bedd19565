#!/usr/bin/python3
"""./fsi rag-ensemble: many independent releases of a rag into a pump case (cases/rag-in-pump) at
one operating point, and the answer a designer needs, a probability: P(hang-up) with its
confidence interval, the distribution of residence time and wrap fraction, and the trap sites
summed over the runs (ensemble.csv, ensemble.yaml, ensemble.png).

    rag_ensemble.py --bin-dir BIN [--runs 8] [--seed 1] [--flow-fraction 1.0] [--sizes 0.15x0.05,0.1x0.1]
                    [--jobs N] [--resolution NAME] [--end-time S] [-o DIR] CASE_DIR

Each member is a copy of the case folder (DIR/run-NN/case) run by fsi_launch.py into DIR/run-NN.
run-00 is the case's own rag and release (without --sizes); every other member's rag is released at a random place
of the sump's floor, turned by a random angle about the vertical, with one of the sizes (in
turn); the seed makes the draw reproducible. The flow rate is --flow-fraction times the case's
(fluid.openfoam.operating_point: Q_BEP), given to every member as --set, so 0.36 is the paper's
part load. The precursor of the flow alone is the same for every member of one operating point:
the first member runs it, the others start from a copy of it. Members run in parallel up to
--jobs (default: half the cores, a coupled run keeps about two busy); a member already run with
the same case files and options is reused. Progress with ETA on stderr; a failed member is
reported and the ensemble summarised over the others.
"""

import argparse
import concurrent.futures
import copy
import csv
import math
import os
import random
import re
import shutil
import subprocess
import sys
import threading
import time

import yaml

from fsi import fsi_launch  # noqa: E402
from fsi import pump_curve  # noqa: E402

# The coupler's progress line: "step 1674/2000  t = 0.4185 s (84%)  wall 9m34s  ETA 112.0 s ..."
# (the precursor counts as nothing: it is a few minutes, once per operating point).
PROGRESS = re.compile(r"\bstep (\d+)/(\d+)\s.*\bETA (\S+(?: s)?)")


say = fsi_launch.speaker("rag-ensemble")


def wilson_interval(k, n, z=1.96):
    """The Wilson score interval of a proportion k / n at 95 % (z = 1.96): honest for few runs
    and for 0 or n successes, where the normal approximation collapses to a point."""
    if n == 0:
        return float("nan"), float("nan")
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def parse_sizes(text):
    sizes = []
    for item in text.split(","):
        try:
            a, b = (float(v) for v in item.lower().split("x"))
        except ValueError:
            raise SystemExit("rag-ensemble: --sizes %s: expected LENGTHxWIDTH in m, comma-separated, e.g. "
                             "0.15x0.05,0.1x0.1" % text)
        if a <= 0 or b <= 0:
            raise SystemExit("rag-ensemble: --sizes %s: sizes must be > 0" % text)
        sizes.append((a, b))
    return sizes


def draw_release(rng, size, rag, design, collision_m):
    """A rag standing upright (its first grid direction vertical) on the sump's floor: its lower
    edge 1 cm above the floor, its centre at a uniformly random point of the disc that keeps
    every point 2 collision distances inside the sump's wall, and inside the suction pipe's wall
    too when the rag reaches up into the pipe, its plane turned by a uniform angle about the
    vertical."""
    inlet = design["inlet"]
    radius = 0.5 * float(inlet["sump_diameter_m"])
    b2, b3 = design["impeller"]["outlet_width_m"], design["volute"]["base_width_m"]
    floor = 0.5 * (b2 - b3) - float(inlet["suction_pipe_length_m"]) - float(inlet["sump_height_m"])
    length, width = size
    lift = 0.01  # the rag's lower edge above the floor
    room = radius - 0.5 * width - 2.0 * collision_m
    into_pipe = lift + length > float(inlet["sump_height_m"]) - 2.0 * collision_m
    if into_pipe:  # its top stands in the suction pipe (the case's long rag: by 1 cm)
        pipe = 0.5 * float(inlet.get("suction_pipe_diameter_m", 0.1))
        room = min(room, pipe - 0.5 * width - 2.0 * collision_m)
    if room <= 0:
        raise SystemExit("rag-ensemble: a rag %g m wide does not fit the %s (diameter %g m)"
                         % (width, "suction pipe it reaches into" if into_pipe else "sump",
                            2 * (pipe if into_pipe else radius)))
    r, phi, turn = room * math.sqrt(rng.random()), 2 * math.pi * rng.random(), math.pi * rng.random()
    across = [math.cos(turn), math.sin(turn), 0.0]
    centre = [r * math.cos(phi), r * math.sin(phi)]
    rag = copy.deepcopy(rag)
    spacing = float(rag["size_m"][0]) / (int(rag["n_points"][0]) - 1)
    rag["size_m"] = [length, width]
    rag["n_points"] = [max(2, int(round(length / spacing)) + 1), max(2, int(round(width / spacing)) + 1)]
    rag["s1_direction"] = [0, 0, 1]
    rag["s2_direction"] = across
    rag["origin_m"] = [centre[0] - 0.5 * width * across[0], centre[1] - 0.5 * width * across[1], floor + lift]
    return rag, {"centre_x_m": centre[0], "centre_y_m": centre[1], "turn_deg": math.degrees(turn),
                 "length_m": length, "width_m": width}


class Member:
    def __init__(self, index, out, flow_rate):
        self.index = index
        self.name = "run-%02d" % index
        self.folder = os.path.join(out, self.name)
        self.case = os.path.join(self.folder, "case")
        self.flow_rate = flow_rate
        self.release = {}
        self.state = "waiting"
        self.progress, self.eta = 0.0, ""
        self.metrics = None
        self.error = None


def prepare_member(args, member, rag):
    pump_curve.copy_case(args.case_dir, member)
    case_file = os.path.join(member.case, "case.yaml")
    with open(case_file) as f:
        case = yaml.safe_load(f)
    case["structures"] = [rag]
    with open(case_file, "w") as f:
        f.write("# Written by ./fsi rag-ensemble: member %s of %s (release %s).\n"
                % (member.name, args.case_dir, member.release))
        yaml.safe_dump(case, f, sort_keys=False)


def seed_precursor(source, member):
    """The precursor of the first member, copied (hard links) into this member's output: the
    launcher reuses it when its fingerprint matches, which it does for one operating point."""
    target = os.path.join(member.folder, "precursor")
    if os.path.isdir(source) and not os.path.exists(target):
        os.makedirs(member.folder, exist_ok=True)
        shutil.copytree(source, target, copy_function=os.link)


def run_member(args, member):
    stamp_file = os.path.join(member.folder, "run.complete")
    stamp = "%s q=%r release=%r resolution=%s end=%r\n" % (args.fingerprint, member.flow_rate, member.release,
                                                            args.resolution, args.end_time)
    if not (os.path.exists(stamp_file) and open(stamp_file).read() == stamp):
        if os.path.exists(stamp_file):
            os.remove(stamp_file)
        member.state, started = "running", time.monotonic()

        def on_line(line):
            match = PROGRESS.search(line)
            if match:
                member.progress = int(match.group(1)) / int(match.group(2))
                member.eta = match.group(3)

        code = pump_curve.run_logged(pump_curve.launcher_command(args, member.folder, member.case, member.flow_rate),
                                     os.path.join(member.folder, "rag_ensemble.log"), on_line)
        if code != 0:
            member.state = "failed"
            member.error = "exit code %d (log: %s)" % (code, os.path.join(member.folder, "rag_ensemble.log"))
            return
        with open(stamp_file, "w") as f:
            f.write(stamp)
        say("%s: ran in %.0f s" % (member.name, time.monotonic() - started))
    else:
        say("%s: up to date (same case, release and run): reused" % member.name)
    # The source case's postprocess.py (the metrics and the pictures, no animation), as pump-curve does.
    made = subprocess.run([sys.executable, os.path.join(args.case_dir, "postprocess.py"), member.folder, member.case,
                           "--no-animation"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          env=fsi_launch.case_script_env())
    metrics_file = os.path.join(member.folder, "rag_metrics.yaml")
    if made.returncode != 0 or not os.path.isfile(metrics_file):
        lines = made.stdout.decode(errors="replace").strip().splitlines() or ["(no output)"]
        member.state, member.error = "failed", "postprocess: %s" % lines[-1]
        return
    with open(metrics_file) as f:
        member.metrics = yaml.safe_load(f)
    member.state = "done"


def flat(metrics, prefix=""):
    """A nested metrics dict as one level of 'a.b' keys (numbers and text only)."""
    out = {}
    for key, value in (metrics or {}).items():
        if isinstance(value, dict):
            out.update(flat(value, prefix + key + "."))
        elif isinstance(value, (int, float, str)) or value is None:
            out[prefix + key] = value
    return out


def summarise(members, fraction):
    done = [m for m in members if m.metrics]
    outcomes = [flat(m.metrics).get("outcome") for m in done]
    n, hung = len(done), sum(o == "hung_up" for o in outcomes)
    decided = sum(o in ("hung_up", "passed", "passed_late") for o in outcomes)
    lo, hi = wilson_interval(hung, decided)
    return {"flow_fraction_of_case": fraction, "runs": len(members), "runs_with_metrics": n,
            "runs_decided": decided, "hung_up": hung, "passed": sum(o == "passed" for o in outcomes),
            "passed_late": sum(o == "passed_late" for o in outcomes),
            "still_running_at_end": sum(o == "running" for o in outcomes),
            "failed": sum(m.state == "failed" for m in members),
            "p_hang_up": hung / decided if decided else None,
            "p_hang_up_95ci": [lo, hi] if decided else None,
            "interval": "Wilson score, 95 %, over the runs that passed (in time or late) or hung up (still in "
                        "the pump at the end)"}


def write_csv(members, path):
    rows = []
    for m in members:
        row = {"run": m.name, "state": m.state, "error": m.error or ""}
        row.update({"release." + k: v for k, v in m.release.items()})
        row.update(flat(m.metrics))
        rows.append(row)
    keys = []
    for row in rows:
        keys += [k for k in row if k not in keys]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


def draw(members, summary, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [flat(m.metrics) for m in members if m.metrics]
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    ax = axes[0]
    p, ci = summary["p_hang_up"], summary["p_hang_up_95ci"]
    if p is not None:
        ax.bar([0], [p], color="C3", width=0.5)
        ax.errorbar([0], [p], yerr=[[p - ci[0]], [ci[1] - p]], color="k", capsize=8)
    ax.set_xlim(-1, 1)
    ax.set_ylim(0, 1)
    ax.set_xticks([])
    ax.set_ylabel("P(hang-up)")
    ax.set_title("P(hang-up) = %s, 95 %% CI %s\n%d hung up, %d passed, %d late, %d not decided, %d failed"
                 % ("%.2f" % p if p is not None else "n/a", "[%.2f, %.2f]" % tuple(ci) if ci else "n/a",
                    summary["hung_up"], summary["passed"], summary["passed_late"], summary["still_running_at_end"],
                    summary["failed"]),
                 fontsize=9)
    ax = axes[1]
    for key, label, colour in (("residence_time_revolutions", "residence (revolutions)", "C0"),
                               ("wrap_fraction_of_residence", "wrap fraction x 10", "C1")):
        values = [d[key] * (10 if "wrap" in key else 1) for d in done if isinstance(d.get(key), (int, float))
                  and not math.isnan(d[key])]
        if values:
            ax.hist(values, bins=max(3, len(values)), alpha=0.6, color=colour, label=label)
    ax.set_xlabel("value")
    ax.set_ylabel("runs")
    ax.legend(fontsize=8)
    ax.set_title("residence time and leading-edge wrap over %d runs" % len(done), fontsize=9)
    ax = axes[2]
    sites = {}
    for d in done:
        for key, value in d.items():
            if key.startswith("trap_contact_time_s.") and isinstance(value, (int, float)):
                sites[key.split(".", 1)[1]] = sites.get(key.split(".", 1)[1], 0.0) + value
    if sites:
        ax.barh(list(sites), list(sites.values()), color="C2")
    ax.set_xlabel("contact time summed over the runs (s)")
    ax.set_title("trap sites", fontsize=9)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def report_progress(members, stop):
    while not stop.wait(30.0):
        running = [m for m in members if m.state == "running"]
        done = sum(m.state in ("done", "failed") for m in members)
        say("%d/%d runs done; %s" % (done, len(members), ", ".join(
            "%s %.0f %% (ETA %s)" % (m.name, 100 * m.progress, m.eta or "?") for m in running) or "starting"))


def parse_args(argv):
    parser = argparse.ArgumentParser(prog="./fsi rag-ensemble", description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--runs", type=int, default=8, help="members of the ensemble (default 8)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the releases' draw (default 1)")
    parser.add_argument("--flow-fraction", type=float, default=1.0,
                        help="flow rate as a fraction of the case's (fluid.openfoam.operating_point: Q_BEP); 0.36: the "
                             "paper's part load")
    parser.add_argument("--sizes", default="", help="rag sizes LENGTHxWIDTH (m), comma-separated, used in turn "
                                                    "(default: the case's rag)")
    parser.add_argument("--jobs", type=int, default=0, help="members at once (default: half the cores, at least 1)")
    parser.add_argument("--resolution", default="", help="a preset of the case (coarse, medium, fine)")
    parser.add_argument("--end-time", type=float, default=0.0, help="stop each member at this time (s)")
    parser.add_argument("-o", "--output", default="", help="results folder (default CASE/output/ensemble-q<F>-s<SEED>)")
    parser.add_argument("case_dir")
    args = parser.parse_args(argv)
    args.case_dir = os.path.abspath(args.case_dir)
    if args.runs < 1:
        raise SystemExit("rag-ensemble: --runs %d: at least 1" % args.runs)
    if args.flow_fraction <= 0:
        raise SystemExit("rag-ensemble: --flow-fraction %g: must be > 0" % args.flow_fraction)
    return args


class CaseInputs:
    """What the ensemble takes from the case folder: the pump's design (with its sump), the case's
    flow rate, its rag and the collision distance."""

    def __init__(self, args):
        for name in ("case.yaml", "pump.yaml"):
            if not os.path.isfile(os.path.join(args.case_dir, name)):
                raise SystemExit("rag-ensemble: %s not found: a rag-in-pump case holds case.yaml and pump.yaml "
                                 "(cases/rag-in-pump)" % os.path.join(args.case_dir, name))
        with open(os.path.join(args.case_dir, "pump.yaml")) as f:
            self.design = yaml.safe_load(f)
        if not float(self.design.get("inlet", {}).get("sump_diameter_m") or 0):
            raise SystemExit("rag-ensemble: %s has no inlet sump (inlet.sump_diameter_m): the rags are released in it"
                             % os.path.join(args.case_dir, "pump.yaml"))
        with open(os.path.join(args.case_dir, "case.yaml")) as f:
            case = yaml.safe_load(f)
        rags = case.get("structures") or []
        if len(rags) != 1 or rags[0].get("model", "membrane") != "membrane":
            raise SystemExit("rag-ensemble: %s/case.yaml: expected one membrane in structures (the rag)" % args.case_dir)
        self.rag = rags[0]
        self.sizes = parse_sizes(args.sizes) if args.sizes else [tuple(float(v) for v in self.rag["size_m"])]
        self.collision_m = float((case.get("collisions") or {}).get("threshold_m", 0.004))
        point = ((case.get("fluid") or {}).get("openfoam") or {}).get("operating_point") or {}
        if "flow_rate_m3_per_s" not in point:
            raise SystemExit("rag-ensemble: %s/case.yaml: no fluid.openfoam.operating_point.flow_rate_m3_per_s (the "
                             "flow rate the ensemble's --flow-fraction multiplies)" % args.case_dir)
        self.case_flow_rate = float(point["flow_rate_m3_per_s"])


def plan_members(args, inputs, out, flow_rate):
    """The members, their releases drawn from the seed, each in its own copy of the case."""
    rng = random.Random(args.seed)
    members = []
    for i in range(args.runs):
        m = Member(i, out, flow_rate)
        member_rag, m.release = draw_release(rng, inputs.sizes[i % len(inputs.sizes)], inputs.rag, inputs.design,
                                             inputs.collision_m)
        if i == 0 and not args.sizes:  # the case's own rag as it is: the reference member
            member_rag, m.release = inputs.rag, {"case_release": True, "length_m": inputs.sizes[0][0],
                                                 "width_m": inputs.sizes[0][1]}
        prepare_member(args, m, member_rag)
        members.append(m)
    return members


def run_members(args, members, jobs):
    """The first member alone (its precursor serves the others), then the rest, `jobs` at once."""
    stop = threading.Event()
    threading.Thread(target=report_progress, args=(members, stop), daemon=True).start()
    try:
        run_member(args, members[0])
        for m in members[1:]:
            seed_precursor(os.path.join(members[0].folder, "precursor"), m)
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            list(pool.map(lambda m: run_member(args, m), members[1:]))
    finally:
        stop.set()
    for m in members:
        if m.state == "failed":
            say("%s failed: %s" % (m.name, m.error))


def main(argv):
    args = parse_args(argv)
    inputs = CaseInputs(args)
    try:  # the case's generated inputs (the pump's geometry) before the members copy the case
        fsi_launch.prepare_case(args.case_dir, args.bin_dir)
    except fsi_launch.UserError as e:
        raise SystemExit("rag-ensemble: %s" % e)
    flow_rate = inputs.case_flow_rate * args.flow_fraction
    out = os.path.abspath(args.output or os.path.join(
        args.case_dir, "output", "ensemble-q%.2f-s%d%s" % (args.flow_fraction, args.seed,
                                                          "-" + args.resolution if args.resolution else "")))
    os.makedirs(out, exist_ok=True)
    args.fingerprint = pump_curve.case_fingerprint(args.case_dir, out)
    members = plan_members(args, inputs, out, flow_rate)
    jobs = args.jobs or max(1, (os.cpu_count() or 2) // 2)
    say("%d runs at Q = %.4g m^3/s (%.3g of the case's), %d at once, into %s"
        % (len(members), flow_rate, args.flow_fraction, jobs, out))
    started = time.monotonic()
    run_members(args, members, jobs)
    summary = summarise(members, args.flow_fraction)
    summary.update({"flow_rate_m3_per_s": flow_rate, "seed": args.seed, "sizes_m": [list(s) for s in inputs.sizes],
                    "wall_time_s": round(time.monotonic() - started, 1)})
    write_csv(members, os.path.join(out, "ensemble.csv"))
    with open(os.path.join(out, "ensemble.yaml"), "w") as f:
        yaml.safe_dump(summary, f, sort_keys=False)
    draw(members, summary, os.path.join(out, "ensemble.png"),
         "%s: %d rag releases at Q = %.3g L/s (%.2f x the case's), seed %d"
         % (os.path.basename(args.case_dir), len(members), 1e3 * flow_rate, args.flow_fraction, args.seed))
    say("P(hang-up) = %s (95 %% CI %s) over %d decided runs; %s"
        % (summary["p_hang_up"], summary["p_hang_up_95ci"], summary["runs_decided"],
           os.path.join(out, "ensemble.png")))
    return 0 if summary["failed"] < len(members) else 1

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
