#!/usr/bin/python3
"""./fsi feed-compare: the same rag feed into two pump designs at the same operating points,
repeated over seeds, and which design clogs later with a confidence statement (issue 33,
section 3): per design and flow, the rags to clog of each seed, their median with a 95 %
interval, and P(A outlasts B) (python/fsi/feed_statistics.py). compare.md, compare.yaml,
compare.csv and compare.png in the output folder.

    feed_compare.py --bin-dir BIN [--designs A.yaml,B.yaml] [--flow-fractions 1,0.36] [--seeds 4]
                    [--rags 20] [--jobs N] [--end-time S] [--submit [--sbatch-arg ARG ...]] [-o DIR] CASE_DIR

CASE_DIR is a feed case (cases/rag-feed). Each design is a pump.yaml (pump/designs/); default:
the case's own pump (cases/rag-in-pump's) against pump/designs/two-blade.yaml. Every design is
given the case's inlet (its sump), so that the rags start in the same place in every pump. The
flow rates are the fractions of the case's (fluid.openfoam.operating_point): the same duty for
both designs. A member is one design, flow and seed: a copy of the case in
DIR/<design>/q<fraction>/seed-<seed>/case with the design's pump.yaml and its flow rate, seed and
rag count written into its case.yaml, run as ./fsi run runs it (results in its output/), then
the feed's report (feed_report.py). Locally the precursor of one design and flow is run once and
shared by its seeds; members run in parallel up to --jobs (default: half the cores). A finished
member (its structure.h5 completed) is reused; an interrupted one resumes from its last
checkpoint. --submit runs the members as a SLURM job array instead (./fsi submit: one task a
member, each requeueable and resumed from its checkpoints); feed-compare again, without
--submit, collects what they wrote and compares.
"""

import argparse
import concurrent.futures
import csv
import os
import re
import shutil
import signal
import sys
import threading
import time

import yaml

from fsi import ROOT
from fsi import case_copy
from fsi import feed_report
from fsi import feed_statistics
from fsi import fsi_launch
from fsi import pump_curve
from fsi.rag_ensemble import PROGRESS   # the coupler's progress line

# The fluid's progress line in the precursor: "precursor: t = 0.0355 of 0.5 s, step 142/2000, ... ETA 3m19s"
PRECURSOR = re.compile(r"precursor: t = \S+ of \S+ s, step (\d+)/(\d+),.*\bETA (\S+(?: s)?)")

STOP = threading.Event()   # set on Ctrl-C or SIGTERM: no member starts after it

# Held while a report or the comparison is written: pyplot's figures are shared by the threads.
LOCK = threading.RLock()


say = fsi_launch.speaker("feed-compare")


class Member:
    def __init__(self, design, fraction, seed, out):
        self.design, self.fraction, self.seed = design, fraction, seed
        self.name = "%s q%.2f seed %d" % (design.name, fraction, seed)
        self.case = os.path.join(out, design.name, "q%.2f" % fraction, "seed-%d" % seed, "case")
        self.folder = os.path.join(self.case, "output")   # where ./fsi run and ./fsi submit write
        self.state, self.error, self.verdict, self.outcomes = "waiting", None, None, {}
        self.progress, self.eta, self.phase = 0.0, "", ""
        self.started, self.seconds = None, None   # monotonic start, wall time of a run to its end (s)
        self.finished_before = False               # finished by an earlier invocation (reused)
        self.resumed_at = None                     # the feed's progress at its first line here (0..1)
        self.pump_revolutions = []                 # the passed rags' revolutions in the pump


class Design:
    def __init__(self, path, index):
        self.path = os.path.abspath(path)
        base = os.path.splitext(os.path.basename(path))[0]
        if base == "pump":   # a case's pump.yaml: named after its case
            base = os.path.basename(os.path.dirname(self.path))
        self.name = "%s-%s" % ("AB"[index], base)


