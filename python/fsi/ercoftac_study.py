#!/usr/bin/python3
"""The ERCOFTAC pump with both methods against the measurement, at each mesh level (issue 31):
the penalized impeller (our fluid, through the launcher, preset <level>) and the body-fitted AMI
rotor (stock pimpleFoam, python/fsi/ercoftac_ami_run.py) on the same stator cells, each from rest
for the same revolutions, each postprocessed by the case (cases/ercoftac-pump/postprocess.py:
the second half of the run).

    ./fsi ercoftac-study [--levels coarse,medium] [--revolutions 10] [--jobs 2] [-o DIR]

Writes DIR/ERCOFTAC.md, DIR/ercoftac.csv and DIR/ercoftac.png (default study/ercoftac-pump):
c_u/U2 at R/R2 = 1.02 against the measured midspan and span average (the acceptance: within
5 %), the profiles' RMS across a pitch, the casing cp, cells and wall seconds per revolution of
both methods. Every run stays in DIR/runs/<level>-<method>/; a finished run is reused while the
case's inputs are unchanged (its postprocessing is redone, a few seconds); a run stopped before
its end continues from its last revolution (the penalized one's checkpoint, the body-fitted one's
fields)."""

import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys

import yaml

from fsi import ROOT, case_module, fsi_launch, pump_ami_run, study_pool
from fsi import ercoftac_pump as ecp
from fsi.pump_curve import files_digest

CASE = os.path.join(ROOT, "cases", "ercoftac-pump")
HERE = os.path.dirname(os.path.abspath(__file__))
LAUNCHER = os.path.join(HERE, "fsi_launch.py")
METHODS = ("penalized", "body-fitted")
# what a run's result depends on; generated files (meshes, geometry, logs, results) are not inputs
SKIPPED_DIRS = {"geometry", "output", "logs", "polyMesh", "postProcessing", "__pycache__"}
MODULES = ("ercoftac_pump.py", "ercoftac_mesh.py", "ercoftac_ami_run.py", "pump_ami_run.py", "foam_case.py")


say = fsi_launch.speaker("ercoftac-study")


def inputs_fingerprint():
    paths = []
    for root, dirs, files in os.walk(CASE):
        dirs[:] = sorted(d for d in dirs if d not in SKIPPED_DIRS)
        # the documentation and the postprocessing (redone on every call) are not a run's inputs
        paths += [os.path.join(root, n) for n in sorted(files)
                  if not n.startswith(".") and n != "postprocess.py" and not n.endswith(".md")]
    paths += [os.path.join(HERE, n) for n in MODULES]
    return files_digest(ROOT, paths)


class Run:
    def __init__(self, level, method, revolutions, out):
        self.level, self.method, self.revolutions = level, method, revolutions
        self.name = "%s-%s" % (level, method)
        self.out = os.path.join(out, "runs", self.name)
        self.result, self.error = None, None

    def end_time_s(self):
        return self.revolutions * 2 * math.pi / ecp.omega_rad_per_s()


def penalized_cost(out):
    """(cells, wall s per step): the mesh's cells (checkMesh) and the fluid's last mean step time
    (its progress line: the whole step of the fluid process, coupling included)."""
    with open(os.path.join(out, "openfoam", "logs", "log.checkMesh")) as f:
        cells = int(re.search(r"cells:\s+(\d+)", f.read()).group(1))
    with open(os.path.join(out, "fluid.log")) as f:
        steps = re.findall(r"([\d.]+) ms/step", f.read())
    if not steps:
        raise RuntimeError("%s/fluid.log: no progress line" % out)
    return cells, float(steps[-1]) / 1000.0


