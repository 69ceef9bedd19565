#!/usr/bin/python3
"""./fsi pump-compare: the penalized impeller against the body-fitted (AMI) one at one flow rate,
as the credible-pump issue asks a fair comparison to be made: the same mesh (the penalized
impeller in the AMI reference's snappyHexMesh mesh, its rotor turning with it behind the same
AMI, preset <resolution>-turning-mesh, against openfoam-ami-<resolution>; --penalized-mesh fixed:
the impeller turning through that mesh held still, preset <resolution>-ami-mesh), the same history (both start from one settled state, the fields of a
pump-curve point), the same number of revolutions, averaged the same way (all revolutions but
the first, each revolution's mean with the standard error of their scatter), and stopped only
when the last three revolution means of head and torque drift by under 2 %.

    pump_compare.py --bin-dir BIN [--flow-fraction 1.0] [--revolutions 8] [--ranks 2]
                    [--resolution coarse] [--penalized-mesh turning|fixed] [--from OPENFOAM_CASE] [--set KEY=VALUE] [--summarize] [-o DIR]
                    CASE_DIR

--from: the settled state (default CASE_DIR/output/pump-curve/q<fraction>/openfoam, which
./fsi pump-curve writes). DIR (default CASE_DIR/output/pump-compare/q<fraction>, with -<resolution> after it for another
resolution than coarse, e.g. q1.00-coarse-fine-blade: the blade's cells 2 mm, and -fixed-mesh for --penalized-mesh fixed) gets ibm/ (the
penalized run, fsi_launch.py), ami/ (python/fsi/pump_ami_run.py), comparison.yaml (both points,
their differences and the issue's goals: head within 5 % at the design flow, 10 % at part load,
torque within 10 %), comparison.md (the table) and comparison.png (the revolution means, the
torque by part). The two runs go one after the other, each on --ranks MPI ranks: their wall
seconds per revolution are the cost ratio at (nearly) equal cells. A run already made with the
same inputs is reused; interrupted, or asked for more revolutions, the AMI run continues from its
last quarter revolution (pump_ami_run.py --restart) and the penalized one from its newest checkpoint
(every quarter revolution; ./fsi run --restart).
--set changes the penalized run only (a variant of the method against the same reference: give
it its own -o and link DIR/ami to the first comparison's, which is then reused). A run is
"the same" when case.yaml, pump.yaml and its own OpenFOAM folder (and preset) are (run_fingerprint);
--summarize writes the comparison again from the finished runs as they are, running nothing."""

import argparse
import fcntl
import glob
import json
import math
import os
import sys
import time

import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
from fsi import fsi_launch  # noqa: E402
from fsi import pump_ami_run  # noqa: E402
from fsi import pump_head_budget  # noqa: E402
from fsi import pump_point  # noqa: E402
from fsi import pump_curve  # noqa: E402
from fsi.pump_curve import flow_rate_assignment  # noqa: E402

LAUNCHER = os.path.join(HERE, "fsi_launch.py")
SURFACES_OF_REVOLUTION = ("hub", "shroud")   # the generated impeller's discs (its STL's regions)
AMI_RUN = os.path.join(HERE, "pump_ami_run.py")
DRIFT_LIMIT = 0.02      # the settling rule: the last 3 revolution means within 2 %
HEAD_GOAL = {"design": 0.05, "part load": 0.10}     # ISO 9906 class 2 at the BEP; part load
TORQUE_GOAL = 0.10
CHECKPOINTS_PER_REVOLUTION = 4   # the penalized run's (it resumes from the newest)
LOCKS = []              # the run folders' locks, held to the end of the process


say = fsi_launch.speaker("pump-compare")


def load_yaml(path):
    with open(path) as f:
        return yaml.safe_load(f)


def penalized_preset(args):
    """The penalized run's preset: <res>-turning-mesh (the impeller in the AMI mesh's rotor, turning
    with it) or <res>-ami-mesh (--penalized-mesh fixed: the impeller turning through the AMI
    mesh's cells, held still)."""
    return args.resolution + ("-turning-mesh" if args.penalized_mesh == "turning" else "-ami-mesh")