def parse_args(argv):
    p = argparse.ArgumentParser(prog="./fsi feed-compare", description=__doc__.split("\n\n")[0])
    p.add_argument("--bin-dir", required=True)
    p.add_argument("--designs", default="", help="two pump.yaml files A,B (default: the case's pump and "
                                                 "pump/designs/two-blade.yaml)")
    p.add_argument("--flow-fractions", default="1,0.36", help="of the case's flow rate (default 1,0.36)")
    p.add_argument("--seeds", type=int, default=4, help="seeds 1..N per design and flow (default 4)")
    p.add_argument("--rags", type=int, default=0, help="rags per feed (default: the case's feed.rags)")
    p.add_argument("--jobs", type=int, default=0, help="members at once (default: half the cores, at least 1)")
    p.add_argument("--resolution", default="", help="a preset of the case")
    p.add_argument("--end-time", type=float, default=0.0, help="stop each member at this time (s)")
    p.add_argument("--submit", action="store_true", help="run the members as a SLURM job array (./fsi submit)")
    p.add_argument("--sbatch-arg", action="append", default=[], metavar="ARG", help="with --submit: to sbatch")
    p.add_argument("-o", "--output", default="", help="results folder (default CASE/output/compare)")
    p.add_argument("case_dir")
    args = p.parse_args(argv)
    args.case_dir = os.path.abspath(args.case_dir)
    try:
        args.fractions = [float(v) for v in args.flow_fractions.split(",")]
    except ValueError:
        p.error("--flow-fractions %r: comma-separated numbers, e.g. 1,0.36" % args.flow_fractions)
    if not args.fractions or any(f <= 0 for f in args.fractions):
        p.error("--flow-fractions %r: each above 0" % args.flow_fractions)
    folders = ["q%.2f" % f for f in args.fractions]
    if len(set(folders)) != len(folders):
        p.error("--flow-fractions %r: two fractions share a folder (%s; to two decimals): give each once"
                % (args.flow_fractions, ", ".join(folders)))
    if args.seeds < 1:
        p.error("--seeds %d: at least 1" % args.seeds)
    for name, value in (("--rags", args.rags), ("--jobs", args.jobs), ("--end-time", args.end_time)):
        if value < 0:
            p.error("%s %s: at least 0 (0: the default)" % (name, value))
    paths = [v for v in args.designs.split(",") if v] if args.designs else \
        [os.path.join(ROOT, "cases", "rag-in-pump", "pump.yaml"), os.path.join(ROOT, "pump", "designs", "two-blade.yaml")]
    if len(paths) != 2:
        p.error("--designs %r: two pump.yaml files, A,B" % args.designs)
    for path in paths:
        if not os.path.isfile(path):
            p.error("--designs: %s: no such file (a pump.yaml, e.g. pump/designs/two-blade.yaml)" % path)
    args.designs = [Design(path, k) for k, path in enumerate(paths)]
    if args.designs[0].name[2:] == args.designs[1].name[2:] and \
            open(paths[0]).read() == open(paths[1]).read():
        p.error("--designs: A and B are the same file")
    return args


def case_inputs(case_dir):
    """(case.yaml, the case's flow rate, its feed's rag count, its inlet section) of a feed case."""
    path = os.path.join(case_dir, "case.yaml")
    if not os.path.isfile(path):
        raise SystemExit("feed-compare: %s: no such file (CASE_DIR: a feed case, e.g. cases/rag-feed)" % path)
    with open(path) as f:
        case = yaml.safe_load(f)
    if not case.get("feed"):
        raise SystemExit("feed-compare: %s: no feed section (a feed case, e.g. cases/rag-feed)" % path)
    point = ((case.get("fluid") or {}).get("openfoam") or {}).get("operating_point") or {}
    if "flow_rate_m3_per_s" not in point:
        raise SystemExit("feed-compare: %s: no fluid.openfoam.operating_point.flow_rate_m3_per_s (the flow rate "
                         "--flow-fractions multiply)" % path)
    source = os.path.join(case_dir, "pump.yaml")
    if not os.path.isfile(source):
        source = os.path.join(ROOT, "cases", "rag-in-pump", "pump.yaml")
    with open(source) as f:
        inlet = (yaml.safe_load(f) or {}).get("inlet")
    if not inlet or not inlet.get("sump_diameter_m"):
        raise SystemExit("feed-compare: %s has no inlet sump (inlet.sump_diameter_m): the rags are released in it"
                         % source)
    return float(point["flow_rate_m3_per_s"]), int(case["feed"].get("rags", 1)), inlet