def run_one(run, args, fingerprint):
    stamp = os.path.join(run.out, "study.complete")
    started = os.path.join(run.out, "study.started")
    expected = "%s %s %d\n" % (fingerprint, run.name, run.revolutions)
    if os.path.exists(stamp) and open(stamp).read() == expected:
        say("%s: up to date, reused" % run.name)
    else:
        # A run of the same inputs that was stopped (a session's end, Ctrl-C) continues: the
        # penalized one from its newest checkpoint, the body-fitted one from its latest fields
        # (both written every revolution).
        same = os.path.exists(started) and open(started).read() == expected
        if run.method == "penalized":
            resumed = same and bool(glob.glob(os.path.join(run.out, "checkpoints", "step-*", "manifest.ckpt")))
        else:
            foam = os.path.join(run.out, "openfoam")
            latest = pump_ami_run.latest_time(foam, 1) if os.path.isdir(foam) else None
            resumed = same and latest is not None and float(latest) > 0
        if not resumed:
            if os.path.exists(run.out):
                shutil.rmtree(run.out)
            os.makedirs(run.out)
            with open(started, "w") as f:
                f.write(expected)
        say("%s: %s %d revolutions" % (run.name, "continuing to" if resumed else "running", run.revolutions))
        log_path = os.path.join(run.out, "study.log")
        if run.method == "penalized":
            period = 2 * math.pi / ecp.omega_rad_per_s()
            command = [sys.executable, LAUNCHER, "--bin-dir", args.bin_dir, "-o", run.out, "--resolution", run.level,
                       "--end-time", repr(run.end_time_s()), "--set", "run.checkpoint_interval_s=%.6g" % period]
            command += ["--restart", CASE] if resumed else [CASE]
        else:
            command = [sys.executable, os.path.join(HERE, "ercoftac_ami_run.py"), "--resolution", run.level,
                       "--end-time", repr(run.end_time_s()), "-o", run.out] + (["--restart"] if resumed else []) + [CASE]
        with open(log_path, "a" if resumed else "w") as log:
            code = subprocess.call(command, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                   env=fsi_launch.case_script_env())
        if code != 0:
            raise RuntimeError("%s: the run failed (exit %d): see %s" % (run.name, code, log_path))
        with open(stamp, "w") as f:
            f.write(expected)
    made = subprocess.run([sys.executable, os.path.join(CASE, "postprocess.py"), run.out, CASE],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=fsi_launch.case_script_env())
    if made.returncode != 0:
        raise RuntimeError("%s: postprocess.py failed: %s" % (run.name, made.stdout.decode()[-2000:]))
    with open(os.path.join(run.out, "impeller_outlet.yaml")) as f:
        result = yaml.safe_load(f)
    if run.method == "penalized":
        result["cells"], per_step = penalized_cost(run.out)
    else:
        with open(os.path.join(run.out, "cost.yaml")) as f:
            cost = yaml.safe_load(f)
        result["cells"], per_step = cost["cells"], cost["wall_s_per_step"]
    make_case = case_module("ercoftac-pump", "make_case")
    steps_per_revolution = 2 * math.pi / ecp.omega_rad_per_s() / make_case.time_step_s(make_case.LEVELS[run.level][0])
    result["wall_s_per_revolution"] = per_step * steps_per_revolution
    run.result = result
    say("%s: c_u/U2 %.4f, %.0f s per revolution" % (run.name, result["cu_over_u2"], result["wall_s_per_revolution"]))
    return run