def run_fingerprint(case_dir, method, resolution, preset=None):
    """A hash of what one method's run is made of: case.yaml, pump.yaml and its OpenFOAM folder
    (the penalized run: presets/<preset>.yaml and openfoam-<preset>; the AMI run:
    openfoam-ami-<res>), links followed to the geometry they name. Other files of the case (another
    resolution's folders, a new preset, the scripts) do not make a finished run stale."""
    if method == "ibm":
        preset = preset or resolution + "-ami-mesh"
        inputs = [os.path.join("presets", preset + ".yaml"), "openfoam-" + preset]
    else:
        inputs = ["openfoam-ami-" + resolution]
    paths = []
    for top in ["case.yaml", "pump.yaml"] + inputs:
        path = os.path.join(case_dir, top)
        paths += [path] if os.path.isfile(path) else sorted(
            os.path.join(root, name) for root, _dirs, names in os.walk(path, followlinks=True) for name in names)
    return pump_curve.files_digest(case_dir, paths)


def run_inputs(args, method, flow_rate):
    """What makes a run: equal inputs, equal run (the end time aside, which the AMI run extends)."""
    inputs = {"method": method, "case": run_fingerprint(args.case_dir, method, args.resolution, penalized_preset(args)),
              "flow_rate_m3_per_s": flow_rate, "from": os.path.abspath(args.settled), "resolution": args.resolution,
              "ranks": args.ranks}
    if method == "ibm" and getattr(args, "assignments", None):
        inputs["set"] = list(args.assignments)
    return inputs


def read_stamp(folder):
    path = os.path.join(folder, "run.json")
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        return json.load(f)


def write_stamp(folder, inputs, end_time, wall_s):
    with open(os.path.join(folder, "run.json"), "w") as f:
        json.dump(dict(inputs, end_time_s=end_time, wall_s=wall_s), f, indent=1)


def run_logged(command, log_path):
    """Runs `command` with its output appended to log_path and its progress lines (ETA) echoed once
    a minute; returns the wall seconds. Exits with the log's last lines if it fails."""
    start = time.monotonic()
    last = [0.0]

    def echo(line):
        if "ETA" in line and time.monotonic() - last[0] > 60.0:
            say("  " + line.split("] ")[-1])
            last[0] = time.monotonic()

    code = pump_curve.run_logged(command, log_path, echo, append=True, env=fsi_launch.case_script_env())
    if code != 0:
        with open(log_path, "rb") as f:
            tail = f.read().decode("utf-8", "replace").strip().splitlines()[-5:]
        raise SystemExit("pump-compare: %s failed (exit %d); the end of %s:\n  %s"
                         % (os.path.basename(command[1]), code, log_path, "\n  ".join(tail)))
    return time.monotonic() - start