def write_member_case(args, member, inlet, flow_rate, rags):
    """The member's copy of the case: the design's pump.yaml given the case's inlet, and the
    member's flow rate, seed and rag count in its case.yaml. Unchanged files are not rewritten."""
    if not os.path.isdir(member.case):
        shutil.copytree(args.case_dir, member.case, symlinks=True, ignore=case_copy.ignore_results([args.output_dir], (
            "output", "__pycache__", "geometry", "geometry.partial-*", "geometry.old-*", ".geometry.lock",
            "openfoam-*", "pump.yaml")))
    with open(member.design.path) as f:
        design = yaml.safe_load(f)
    design["inlet"] = inlet
    with open(os.path.join(args.case_dir, "case.yaml")) as f:
        case = yaml.safe_load(f)
    case["feed"]["seed"] = member.seed
    case["feed"]["rags"] = rags
    case["fluid"]["openfoam"]["operating_point"]["flow_rate_m3_per_s"] = flow_rate * member.fraction
    if args.end_time:
        case["run"]["end_time_s"] = args.end_time   # in the case: a SLURM task runs it as it is
    # The pump.yaml is the same for every member of a design (its geometry is generated once).
    pump_text = "# Written by ./fsi feed-compare: %s with the inlet of %s\n" % (member.design.path, args.case_dir)
    case_text = "# Written by ./fsi feed-compare: member %s of %s\n" % (member.name, args.case_dir)
    for name, text in (("pump.yaml", pump_text + yaml.safe_dump(design, sort_keys=False)),
                       ("case.yaml", case_text + yaml.safe_dump(case, sort_keys=False))):
        target = os.path.join(member.case, name)
        if not os.path.isfile(target) or open(target).read() != text:
            with open(target, "w") as f:
                f.write(text)


def stamp_of(member, args):
    """What a member's results depend on: its case.yaml and pump.yaml, and the preset."""
    return "case %s resolution %s\n" % (pump_curve.files_digest(member.case, [
        os.path.join(member.case, "case.yaml"), os.path.join(member.case, "pump.yaml")]), args.resolution or "-")


def start_folder(member, args):
    """The member's output folder for its current case: results of another case (other options,
    another pump.yaml) are moved aside to <folder>.old-<n>, not reused nor deleted."""
    path = os.path.join(member.folder, "feed_compare.stamp")
    stamp = stamp_of(member, args)
    holds_results = os.path.isdir(member.folder) and \
        set(os.listdir(member.folder)) - {"feed_compare.stamp", fsi_launch.RUN_LOCK}
    if holds_results and (not os.path.isfile(path) or open(path).read() != stamp):
        n = 1
        while os.path.exists("%s.old-%d" % (member.folder, n)):
            n += 1
        os.rename(member.folder, "%s.old-%d" % (member.folder, n))
        say("%s: results of another case moved to %s.old-%d" % (member.name, member.folder, n))
    os.makedirs(member.folder, exist_ok=True)
    with open(path, "w") as f:
        f.write(stamp)


def finished(member):
    """The member's run completed (its structure.h5 says so)."""
    import h5py
    path = os.path.join(member.folder, "structure.h5")
    if not os.path.isfile(path):
        return False
    try:
        with h5py.File(path, "r") as f:
            status = f.attrs.get("status", "")
    except OSError:
        return False
    return (status.decode() if isinstance(status, bytes) else str(status)) == "completed"


def member_command(args, member):
    command = [sys.executable, pump_curve.LAUNCHER, "--bin-dir", args.bin_dir, "-o", member.folder]
    command += ["--resolution", args.resolution] if args.resolution else []
    command += ["--end-time", str(args.end_time)] if args.end_time else []
    if os.path.isdir(os.path.join(member.folder, "checkpoints")):
        command.append("--restart")
    return command + [member.case]


def run_member(args, member, on_done=None):
    if STOP.is_set():
        return
    start_folder(member, args)
    if not finished(member):
        member.state = "running"
        started = member.started = time.monotonic()
        def on_line(line):
            for phase, pattern in (("precursor ", PRECURSOR), ("", PROGRESS)):
                match = pattern.search(line)
                if match:
                    member.progress, member.eta = int(match.group(1)) / int(match.group(2)), match.group(3)
                    member.phase = phase
                    if not phase and member.resumed_at is None:   # a resumed feed starts part done
                        member.resumed_at, member.started = member.progress, time.monotonic()

        code = pump_curve.run_logged(member_command(args, member), os.path.join(member.folder, "feed_compare.log"),
                                     on_line, append=True)
        if code != 0:
            member.state, member.error = "failed", "exit code %d (log: %s)" % (
                code, os.path.join(member.folder, "feed_compare.log"))
            return
        elapsed = time.monotonic() - started
        # A whole member's wall time, for the study's ETA: a resumed one ran only its rest.
        done_here = 1.0 - (member.resumed_at or 0.0)
        member.seconds = elapsed / done_here if done_here > 0.2 else None
        say("%s: ran in %.0f s" % (member.name, elapsed))
    collect(member)
    if on_done:
        on_done()


