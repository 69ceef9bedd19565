#!/usr/bin/python3
"""./fsi pump-curve: the performance curve of a pump case (cases/centrifugal-pump): the same
case run at several flow rates, each point independent and averaged over its last whole
revolutions (python/fsi/pump_point.py), written to pump_curve.csv and drawn in pump_curve.png (H/H_BEP
and T/T_BEP against Q/Q_BEP, as the paper's Figs. 10-11, the efficiency on a second axis).

    pump_curve.py --bin-dir BIN [--points 0.36,0.6,0.8,1.0,1.2] [--method ibm|ami|both] [--jobs N] [--resolution NAME]
                  [--end-time S] [-o DIR] CASE_DIR

Each point is a copy of the case folder run by fsi_launch.py at its flow rate, the fraction of
the design flow rate (pump.yaml) given as --set fluid.openfoam.operating_point.flow_rate_m3_per_s,
in DIR/q<fraction>/ (the run) and DIR/q<fraction>/case (the copy). Points run in parallel, up to
--jobs at once (default: the cores, over the fluid's MPI ranks); the first one meshes and the
others start once its mesh is in the mesh cache. Progress with ETA on stderr; a failed point is
reported and the curve drawn with the others. A point already run with the same case files,
flow rate and options (DIR/q<fraction>/run.complete) is not run again: its results are reused.
--method ami runs the reference instead, --method both both of them: the same geometry meshed
body-fitted with the impeller in a rotating zone behind an AMI, by stock pimpleFoam
(python/fsi/pump_ami_run.py, in DIR/ami-q<fraction>/), the same averaging; the picture then shows
both curves scaled by the reference's BEP and the log the differences point by point.
"""

import argparse
import concurrent.futures
import csv
import hashlib
import math
import os
import re
import shutil
import subprocess
import sys
import threading
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
from fsi import case_copy, fsi_launch  # noqa: E402

LAUNCHER = os.path.join(HERE, "fsi_launch.py")
AMI_RUN = os.path.join(HERE, "pump_ami_run.py")
PROGRESS = re.compile(r"flow: t = ([0-9.eE+-]+) of ([0-9.eE+-]+) s.*ETA (.*)$")


say = fsi_launch.speaker("pump-curve")


METHODS = {"ibm": "penalized IBM (ours)", "ami": "body-fitted AMI (stock pimpleFoam)"}


class Point:
    def __init__(self, fraction, design_q, out, method):
        self.fraction = fraction
        self.method = method
        self.flow_rate = fraction * design_q
        self.name = ("q%.2f" if method == "ibm" else "ami-q%.2f") % fraction
        self.folder = os.path.join(out, self.name)
        self.case = os.path.join(self.folder, "case")
        self.progress = 0.0
        self.eta = ""
        self.state = "waiting"
        self.result = None
        self.error = None
        self.started = None
        self.meshed = threading.Event()


FLOW_RATE_KEY = "fluid.openfoam.operating_point.flow_rate_m3_per_s"


def copy_case(case_dir, point):
    """The case folder without its results (its flow rate is set on the command line), nor the
    study's own folder (the parent of the point's) when that lies inside the case."""
    if os.path.exists(point.case):
        shutil.rmtree(point.case)
    shutil.copytree(case_dir, point.case, symlinks=True,
                    ignore=case_copy.ignore_results([os.path.dirname(point.folder)]))


def flow_rate_assignment(flow_rate):
    """The launcher's --set of a run at `flow_rate` (m^3/s)."""
    return "%s=%r" % (FLOW_RATE_KEY, float(flow_rate))


def files_digest(base, paths):
    """A short hash of the files' paths (relative to base) and contents, in the order given."""
    digest = hashlib.sha256()
    for path in paths:
        digest.update(os.path.relpath(path, base).encode() + b"\0")
        with open(path, "rb") as f:
            digest.update(f.read())
    return digest.hexdigest()[:16]


def case_fingerprint(case_dir, out):
    """A hash of every file of the case folder but its results (output/ and the study's folder
    `out`, which may lie inside it) and logs: a point reruns when it changes."""
    # the generator's log (its timings) and its lock are not the case
    return files_digest(case_dir, case_copy.case_files(case_dir, [out], skipped_files=("generate.log", ".geometry.lock")))