def run_method(args, method, flow_rate, end_time, period):
    """The run of one method in OUT/<method>, reused or extended when it can be. A lock on the
    folder (held until this process ends) refuses a second comparison on the same run (a
    variant's linked ami/ included) while it runs."""
    folder = os.path.join(args.output, method)
    os.makedirs(folder, exist_ok=True)
    lock = open(os.path.join(folder, ".pump-compare.lock"), "w")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        raise SystemExit("pump-compare: %s is in use by another pump-compare (its lock %s): wait for it to end"
                         % (os.path.realpath(folder), lock.name))
    LOCKS.append(lock)
    inputs = run_inputs(args, method, flow_rate)
    stamp = read_stamp(folder)
    same = stamp is not None and {k: stamp.get(k) for k in inputs} == inputs
    if same and abs(stamp["end_time_s"] - end_time) < 1e-9:
        say("%s: up to date (%s): reused" % (method, folder))
        return folder
    os.makedirs(folder, exist_ok=True)
    log = os.path.join(folder, "pump_compare.log")
    started_path = os.path.join(folder, "run.started.json")
    started = None
    if os.path.isfile(started_path):
        with open(started_path) as f:
            started = json.load(f)
    if method == "ami":
        command = [sys.executable, AMI_RUN, "--resolution", args.resolution, "--flow-rate", repr(flow_rate),
                   "--end-time", repr(end_time), "--ranks", str(args.ranks), "-o", folder, args.case_dir]
        # An interrupted run (or a finished one asked for more revolutions) of the same inputs
        # continues from its latest fields (every quarter revolution).
        latest = pump_ami_run.latest_time(os.path.join(folder, "openfoam"), args.ranks)
        if (same or started == inputs) and latest is not None and 0 < float(latest) < end_time:
            command.insert(2, "--restart")
            say("ami: continuing from t = %s s to %g s" % (latest, end_time))
        else:
            command += ["--initial-fields-from", args.settled]
    else:
        # Checkpointed every quarter revolution: an interrupted run (or a finished one asked for
        # more revolutions) of the same inputs continues from its newest checkpoint.
        command = [sys.executable, LAUNCHER, "--bin-dir", args.bin_dir, "-o", folder, "--preset",
                   penalized_preset(args), "--end-time", repr(end_time), "--set",
                   flow_rate_assignment(flow_rate), "--set", "fluid.openfoam.initial_fields_from=" + args.settled,
                   "--set", "fluid.openfoam.mpi_ranks=%d" % args.ranks,
                   "--set", "run.checkpoint_interval_s=%.6g" % (period / CHECKPOINTS_PER_REVOLUTION)]
        for assignment in args.assignments:
            command += ["--set", assignment]
        if (same or started == inputs) and glob.glob(os.path.join(folder, "checkpoints", "step-*", "manifest.ckpt")):
            command.append("--restart")
            say("ibm: continuing from its newest checkpoint to t = %g s" % end_time)
        command.append(args.case_dir)
    if os.path.exists(os.path.join(folder, "run.json")):
        os.remove(os.path.join(folder, "run.json"))
    with open(started_path, "w") as f:
        json.dump(inputs, f, indent=1)
    say("%s: running to t = %g s (%d ranks; log %s)" % (method, end_time, args.ranks, log))
    wall = run_logged(command, log)
    resumed = "--restart" in command
    write_stamp(folder, inputs, end_time, wall + (stamp["wall_s"] if same and (method == "ami" or resumed) else 0.0))
    return folder


def finished_run(args, method, end_time):
    """OUT/<method> for --summarize: a run that finished (its run.json) at least to end_time; told
    when its inputs are not the case's files of now."""
    folder = os.path.join(args.output, method)
    stamp = read_stamp(folder)
    if stamp is None:
        raise SystemExit("pump-compare: --summarize: %s has no finished run (no run.json); run without --summarize"
                         % folder)
    if stamp["end_time_s"] < end_time - 1e-9:
        raise SystemExit("pump-compare: --summarize: %s ran to t = %g s, not the %d revolutions' %g s; give "
                         "--revolutions of at most what it ran" % (folder, stamp["end_time_s"], args.revolutions,
                                                                   end_time))
    inputs = run_inputs(args, method, stamp["flow_rate_m3_per_s"])
    changed = sorted(k for k in inputs if stamp.get(k) != inputs[k])
    if changed:
        say("%s: summarized as it ran; made with other %s than the case's of now" % (method, ", ".join(changed)))
    return folder


def penalized_cost(folder, period):
    """(cells, wall s per revolution) of a penalized run: its fluid.log and timings.csv."""
    cells = None
    with open(os.path.join(folder, "fluid.log")) as f:
        for line in f:
            if "PIMPLE, " in line and " cells" in line:
                cells = int(line.split("PIMPLE, ")[1].split(" cells")[0])
    data = np.loadtxt(os.path.join(folder, "timings.csv"), delimiter=",", skiprows=1, ndmin=2)
    dt = float(np.median(np.diff(data[:, 0])))
    per_step = float(np.mean(data[min(5, len(data) - 1):, 1:].sum(axis=1)))
    return cells, per_step * period / dt