def collect(member):
    """The member's verdict from its feed report (written anew)."""
    if not finished(member):
        member.state = "not run" if not os.path.isdir(member.folder) else "unfinished"
        return
    member.state = "reporting"
    try:
        with LOCK:
            report = feed_report.write_report(member.folder, member.case, animation=False)
    except Exception as error:   # one member's report must not stop the others (a traceback in its log)
        member.state, member.error = "failed", "report: %s: %s" % (type(error).__name__, error)
        return
    verdict = report.get("verdict") or {}
    if verdict.get("clogged") is None:
        member.state, member.error = "failed", "no clog criterion evaluated (feed.clog_criterion)"
        return
    if verdict.get("not_evaluated"):
        # Judged on fewer conditions than its case states (no clean pump to compare with): not
        # comparable with members judged on all of them.
        said = [n for n in report.get("notes") or [] if n.startswith("clog criterion:")]
        member.state, member.error = "failed", "report: %s" % (
            "; ".join(said) or "%s not evaluated" % " and ".join(verdict["not_evaluated"]))
        return
    member.verdict = verdict
    member.outcomes = report.get("outcomes") or {}
    with open(os.path.join(member.folder, "feed_rags.csv")) as f:
        member.pump_revolutions = [float(r["time_in_pump_revolutions"]) for r in csv.DictReader(f)
                                   if r["outcome"] in ("passed", "passed_late")]
    member.state = "done"


def rags_to_clog(member):
    v = member.verdict
    return feed_statistics.RagsToClog(int(v["rags_released"]), not v["clogged"])


def summarise(args, members):
    """Per flow fraction: the comparison of A against B over the members that finished."""
    a_name, b_name = args.designs[0].name, args.designs[1].name
    results = []
    for fraction in args.fractions:
        done = {d.name: [m for m in members if m.design is d and m.fraction == fraction and m.verdict]
                for d in args.designs}
        row = {"flow_fraction": fraction, "design_a": a_name, "design_b": b_name,
               "runs_a": len(done[a_name]), "runs_b": len(done[b_name]),
               "rags_to_clog_a": [[rags_to_clog(m).rags, rags_to_clog(m).censored] for m in done[a_name]],
               "rags_to_clog_b": [[rags_to_clog(m).rags, rags_to_clog(m).censored] for m in done[b_name]]}
        if done[a_name] and done[b_name]:
            c = feed_statistics.compare([rags_to_clog(m) for m in done[a_name]],
                                        [rags_to_clog(m) for m in done[b_name]])
            row.update({k: v for k, v in vars(c).items()})
            row["statement"] = feed_statistics.statement(c, a_name, b_name)
        else:
            row["statement"] = "not compared: a design has no finished run at this flow"
        results.append(row)
    return results