def postprocess(args, point):
    """The case's own postprocess.py (the source case's: the copy's relative imports would not
    resolve) on the point's results, with this folder on PYTHONPATH (the source case may itself
    be a copy away from the repository)."""
    made = subprocess.run([sys.executable, os.path.join(args.case_dir, "postprocess.py"), point.folder, point.case],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=fsi_launch.case_script_env())
    if made.returncode != 0:
        lines = made.stdout.decode().strip().splitlines() or ["(no output)"]
        point.state, point.error = "failed", "postprocess: %s" % lines[-1]
        return
    with open(os.path.join(point.folder, "operating_point.yaml")) as f:
        point.result = yaml.safe_load(f)
    ran_at = point.result.get("flow_rate_m3_per_s")
    if ran_at is None or abs(ran_at - point.flow_rate) > 1e-9 * point.flow_rate:
        point.state, point.error = "failed", ("ran at Q = %s m^3/s instead of this point's %r m^3/s (the flow rate of its "
                                              "config.effective.yaml is not the one --set gave)" % (ran_at, point.flow_rate))
        return
    point.state = "done"


def launcher_command(args, out, case, flow_rate):
    """fsi_launch.py on a copy of the case into `out` at `flow_rate` (m^3/s), with the run's
    preset and end time (also ./fsi rag-ensemble's members)."""
    command = [sys.executable, LAUNCHER, "--bin-dir", args.bin_dir, "-o", out, "--set", flow_rate_assignment(flow_rate)]
    if args.resolution:
        command += ["--resolution", args.resolution]
    if args.end_time:
        command += ["--end-time", str(args.end_time)]
    return command + [case]


RUNNING = set()   # the processes run_logged is running (a study forwards a SIGTERM to them)


def run_logged(command, log_path, on_line, append=False, env=None):
    """Runs `command`, its output into `log_path` (appended to with `append`), each line of its
    stderr also to on_line (the progress); returns the exit code. The process is in RUNNING
    while it runs."""
    with open(log_path, "ab" if append else "wb") as log:
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.PIPE, env=env)
        RUNNING.add(process)
        try:
            for raw in iter(process.stderr.readline, b""):
                log.write(raw)
                on_line(raw.decode("utf-8", "replace").rstrip())
            return process.wait()
        finally:
            RUNNING.discard(process)


def run_point(args, point):
    stamp_file = os.path.join(point.folder, "run.complete")
    stamp = "%s q=%r resolution=%s end=%r\n" % (args.fingerprint, point.flow_rate, args.resolution, args.end_time)
    if os.path.exists(stamp_file) and open(stamp_file).read() == stamp and os.path.isdir(point.case):
        point.meshed.set()
        say("%s: up to date (same case, flow rate and run): reused" % point.name)
        if point.method == "ibm":
            postprocess(args, point)
        else:
            with open(os.path.join(point.folder, "operating_point.yaml")) as f:
                point.result = yaml.safe_load(f)
            point.state = "done"
        return
    if os.path.exists(stamp_file):
        os.remove(stamp_file)
    if point.method == "ibm":
        copy_case(args.case_dir, point)
        command = launcher_command(args, point.folder, point.case, point.flow_rate)
    else:  # the reference: python/fsi/pump_ami_run.py on the case's openfoam-ami-<resolution>
        os.makedirs(point.folder, exist_ok=True)
        point.case = args.case_dir
        command = [sys.executable, AMI_RUN, "--resolution", args.resolution or "coarse", "--flow-rate",
                   repr(point.flow_rate), "--end-time", repr(args.end_time or args.case_end_time), "-o", point.folder,
                   args.case_dir]
    point.state, point.started = "running", time.monotonic()
    def on_line(line):
        if "flow alone (no structure)" in line or "pimpleFoam from t =" in line:
            point.meshed.set()
        match = PROGRESS.search(line)
        if match:
            point.progress = float(match.group(1)) / float(match.group(2))
            point.eta = match.group(3)

    code = run_logged(command, os.path.join(point.folder, "pump_curve.log"), on_line)
    point.meshed.set()
    if code != 0:
        point.state, point.error = "failed", "exit code %d (log: %s)" % (code, os.path.join(point.folder, "pump_curve.log"))
        return
    with open(stamp_file, "w") as f:
        f.write(stamp)
    if point.method == "ibm":
        postprocess(args, point)
    else:  # pump_ami_run.py wrote it
        with open(os.path.join(point.folder, "operating_point.yaml")) as f:
            point.result = yaml.safe_load(f)
        point.state = "done"