def summary(folder, design, omega, axis, flow_rate, revolutions):
    """The operating point over all revolutions but the first, with the leak through the front
    side space: averaged over the same revolutions from the face flux through a front seal's ring
    (front_seal.py) or else the stations' function objects (pump_stations.py) when the run has
    them, else from its last fields (pump_head_budget)."""
    point = pump_point.operating_point(folder, omega, axis, 0.5 * design["impeller"]["outer_diameter_m"],
                                       flow_rate, average_revolutions=revolutions, settle_revolutions=1)
    if "front_seal_leak_m3_per_s" in point:   # the face flux through the seal's ring: both methods alike
        point["front_side_space_leak_m3_per_s"] = point["front_seal_leak_m3_per_s"]
        point["front_side_space_leak_from"] = "seal faces"
        return point
    if point.get("stations"):
        leak = {row["station"]: row for row in point["stations"]}["front_side_space"]["flow_rate_m3_per_s"]
        point["front_side_space_leak_m3_per_s"], point["front_side_space_leak_from"] = leak, "window"
        return point
    foam_case = os.path.join(folder, "openfoam")
    try:
        pump_head_budget.latest_time(foam_case)
    except ValueError:   # a run on MPI ranks: its last fields are in processor*/
        pump_ami_run.run_tool("reconstructPar", foam_case, folder, ["-latestTime"])
    rows = pump_head_budget.head_budget(foam_case, design)
    stations = {row["station"]: row for row in rows}
    point["front_side_space_leak_m3_per_s"] = stations["front side space"]["flow_rate_m3_per_s"]
    point["front_side_space_leak_from"] = "last fields"
    return point


def compare(args, points, fraction, costs):
    ibm, ami = points["ibm"], points["ami"]
    regime = "design" if abs(fraction - 1.0) < 0.05 else "part load"

    def rel(key):
        return (ibm[key] - ami[key]) / abs(ami[key])

    def combined_error(key, error_key):
        return math.hypot(ibm[error_key] or 0.0, ami[error_key] or 0.0) / abs(ami[key])

    head, torque = rel("head_m"), rel("shaft_torque_n_m")
    settled = all((p[k] is not None and p[k] < DRIFT_LIMIT) for p in points.values()
                  for k in ("head_drift_last_3_revolutions", "torque_drift_last_3_revolutions"))
    parts = sorted(set(ibm.get("torque_by_part_n_m", {})) & set(ami.get("torque_by_part_n_m", {})))
    # A smooth surface of revolution turning about its axis takes no torque from the pressure;
    # what the body-fitted discs take is the roughness of their snapped, faceted surfaces.
    pressure = ami.get("pressure_torque_by_part_n_m") or {}
    discs = {p: pressure[p] for p in SURFACES_OF_REVOLUTION if p in pressure}
    return {
        "flow_fraction_of_design": fraction,
        "regime": regime,
        "settled_last_3_revolutions_within_2_percent": settled,
        "head_difference": head,
        "head_difference_standard_error": combined_error("head_m", "head_standard_error_m"),
        "head_goal": HEAD_GOAL[regime],
        "head_within_goal": abs(head) <= HEAD_GOAL[regime],
        "torque_difference": torque,
        "torque_difference_standard_error": combined_error("shaft_torque_n_m", "torque_standard_error_n_m"),
        "torque_goal": TORQUE_GOAL,
        "torque_within_goal": abs(torque) <= TORQUE_GOAL,
        "efficiency_ibm": ibm["efficiency"], "efficiency_ami": ami["efficiency"],
        "torque_by_part_n_m": {p: {"ibm": ibm["torque_by_part_n_m"][p], "ami": ami["torque_by_part_n_m"][p]}
                               for p in parts},
        "cost": costs,
        "ami_pressure_torque_on_surfaces_of_revolution_n_m": discs or None,
    }