def write_outputs(args, members, results, out):
    with open(os.path.join(out, "compare.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["design", "flow_fraction", "seed", "state", "clogged", "rags_released", "time_s", "reason",
                    "saturation_rags", "saturation_kg"] + ["rags_" + o for o in feed_report.OUTCOMES] + ["error"])
        for m in members:
            v = m.verdict or {}
            w.writerow([m.design.name, m.fraction, m.seed, m.state, v.get("clogged"), v.get("rags_released"),
                        v.get("time_s"), v.get("reason"), v.get("saturation_rags"), v.get("saturation_kg")]
                       + [m.outcomes.get(o) if m.outcomes else None for o in feed_report.OUTCOMES] + [m.error or ""])
    with open(os.path.join(out, "compare.yaml"), "w") as f:
        yaml.safe_dump({"designs": {d.name: d.path for d in args.designs}, "seeds": args.seeds,
                        "comparisons": feed_report._plain(results)}, f, sort_keys=False)
    lines = ["# Feed comparison: %s against %s, %d seeds\n" % (args.designs[0].path, args.designs[1].path, args.seeds),
             "| flow (of the case's) | %s: rags to clog per seed | %s: rags to clog per seed | P(A outlasts B) (95 %% interval) "
             "| Gehan's test p | rags torn (A, B) |"
             % (args.designs[0].name, args.designs[1].name), "|---|---|---|---|---|---|"]

    def runs(values):
        return ", ".join("%s%d" % (">" if censored else "", n) for n, censored in values) or "none"
    for r in results:
        p = ("%.2f (%.2f-%.2f)" % (r["p_a_outlasts_b"], *r["p_a_outlasts_b_95"])) if "p_a_outlasts_b" in r else "n/a"
        torn = [sum(m.outcomes.get("torn", 0) for m in members
                    if m.design is d and m.fraction == r["flow_fraction"] and m.verdict) for d in args.designs]
        lines.append("| %.2f | %s | %s | %s | %s | %d, %d |" % (
            r["flow_fraction"], runs(r["rags_to_clog_a"]), runs(r["rags_to_clog_b"]), p,
            "%.3f" % r["p_value"] if "p_value" in r else "n/a", *torn))
    lines.append("\n>N: the pump coped with the N rags it was fed (not clogged by the end). A torn rag (stretched "
                 "past its kind's tear_above_stretch_ratio, caught between the impeller and the casing) counts as "
                 "held in the pump from its tear on.\n")
    lines += ["- **%.2f Q**: %s" % (r["flow_fraction"], r["statement"]) for r in results]
    lines += ["", "How the rags went, over the finished seeds (outcomes as feed_rags.csv; revolutions in the pump "
              "from a rag's entry past the sump to its exit):", "",
              "| flow | design | seeds | rags fed | passed (late) | revolutions in the pump, passed: median (range) "
              "| torn | retained or in the pump at the end | in the sump at the end |", "|---|---|---|---|---|---|---|---|---|"]
    for fraction in args.fractions:
        for d in args.designs:
            done = [m for m in members if m.design is d and m.fraction == fraction and m.verdict]
            if not done:
                continue
            total = {o: sum(m.outcomes.get(o, 0) for m in done) for o in feed_report.OUTCOMES}
            times = sorted(v for m in done for v in m.pump_revolutions)
            spread = ("%.1f (%.1f-%.1f)" % (feed_statistics.median(times), times[0], times[-1])) if times else "n/a"
            lines.append("| %.2f | %s | %d | %d | %d (%d) | %s | %d | %d | %d |" % (
                fraction, d.name, len(done), sum(total.values()) - total["waiting"],
                total["passed"] + total["passed_late"], total["passed_late"], spread, total["torn"],
                total["retained"] + total["in_pump"], total["in_sump"]))
    with open(os.path.join(out, "compare.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    draw(args, results, os.path.join(out, "compare.png"), members)


def draw(args, results, path, members=()):
    """Per flow: the rags to clog of each seed (open: not clogged by the end), their median and
    95 % interval, P(A outlasts B) and Gehan's p; below, how the rags went in each design (the
    outcomes summed over its finished seeds)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator
    fig, axes = plt.subplots(2, len(results), figsize=(max(7.0, 4.6 * len(results)), 7.6), squeeze=False,
                             gridspec_kw={"height_ratios": [3, 2]})
    shown = [o for o in feed_report.OUTCOMES if o != "waiting"]
    for column, r in enumerate(results):
        ax = axes[0, column]
        top = 1
        for k, key in enumerate(("a", "b")):
            values = r["rags_to_clog_" + key]
            top = max([top] + [n for n, _ in values])
            xs = [k + 0.08 * (i - (len(values) - 1) / 2) for i in range(len(values))]
            ax.scatter(xs, [n for n, _ in values], marker="o", facecolors=["none" if c else "C%d" % k for _, c in values],
                       edgecolors="C%d" % k, zorder=3)
            if "median_" + key in r:
                m, ci = r["median_" + key], r["median_%s_95" % key]
                ax.errorbar([k + 0.3], [m], yerr=[[m - ci[0]], [ci[1] - m]], fmt="s", color="k", capsize=6)
        ax.set_xticks([0, 1])
        ax.set_xticklabels([r["design_a"], r["design_b"]], fontsize=8)
        ax.set_xlim(-0.6, 1.6)
        ax.set_ylim(0, top + 2)
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))
        ax.set_ylabel("rags released when clogged\n(open: not clogged by the end)")
        title = "%.2f x the case's flow" % r["flow_fraction"]
        if "p_a_outlasts_b" in r:
            title += "\nP(A outlasts B) = %.2f (%.2f-%.2f), Gehan's p = %.3f" % (
                r["p_a_outlasts_b"], *r["p_a_outlasts_b_95"], r["p_value"])
        ax.set_title(title, fontsize=9)
        ax.grid(alpha=0.3)
        ax = axes[1, column]
        for k, d in enumerate(args.designs):
            done = [m for m in members if m.design is d and m.fraction == r["flow_fraction"] and m.verdict]
            bottom = 0
            for outcome in shown:
                n = sum(m.outcomes.get(outcome, 0) for m in done)
                if n:
                    ax.bar([k], [n], bottom=[bottom], width=0.5, color=feed_report.OUTCOME_COLOURS[outcome])
                    bottom += n
            ax.text(k, bottom, " %d seed%s" % (len(done), "" if len(done) == 1 else "s"), ha="center",
                    va="bottom", fontsize=7)
        ax.set_xticks([0, 1])
        ax.set_xticklabels([d.name for d in args.designs], fontsize=8)
        ax.set_xlim(-0.6, 1.6)
        ax.yaxis.set_major_locator(MaxNLocator(integer=True))
        ax.set_ylabel("rags, over the seeds")
        ax.grid(alpha=0.3, axis="y")
    from matplotlib.patches import Patch
    fig.legend([Patch(color=feed_report.OUTCOME_COLOURS[o]) for o in shown], [o.replace("_", " ") for o in shown],
               loc="lower center", ncol=len(shown), fontsize=8)
    fig.suptitle("feed comparison over %d seeds: median and 95 %% interval in black;\nbelow, how the rags went"
                 % args.seeds, fontsize=10)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plan(args, out, inlet, flow_rate, rags):
    members = [Member(d, f, s, out) for f in args.fractions for d in args.designs for s in range(1, args.seeds + 1)]
    for m in members:
        write_member_case(args, m, inlet, flow_rate, rags)
    return members


def prepare_members(args, members):
    """Each design's pump generated once (its first member), its geometry and OpenFOAM folders
    copied to the design's other members, then each member prepared (up to date: quick)."""
    for design in args.designs:
        mine = [m for m in members if m.design is design]
        try:
            fsi_launch.prepare_case(mine[0].case, args.bin_dir, args.resolution or None)
            for m in mine[1:]:
                for name in os.listdir(mine[0].case):
                    if (name == "geometry" or name.startswith("openfoam-")) and \
                            not os.path.exists(os.path.join(m.case, name)):
                        shutil.copytree(os.path.join(mine[0].case, name), os.path.join(m.case, name), symlinks=True)
                fsi_launch.prepare_case(m.case, args.bin_dir, args.resolution or None)
        except fsi_launch.UserError as e:
            raise SystemExit("feed-compare: %s: %s" % (design.path, e))


def study_eta_s(members, jobs, now=None):
    """The study's remaining wall time (s), or None before anything can tell: the members still
    to run and the running ones' remaining shares, at the median wall time of the members that
    ran to the end in this invocation (else the running ones' pace since their first progress
    line here: a resumed member starts part done), `jobs` at a time."""
    now = time.monotonic() if now is None else now
    running = [m for m in members if m.state == "running"]
    waiting = sum(m.state == "waiting" and not m.finished_before for m in members)
    ran = sorted(m.seconds for m in members if m.seconds)
    if ran:
        per_member = ran[len(ran) // 2]
    else:   # a feed's progress (not a precursor's): the elapsed time over the share done
        paces = [(now - m.started) / (m.progress - (m.resumed_at or 0.0)) for m in running
                 if not m.phase and m.started is not None and m.progress - (m.resumed_at or 0.0) > 0.05]
        if not paces:
            return None
        per_member = sorted(paces)[len(paces) // 2]
    left = waiting + sum(1.0 - (m.progress if not m.phase else 0.0) for m in running)
    return left * per_member / max(1, min(jobs, len(running) + waiting))


def report_progress(members, stop, jobs):
    """Every minute: members done, each running one's progress and ETA (its coupler's), and the
    whole study's ETA (study_eta_s)."""
    while not stop.wait(60.0):
        running = [m for m in members if m.state == "running"]
        done = sum(m.state in ("done", "failed") for m in members)
        eta = study_eta_s(members, jobs)
        say("%d/%d members done%s; %s" % (done, len(members), ", study ETA %.1f h" % (eta / 3600.0)
                                          if eta is not None else "", ", ".join(
            "%s: %s%.0f %% (ETA %s)" % (m.name, m.phase, 100 * m.progress, m.eta or "?") for m in running)
            or ("writing the reports of finished members" if any(m.state == "reporting" for m in members)
                else "starting")))


def run_all(args, members, jobs, on_done=None):
    """Per design and flow, the first seed alone (its precursor serves the others), then the rest."""
    firsts = [m for m in members if m.seed == 1]
    rest = [m for m in members if m.seed != 1]
    stop = threading.Event()
    threading.Thread(target=report_progress, args=(members, stop, jobs), daemon=True).start()
    try:
        run_pool(args, firsts, rest, jobs, on_done)
    finally:
        stop.set()


def run_pool(args, firsts, rest, jobs, on_done):
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        try:
            run_stages(args, firsts, rest, pool, on_done)
        except KeyboardInterrupt:
            # Ctrl-C: the running members' launchers had it too and checkpoint; none starts after.
            STOP.set()
            pool.shutdown(wait=False, cancel_futures=True)
            raise


def run_stages(args, firsts, rest, pool, on_done):
    """The first seeds, then the rest with the first's precursor hard-linked into each."""
    list(pool.map(lambda m: run_member(args, m, on_done), firsts))
    for m in rest:
        first = next(f for f in firsts if f.design is m.design and f.fraction == m.fraction)
        source, target = os.path.join(first.folder, "precursor"), os.path.join(m.folder, "precursor")
        if os.path.isdir(source) and not os.path.exists(target):
            os.makedirs(m.folder, exist_ok=True)
            shutil.copytree(source, target, copy_function=os.link)
    list(pool.map(lambda m: run_member(args, m, on_done), rest))


def submit(args, members):
    """The unfinished members as one SLURM job array (./fsi submit)."""
    from fsi import fsi_submit
    for m in members:
        start_folder(m, args)
    todo = [m.case for m in members if not finished(m)]
    if not todo:
        say("every member has finished: nothing to submit; run feed-compare without --submit to compare")
        return 0
    extra = []
    for a in args.sbatch_arg:
        extra += ["--sbatch-arg", a]
    say("%d members to SLURM; afterwards: ./fsi feed-compare (the same options, without --submit)" % len(todo))
    return fsi_submit.main(["--bin-dir", args.bin_dir] + extra + todo)


def main(argv):
    args = parse_args(argv)
    flow_rate, case_rags, inlet = case_inputs(args.case_dir)
    rags = args.rags or case_rags
    out = os.path.abspath(args.output or os.path.join(args.case_dir, "output", "compare"))
    os.makedirs(out, exist_ok=True)
    args.output_dir = out
    members = plan(args, out, inlet, flow_rate, rags)
    prepare_members(args, members)
    if args.submit:
        if args.resolution:
            raise SystemExit("feed-compare: --resolution with --submit: ./fsi submit runs a case as it is; "
                             "give the preset's keys in the case instead")
        return submit(args, members)
    jobs = args.jobs or max(1, (os.cpu_count() or 2) // 2)
    say("%d members (2 designs x %d flows x %d seeds, %d rags each), %d at once, into %s"
        % (len(members), len(args.fractions), args.seeds, rags, jobs, out))
    for m in members:   # the precursor copies below go into folders of this case
        start_folder(m, args)
        m.finished_before = finished(m)
    def write_so_far():   # after each member: the comparison of what has finished, kept if the run is cut
        with LOCK:
            write_outputs(args, members, summarise(args, members), out)

    def terminated(signum, frame):   # SIGTERM (kill, a scheduler): passed on to the running members
        for process in list(pump_curve.RUNNING):
            process.send_signal(signal.SIGTERM)
        raise KeyboardInterrupt
    signal.signal(signal.SIGTERM, terminated)
    try:
        run_all(args, members, jobs, write_so_far)
    except KeyboardInterrupt:
        write_so_far()
        say("interrupted: the running members stopped at a checkpoint; run the same command again to resume "
            "(finished members are reused); the comparison so far: %s" % os.path.join(out, "compare.md"))
        return 130
    for m in members:
        if m.state == "failed":
            say("%s failed: %s" % (m.name, m.error))
    results = summarise(args, members)
    write_outputs(args, members, results, out)
    for r in results:
        say("%.2f Q: %s" % (r["flow_fraction"], r["statement"]))
    say("%s" % os.path.join(out, "compare.md"))
    return 0 if any(m.verdict for m in members) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