def report_progress(points, stop):
    while not stop.wait(15.0):
        running = [p for p in points if p.state == "running"]
        done = sum(p.state in ("done", "failed") for p in points)
        say("%d/%d points done; %s" % (done, len(points), ", ".join(
            "%s %.0f %% (ETA %s)" % (p.name, 100 * p.progress, p.eta or "?") for p in running) or "starting"))


def write_csv(points, path):
    keys = ["method", "fraction_of_design", "flow_rate_m3_per_s", "head_m", "shaft_torque_n_m", "efficiency",
            "head_coefficient_psi", "flow_coefficient_phi", "torque_pulsation_1_per_rev",
            "head_pulsation_1_per_rev", "head_pulsation_amplitude_m", "revolutions_averaged"]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for p in points:
            if p.result:
                w.writerow([p.method, p.fraction] + [p.result[k] for k in keys[2:]])


def plausibility(points, method):
    """The checks of issue 11 that a single curve can tell, as lines of text."""
    done = [p for p in points if p.result and p.method == method]
    if len(done) < 3:
        return ["%s: fewer than 3 points, no curve checks" % method]
    q = [p.flow_rate for p in done]
    h = [p.result["head_m"] for p in done]
    t = [p.result["shaft_torque_n_m"] for p in done]
    eta = [p.result["efficiency"] for p in done]
    bep = max(range(len(done)), key=lambda i: eta[i])
    import numpy as np
    fit = np.polyfit(q, h, 2)
    lines = [
        method + ": BEP at %.3g Q_design: psi = %.3f (band 0.3-0.5), eta = %.2f (band 0.5-0.8)"
        % (done[bep].fraction, done[bep].result["head_coefficient_psi"], eta[bep]),
        method + ": shut-off head (quadratic fit to Q = 0) / H_BEP = %.2f (band 1.2-1.4)" % (np.polyval(fit, 0.0) / h[bep]),
        method + ": head falls with Q: %s; torque rises with Q: %s" % (
            all(b < a for a, b in zip(h, h[1:])), all(b > a for a, b in zip(t, t[1:]))),
    ]
    return lines


def best_point_duty(points, method, design):
    """The best point's duty against a single-channel waste-water pump's (issue 30: n_q 56 +- 5,
    psi_G = 2 g H / u2^2 >= 0.6, eta >= 0.6), and the swirl it leaves, c_u2 r2 = T / (rho Q) (the
    shaft torque's angular momentum, disc friction included): what the volute is sized for."""
    done = [p for p in points if p.result and p.method == method]
    if not done:
        return None, []
    bep = max(done, key=lambda p: p.result["efficiency"])
    omega = float(design["operation"]["rotation_rate_rad_per_s"])
    u2 = omega * 0.5 * float(design["impeller"]["outer_diameter_m"])
    q, h, t = bep.flow_rate, bep.result["head_m"], bep.result["shaft_torque_n_m"]
    swirl = t / (1000.0 * q)
    lines = []
    if h > 0:
        n_q = omega * 30.0 / math.pi * math.sqrt(q) / h ** 0.75
        lines.append(method + ": BEP Q = %.4g L/s, H = %.3g m: n_q = %.1f (56 +- 5), psi_G = 2 g H / u2^2 = %.3f "
                     "(>= 0.6), eta = %.2f (>= 0.6)" % (1e3 * q, h, n_q, 2 * 9.81 * h / u2 ** 2,
                                                      bep.result["efficiency"]))
    lines.append(method + ": swirl at the BEP c_u2 r2 = T / (rho Q) = %.4g m^2/s (the volute's design_swirl_m2_per_s)"
                 % swirl)
    return (q, swirl), lines


def with_operation(text, values):
    """pump.yaml's text with keys of its operation section set (replaced, or added at its end)."""
    lines = text.splitlines()
    start = next((i for i, line in enumerate(lines) if line.rstrip() == "operation:"), None)
    if start is None:
        lines.append("operation:")
        start = len(lines) - 1
    end = start + 1
    while end < len(lines) and (lines[end].startswith(" ") or not lines[end].strip()):
        end += 1
    for key, value in values.items():
        entry = "  %s: %s" % (key, value)
        found = [i for i in range(start + 1, end) if lines[i].split(":")[0].strip() == key]
        if found:
            lines[found[0]] = entry
        else:
            lines.insert(end, entry)
            end += 1
    return "\n".join(lines) + "\n"