def report(runs, out, measured, failed=()):
    lines = ["# The ERCOFTAC pump, both methods, against the measurement", "",
             "Generated by `./fsi ercoftac-study` (python/fsi/ercoftac_study.py); the case and the data: "
             "cases/ercoftac-pump/README.md. Each run from rest, averaged over its second half; c_u/U2 and c_r/U2 "
             "pitch-averaged at R/R2 = 1.02 (measured: c_u/U2 %.3f midspan, %.3f span average); profile RMS across "
             "a pitch at the one shift that fits c_u and c_r; casing cp RMS at one fitted shift and offset; "
             "the angular momentum the flow carries through R/R2 = 1.02 over the impeller's torque (1 when the "
             "torque is all the flow gets); wall seconds per revolution of each run on one core, as it ran (beside "
             "the study's other runs: compare costs from runs that ran side by side)." % (measured["cu_over_u2_midspan"],
                                                         measured["cu_over_u2_span_average"]), "",
             "| level | method | cells | c_u/U2 | vs midspan | vs span average | c_u/U2 c_r-weighted | c_r / continuity "
             "| profile RMS c_u, c_r "
             "| casing cp RMS | cp rise (measured %s) | angular momentum flux / torque | s per revolution |" % (
                 next(("%.3f" % r.result["casing"]["cp_rise_measured"][-1] for r in runs if "casing" in r.result), "-")),
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        res = r.result
        casing = res.get("casing")
        balance = res.get("angular_momentum")
        weighted = res.get("cu_over_u2_flux_weighted")
        lines.append("| %s | %s | %d | %.4f | %+.1f %% | %+.1f %% | %s | %.3f | %.3f, %.3f | %s | %s | %s | %.0f |" % (
            r.level, r.method, res["cells"], res["cu_over_u2"], 100 * res["cu_error_against_midspan"],
            100 * res["cu_error_against_span_average"], "%.4f" % weighted if weighted is not None else "-",
            res["cr_over_continuity"], res["cu_profile_rms_midspan"],
            res["cr_profile_rms_midspan"], "%.3f" % casing["cp_rms"] if casing else "-",
            "%.3f" % casing["cp_rise_ours"][-1] if casing else "-",
            "%.3f" % balance["flux_over_torque"] if balance else "-", res["wall_s_per_revolution"]))
    lines.append("")
    budgets = [(r, r.result["angular_momentum_by_radius"]) for r in runs if r.result.get("angular_momentum_by_radius")]
    if budgets:
        radii = [b["radius_m"] for b in budgets[0][1]]
        lines += ["Where the flow gets its angular momentum: the flux through circles of radius r over the impeller's "
                  "torque (1 where the torque is all the flow has got; inside the blades the probes in the blades "
                  "read no flux, and the sampling misses mass there, so compare the methods beyond R2 = 0.21 m).", "",
                  "| level | method | " + " | ".join("r = %.4g m" % r for r in radii) + " |",
                  "|---|---|" + "---|" * len(radii)]
        for r, budget in budgets:
            lines.append("| %s | %s | " % (r.level, r.method) +
                         " | ".join("%.3f" % b["flux_over_torque"] for b in budget) + " |")
        lines.append("")
    for level in sorted({r.level for r in runs}):
        pair = {r.method: r for r in runs if r.level == level}
        if len(pair) == 2:
            pen, ami = pair["penalized"].result, pair["body-fitted"].result
            weighted = ("" if "cu_over_u2_flux_weighted" not in pen or "cu_over_u2_flux_weighted" not in ami else
                        " (c_r-weighted %+.1f %%)" % (100 * (pen["cu_over_u2_flux_weighted"]
                                                             / ami["cu_over_u2_flux_weighted"] - 1)))
            lines.append("- %s: penalized against body-fitted c_u/U2 %+.1f %%%s; cost per revolution %.2f (cells %.2f)." % (
                level, 100 * (pen["cu_over_u2"] / ami["cu_over_u2"] - 1), weighted, ami["wall_s_per_revolution"]
                / pen["wall_s_per_revolution"], ami["cells"] / pen["cells"]))
    if failed:
        lines += ["", "## Failed runs", ""] + ["- %s: %s" % (r.name, r.error) for r in failed]
    lines.append("")
    with open(os.path.join(out, "ERCOFTAC.md"), "w") as f:
        f.write("\n".join(lines))
    with open(os.path.join(out, "ercoftac.csv"), "w") as f:
        f.write("level,method,cells,cu_over_u2,cr_over_u2,cr_over_continuity,cu_profile_rms,cr_profile_rms,"
                "casing_cp_rms,casing_cp_rise,torque_n_m,flux_over_torque,wall_s_per_revolution\n")
        for r in runs:
            res, casing, balance = r.result, r.result.get("casing"), r.result.get("angular_momentum")
            f.write("%s,%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%s,%s,%s,%s,%.1f\n" % (
                r.level, r.method, res["cells"], res["cu_over_u2"], res["cr_over_u2"], res["cr_over_continuity"],
                res["cu_profile_rms_midspan"], res["cr_profile_rms_midspan"],
                "%.6g" % casing["cp_rms"] if casing else "", "%.6g" % casing["cp_rise_ours"][-1] if casing else "",
                "%.6g" % balance["torque_n_m"] if balance else "", "%.6g" % balance["flux_over_torque"] if balance else "",
                res["wall_s_per_revolution"]))
    draw(runs, measured, os.path.join(out, "ercoftac.png"))
    return "\n".join(lines)


def draw(runs, measured, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    levels = sorted({r.level for r in runs}, key=lambda name: case_module("ercoftac-pump", "make_case").LEVELS[name][0],
                    reverse=True)
    fig, ax = plt.subplots(figsize=(6, 4))
    for method, marker in zip(METHODS, "os"):
        chosen = sorted((levels.index(r.level), r.result["cu_over_u2"]) for r in runs if r.method == method)
        ax.plot([c[0] for c in chosen], [c[1] for c in chosen], marker + "-", label=method)
    ax.axhline(measured["cu_over_u2_midspan"], color="k", ls="--", lw=1, label="measured, midspan")
    ax.axhline(measured["cu_over_u2_span_average"], color="grey", ls=":", lw=1, label="measured, span average")
    ax.axhspan(0.95 * measured["cu_over_u2_midspan"], 1.05 * measured["cu_over_u2_midspan"], color="k", alpha=0.08,
               label="midspan +- 5 %")
    ax.set_xticks(range(len(levels)))
    ax.set_xticklabels(levels)
    ax.set_ylabel("c_u / U2 at R/R2 = 1.02 (pitch average)")
    ax.set_title("ERCOFTAC pump: the work input by mesh level")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(prog="./fsi ercoftac-study", description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--levels", default="coarse,medium", help="mesh levels, comma-separated (default coarse,medium)")
    parser.add_argument("--revolutions", type=int, default=10)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("-o", dest="out", default=os.path.join(ROOT, "study", "ercoftac-pump"))
    args = parser.parse_args(argv)
    make_case = case_module("ercoftac-pump", "make_case")
    levels = [name for name in args.levels.split(",") if name]
    unknown = [name for name in levels if name not in make_case.LEVELS]
    if unknown or not levels:
        raise SystemExit("ercoftac-study: --levels %s: each one of %s" % (args.levels, ", ".join(make_case.LEVELS)))
    if args.revolutions < 2:
        raise SystemExit("ercoftac-study: --revolutions %d: at least 2 (the second half is averaged)" % args.revolutions)
    os.makedirs(args.out, exist_ok=True)
    try:
        for level in levels:     # the meshes once, before the runs share them
            fsi_launch.prepare_case(CASE, args.bin_dir, level)
    except fsi_launch.UserError as e:
        raise SystemExit("ercoftac-study: %s" % e)
    with open(os.path.join(CASE, "reference.yaml")) as f:
        measured = yaml.safe_load(f)["measured"]
    fingerprint = inputs_fingerprint()
    runs = [Run(level, method, args.revolutions, args.out) for level in levels for method in METHODS]
    failed = study_pool.run_all(runs, lambda r: run_one(r, args, fingerprint), args.jobs, say)
    print(report([r for r in runs if r.result is not None], args.out, measured, failed))
    if failed:
        raise SystemExit("ercoftac-study: %d run(s) failed: %s" % (len(failed), ", ".join(r.name for r in failed)))
    say("wrote %s/ERCOFTAC.md, ercoftac.csv, ercoftac.png" % args.out)


if __name__ == "__main__":
    main(sys.argv[1:])