def table(points, result):
    ibm, ami = points["ibm"], points["ami"]
    c = result["cost"]
    rows = [
        "| | penalized (ours) | AMI (stock pimpleFoam) | difference |",
        "|---|---|---|---|",
        "| head H (m) | %.3f +- %.3f | %.3f +- %.3f | %+.1f +- %.1f %% (goal %.0f %%) |" % (
            ibm["head_m"], ibm["head_standard_error_m"], ami["head_m"], ami["head_standard_error_m"],
            100 * result["head_difference"], 100 * result["head_difference_standard_error"], 100 * result["head_goal"]),
        "| shaft torque T (N m) | %.2f +- %.2f | %.2f +- %.2f | %+.1f +- %.1f %% (goal %.0f %%) |" % (
            ibm["shaft_torque_n_m"], ibm["torque_standard_error_n_m"], ami["shaft_torque_n_m"],
            ami["torque_standard_error_n_m"], 100 * result["torque_difference"],
            100 * result["torque_difference_standard_error"], 100 * result["torque_goal"]),
        "| efficiency | %.3f | %.3f | |" % (ibm["efficiency"], ami["efficiency"]),
        "| head drift, last 3 revolutions | %.1f %% | %.1f %% | rule: under 2 %% |" % (
            100 * ibm["head_drift_last_3_revolutions"], 100 * ami["head_drift_last_3_revolutions"]),
        "| torque drift, last 3 revolutions | %.1f %% | %.1f %% | rule: under 2 %% |" % (
            100 * ibm["torque_drift_last_3_revolutions"], 100 * ami["torque_drift_last_3_revolutions"]),
        "| front side space leak (L/s; %s, %s) | %.2f | %.2f | |" % (
            ibm["front_side_space_leak_from"], ami["front_side_space_leak_from"],
            1e3 * ibm["front_side_space_leak_m3_per_s"], 1e3 * ami["front_side_space_leak_m3_per_s"]),
        "| once-per-revolution torque pulsation | %.3f | %.3f | |" % (
            ibm["torque_pulsation_1_per_rev"], ami["torque_pulsation_1_per_rev"]),
        "| cells | %s | %s | |" % (c["ibm"]["cells"], c["ami"]["cells"]),
        "| wall s per revolution (%d ranks) | %.0f | %.0f | AMI / penalized %.2f |" % (
            c["ranks"], c["ibm"]["wall_s_per_revolution"], c["ami"]["wall_s_per_revolution"],
            c["ami"]["wall_s_per_revolution"] / c["ibm"]["wall_s_per_revolution"]),
    ]
    if ibm.get("stations") and ami.get("stations"):
        for a, b in zip(ibm["stations"], ami["stations"]):
            rows.append("| %s: flow rate (L/s), head above the suction pipe (m) | %.2f, %.2f | %.2f, %.2f | |" % (
                a["station"].replace("_", " "), 1e3 * a["flow_rate_m3_per_s"], a["head_above_suction_m"],
                1e3 * b["flow_rate_m3_per_s"], b["head_above_suction_m"]))
    if ibm.get("rotor") and ami.get("rotor"):
        a, b = ibm["rotor"], ami["rotor"]
        rows.append("| energy flux out of the rotor's water (W) | %.0f | %.0f | %+.0f W |" % (
            a["energy_flux_out_w"], b["energy_flux_out_w"], a["energy_flux_out_w"] - b["energy_flux_out_w"]))
        rows.append("| lost in the rotor's water: shaft power less that flux (W, fraction of the shaft power) | "
                    "%.0f (%.2f) | %.0f (%.2f) | %+.0f W |" % (a["loss_w"], a["loss_fraction"], b["loss_w"],
                                                              b["loss_fraction"], a["loss_w"] - b["loss_w"]))
    steps = ibm.get("staircase_torque_by_part_n_m") or {}
    for part, v in result["torque_by_part_n_m"].items():
        rows.append("| torque on %s (N m) | %.2f%s | %.2f | %+.2f N m |" % (
            part, v["ibm"], " (steps %.2f)" % steps[part] if part in steps else "", v["ami"], v["ibm"] - v["ami"]))
    if steps:
        rows.append("| torque of the pressure on the penalized staircase's steps, off the surface (N m; "
                    "parts_staircase.csv, a smooth surface takes none) | %.2f | | |" % sum(steps.values()))
    discs = result.get("ami_pressure_torque_on_surfaces_of_revolution_n_m")
    if discs:
        rows.append("| pressure torque on the AMI's surfaces of revolution (%s; none on a smooth one: the snapped "
                    "mesh's roughness) (N m) | | %.2f | AMI torque without it: %.2f N m |" % (
                        ", ".join(discs), sum(discs.values()), ami["shaft_torque_n_m"] - sum(discs.values())))
    return "\n".join(rows) + "\n"