def comparison(points):
    """The penalized IBM against the AMI reference, point by point (relative differences)."""
    ami = {p.fraction: p for p in points if p.method == "ami" and p.result}
    lines = []
    for p in points:
        if p.method == "ibm" and p.result and p.fraction in ami:
            ref = ami[p.fraction].result
            lines.append("Q = %.3g Q_design: H %.3g m vs AMI %.3g m (%+.1f %%), T %.3g vs %.3g N m (%+.1f %%)" % (
                p.fraction, p.result["head_m"], ref["head_m"], 100 * (p.result["head_m"] / ref["head_m"] - 1),
                p.result["shaft_torque_n_m"], ref["shaft_torque_n_m"],
                100 * (p.result["shaft_torque_n_m"] / ref["shaft_torque_n_m"] - 1)))
            ours, theirs = p.result.get("torque_by_part_n_m"), ref.get("torque_by_part_n_m")
            if ours and theirs:
                lines.append("  torque by part (N m, ours vs AMI): " + ", ".join(
                    "%s %.3g vs %.3g" % (part, ours[part], theirs[part]) for part in sorted(ours) if part in theirs))
    return lines


def draw(points, path, title):
    """H/H_BEP and T/T_BEP against Q/Q_BEP per method, scaled by the reference's BEP (AMI when it
    ran, else the method's own), efficiency on the right axis."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    done = [p for p in points if p.result]
    if not done:
        return
    methods = [m for m in METHODS if any(p.method == m for p in done)]
    scale_method = "ami" if "ami" in methods else methods[0]
    bep = max((p for p in done if p.method == scale_method), key=lambda p: p.result["efficiency"])
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    right = ax.twinx()
    for k, method in enumerate(methods):
        pts = sorted((p for p in done if p.method == method), key=lambda p: p.flow_rate)
        q = [p.flow_rate / bep.flow_rate for p in pts]
        style = "-" if method == "ibm" else ":"
        ax.plot(q, [p.result["head_m"] / bep.result["head_m"] for p in pts], "o" + style, color="C0",
                label="H / H_BEP, " + METHODS[method])
        ax.plot(q, [p.result["shaft_torque_n_m"] / bep.result["shaft_torque_n_m"] for p in pts], "s" + style,
                color="C1", label="T / T_BEP, " + METHODS[method])
        right.plot(q, [p.result["efficiency"] for p in pts], "^" + style, color="C2", label="efficiency, " + method)
    ax.set_xlabel("Q / Q_BEP (Q_BEP = %.3g L/s, %s)" % (1e3 * bep.flow_rate, scale_method))
    ax.set_ylabel("H / H_BEP, T / T_BEP (H_BEP = %.3g m, T_BEP = %.3g N m)"
                  % (bep.result["head_m"], bep.result["shaft_torque_n_m"]))
    ax.grid(alpha=0.3)
    right.set_ylabel("efficiency rho g Q H / (T omega)")
    right.set_ylim(0, 1)
    lines = ax.get_legend_handles_labels()
    more = right.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], loc="lower left", fontsize=7)
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(prog="./fsi pump-curve", description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--points", default="0.36,0.6,0.8,1.0,1.2",
                        help="flow rates as fractions of the design flow rate (pump.yaml), comma-separated")
    parser.add_argument("--jobs", type=int, default=0, help="points at once (default: cores / MPI ranks)")
    parser.add_argument("--resolution", default="", help="a preset of the case (coarse, medium, fine, rans)")
    parser.add_argument("--end-time", type=float, default=0.0, help="stop each point at this time (s)")
    parser.add_argument("--method", choices=["ibm", "ami", "both"], default="ibm",
                        help="ibm: the penalized impeller (ours); ami: the body-fitted sliding-mesh reference "
                             "(stock pimpleFoam, openfoam-ami-<resolution>); both")
    parser.add_argument("-o", "--output", default="", help="results folder (default CASE/output/pump-curve)")
    parser.add_argument("case_dir")
    args = parser.parse_args(argv)
    args.case_dir = os.path.abspath(args.case_dir)
    design_file = os.path.join(args.case_dir, "pump.yaml")
    if not os.path.isfile(design_file):
        raise SystemExit("pump-curve: %s not found: a pump case holds its design file pump.yaml" % design_file)
    try:
        fractions = [float(v) for v in args.points.split(",") if v.strip()]
    except ValueError:
        raise SystemExit("pump-curve: --points %s: expected comma-separated numbers, e.g. 0.36,0.6,0.8,1.0,1.2"
                         % args.points)
    if not fractions or min(fractions) <= 0:
        raise SystemExit("pump-curve: --points %s: fractions must be > 0" % args.points)
    with open(design_file) as f:
        design_q = float(yaml.safe_load(f)["operation"]["design_flow_rate_m3_per_s"])
    try:  # the case's generated inputs (the pump's geometry) before the points copy the case
        fsi_launch.prepare_case(args.case_dir, args.bin_dir)
    except fsi_launch.UserError as e:
        raise SystemExit("pump-curve: %s" % e)
    plan = subprocess.run([sys.executable, LAUNCHER, "--bin-dir", args.bin_dir, "--print-output-dir"]
                          + (["--resolution", args.resolution] if args.resolution else []) + [args.case_dir],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if plan.returncode != 0:
        raise SystemExit("pump-curve: %s" % plan.stderr.decode().strip())
    with open(os.path.join(args.case_dir, "case.yaml")) as f:
        case = yaml.safe_load(f)
    ranks = int(case["fluid"]["openfoam"].get("mpi_ranks", 1))
    if args.resolution:
        with open(os.path.join(args.case_dir, "presets", args.resolution + ".yaml")) as f:
            preset = yaml.safe_load(f) or {}
        ranks = int(((preset.get("fluid") or {}).get("openfoam") or {}).get("mpi_ranks", ranks))
    out = os.path.abspath(args.output or os.path.join(args.case_dir, "output",
                                                      "pump-curve" + ("-" + args.resolution if args.resolution else "")))
    os.makedirs(out, exist_ok=True)
    jobs = args.jobs or max(1, (os.cpu_count() or 1) // max(ranks, 1))
    args.fingerprint = case_fingerprint(args.case_dir, out)
    args.case_end_time = float(case["run"]["end_time_s"])
    methods = ["ibm", "ami"] if args.method == "both" else [args.method]
    points = [Point(f, design_q, out, m) for m in methods for f in fractions]
    say("%d points (%s of Q_design = %.4g L/s; %s), %d at once, in %s"
        % (len(points), args.points, 1e3 * design_q, " and ".join(METHODS[m] for m in methods), jobs, out))
    start = time.monotonic()
    stop = threading.Event()
    threading.Thread(target=report_progress, args=(points, stop), daemon=True).start()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = []
        for method in methods:  # the first point of each method meshes; the others reuse its mesh
            mine = [p for p in points if p.method == method]
            futures.append(pool.submit(run_point, args, mine[0]))
            mine[0].meshed.wait()
            futures += [pool.submit(run_point, args, p) for p in mine[1:]]
        for future in futures:
            future.result()
    stop.set()
    for p in points:
        if p.error:
            say("%s failed: %s" % (p.name, p.error))
    write_csv(points, os.path.join(out, "pump_curve.csv"))
    title = "%s%s: %d points, %.0f s" % (os.path.basename(args.case_dir),
                                         " (" + args.resolution + ")" if args.resolution else "",
                                         sum(p.result is not None for p in points), time.monotonic() - start)
    draw(points, os.path.join(out, "pump_curve.png"), title)
    for method in methods:
        for line in plausibility(points, method):
            say(line)
    for line in comparison(points):
        say(line)
    with open(design_file) as f:
        design_text = f.read()
    sizing, lines = best_point_duty(points, methods[0], yaml.safe_load(design_text))
    for line in lines:
        say(line)
    if sizing:
        volute_file = os.path.join(out, "pump.bep-volute.yaml")
        with open(volute_file, "w") as f:
            f.write(with_operation(design_text, {"design_flow_rate_m3_per_s": "%.6g" % sizing[0],
                                                 "design_swirl_m2_per_s": "%.6g" % sizing[1]}))
        say("the volute for this BEP: %s (pump.yaml with the BEP's flow rate and swirl; see its throat and spiral "
            "with ./fsi pump-design %s, run it by copying it over the case's pump.yaml)" % (volute_file, volute_file))
    say("pump_curve.csv, pump_curve.png in %s (%.0f s)" % (out, time.monotonic() - start))
    return 0 if all(p.result for p in points) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