def picture(points, result, omega, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    labels = {"ibm": "penalized (ours)", "ami": "AMI (body-fitted)"}
    for method, p in points.items():
        n = len(p["revolution_head_m"])
        rev = np.arange(p["revolutions_run"] - n + 1, p["revolutions_run"] + 1)
        for ax, key, mean, err in ((axes[0], "revolution_head_m", "head_m", "head_standard_error_m"),
                                   (axes[1], "revolution_torque_n_m", "shaft_torque_n_m", "torque_standard_error_n_m")):
            line, = ax.plot(rev, p[key], "o-", label=labels[method])
            ax.axhline(p[mean], color=line.get_color(), lw=0.8)
            ax.axhspan(p[mean] - p[err], p[mean] + p[err], color=line.get_color(), alpha=0.15)
    axes[0].set(xlabel="revolution", ylabel="head H (m)", title="head, revolution means (band: +- standard error)")
    axes[1].set(xlabel="revolution", ylabel="shaft torque T (N m)", title="torque, revolution means")
    parts = list(result["torque_by_part_n_m"])
    x = np.arange(len(parts))
    for k, method in enumerate(("ibm", "ami")):
        axes[2].bar(x + (k - 0.5) * 0.4, [result["torque_by_part_n_m"][q][method] for q in parts], 0.4,
                    label=labels[method])
    axes[2].set_xticks(x)
    axes[2].set_xticklabels(parts, rotation=30, ha="right")
    axes[2].axhline(0, color="k", lw=0.6)
    axes[2].set(ylabel="torque (N m)", title="torque by part (the shaft's share)")
    for ax in axes:
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle("Q = %.3g L/s: head %+.1f %%, torque %+.1f %% (penalized vs AMI)" % (
        1e3 * points["ami"]["flow_rate_m3_per_s"], 100 * result["head_difference"], 100 * result["torque_difference"]))
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--flow-fraction", type=float, default=1.0, help="of the design flow rate (pump.yaml)")
    parser.add_argument("--revolutions", type=int, default=8, help="each method's, from the settled state (>= 4)")
    parser.add_argument("--ranks", type=int, default=2, help="MPI ranks of each run (they run one after the other)")
    parser.add_argument("--resolution", default="coarse")
    parser.add_argument("--penalized-mesh", choices=("turning", "fixed"), default="turning",
                        help="the penalized impeller in the AMI mesh's rotor turning with it (default), or turning "
                             "through its cells held still (the cells it switches: docs/model.md)")
    parser.add_argument("--from", dest="settled", default="", help="the settled state: an OpenFOAM case whose latest "
                        "fields start both runs (default: CASE_DIR/output/pump-curve/q<fraction>/openfoam)")
    parser.add_argument("--set", metavar="KEY=VALUE", dest="assignments", action="append", default=[],
                        help="a key of the penalized run (e.g. fluid.openfoam.immersed_wall_model=spalding; "
                             "repeatable); the AMI run is the same with or without")
    parser.add_argument("--summarize", action="store_true",
                        help="only write the comparison again from the two finished runs in DIR, as they are "
                             "(whatever the case's files are now): nothing runs")
    parser.add_argument("-o", "--output", default="")
    parser.add_argument("case_dir")
    args = parser.parse_args(argv)
    args.case_dir = os.path.abspath(args.case_dir)
    for name in ("pump.yaml", "case.yaml"):
        if not os.path.isfile(os.path.join(args.case_dir, name)):
            raise SystemExit("pump-compare: %s has no %s: give a pump case folder (cases/centrifugal-pump)"
                             % (args.case_dir, name))
    if args.revolutions < 4:
        raise SystemExit("pump-compare: --revolutions %d: at least 4 (one to settle, three for the drift rule)"
                         % args.revolutions)
    preset = os.path.join(args.case_dir, "presets", penalized_preset(args) + ".yaml")
    if not os.path.isfile(preset):
        raise SystemExit("pump-compare: --resolution %s --penalized-mesh %s: %s does not exist (the penalized "
                         "impeller on the AMI mesh; make_ami_case.py writes the coarse one)"
                         % (args.resolution, args.penalized_mesh, preset))
    tag = "q%.2f" % args.flow_fraction
    args.settled = os.path.abspath(args.settled or os.path.join(args.case_dir, "output", "pump-curve", tag, "openfoam"))
    if not os.path.isdir(args.settled):
        raise SystemExit("pump-compare: the settled state %s does not exist: run ./fsi pump-curve --points %g %s "
                         "first, or give --from" % (args.settled, args.flow_fraction, args.case_dir))
    # One folder per flow rate and mesh: another resolution never takes over a finished pair's runs.
    folder = (tag if args.resolution == "coarse" else "%s-%s" % (tag, args.resolution)) + (
        "" if args.penalized_mesh == "turning" else "-fixed-mesh")
    args.output = os.path.abspath(args.output or os.path.join(args.case_dir, "output", "pump-compare", folder))
    os.makedirs(args.output, exist_ok=True)
    design = load_yaml(os.path.join(args.case_dir, "pump.yaml"))
    flow_rate = args.flow_fraction * float(design["operation"]["design_flow_rate_m3_per_s"])
    omega, axis = pump_point.rotation(args.case_dir, "pump-compare")
    period = 2 * math.pi / omega
    # The whole revolutions, rounded up to 0.1 ms: the last one is in the averaging window.
    end_time = math.ceil(args.revolutions * period * 1e4 - 1e-3) / 1e4
    if args.summarize:
        folders = {m: finished_run(args, m, end_time) for m in ("ibm", "ami")}
    else:
        folders = {m: run_method(args, m, flow_rate, end_time, period) for m in ("ibm", "ami")}
    points = {m: summary(folders[m], design, omega, axis, flow_rate, args.revolutions) for m in folders}
    ami_cost = load_yaml(os.path.join(folders["ami"], "cost.yaml"))
    ibm_cells, ibm_per_rev = penalized_cost(folders["ibm"], period)
    costs = {"ranks": args.ranks,
             "ibm": {"cells": ibm_cells, "wall_s_per_revolution": ibm_per_rev},
             "ami": {"cells": ami_cost["cells"], "wall_s_per_revolution": ami_cost["wall_s_per_revolution"]}}
    result = compare(args, points, args.flow_fraction, costs)
    with open(os.path.join(args.output, "comparison.yaml"), "w") as f:
        f.write("# ./fsi pump-compare: the penalized impeller against the AMI one, same mesh and history (SI).\n")
        yaml.safe_dump({"comparison": result, "ibm": points["ibm"], "ami": points["ami"]}, f, sort_keys=False)
    text = table(points, result)
    with open(os.path.join(args.output, "comparison.md"), "w") as f:
        f.write(text)
    picture(points, result, omega, os.path.join(args.output, "comparison.png"))
    sys.stdout.write(text)
    if not result["settled_last_3_revolutions_within_2_percent"]:
        say("not settled: a last-3-revolution drift is over 2 %%; run again with --revolutions %d"
            % (args.revolutions + 2))
    say("written: %s/comparison.{yaml,md,png}" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
