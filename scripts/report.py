#!/usr/bin/python3
"""The speed-against-error report (./fsi report): for each case with a reference, run a ladder
of resolutions / time steps through the launcher, measure the wall time and the error against
the reference, and write report/REPORT.md (table: resolution, dt, wall time, core-seconds per
simulated second, error, observed order) and report/error_vs_cost.png. The report names the
machine and the commit. Usage: report.py --bin-dir build/bin [--out report] [--quick]"""

import argparse
import datetime
import math
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
J01 = 2.404825557695773  # first zero of the Bessel function J0


class Study:
    """One case, a ladder of overrides, a reference and how to measure the error."""

    def __init__(self, name, case, reference_text, ladder, measure, cores=1):
        self.name, self.case, self.reference_text = name, case, reference_text
        self.ladder, self.measure, self.cores = ladder, measure, cores


# ---- measurements --------------------------------------------------------------------------

def chain_period_error(out, config):
    """Period of the hanging chain's first mode, against T_1 = 4 pi / (j01 sqrt(g / L))
    (continuous inextensible chain). The initial uniform velocity excites every mode: the
    first one is the peak of the tip's spectrum between 0.5 and 1.5 times its expected
    frequency (Hann window, zero padding, parabolic interpolation of the peak)."""
    f = h5py.File(os.path.join(out, "structure.h5"), "r")
    t = f["time_s"][:]
    x = f["structures/chain/position_m"][:, -1, 0]
    s = config["structures"][0]
    g = abs(config["gravity_m_per_s2"][2])
    reference = 4 * math.pi / (J01 * math.sqrt(g / s["length_m"]))
    dt = t[1] - t[0]
    signal = (x - x.mean()) * np.hanning(len(x))
    n_fft = 64 * len(x)
    spectrum = np.abs(np.fft.rfft(signal, n_fft))
    freq = np.fft.rfftfreq(n_fft, dt)
    band = np.where((freq > 0.5 / reference) & (freq < 1.5 / reference))[0]
    k = band[np.argmax(spectrum[band])]
    a, b, c = np.log(spectrum[k - 1:k + 2])
    peak = freq[k] + 0.5 * (a - c) / (a - 2 * b + c) * (freq[1] - freq[0])
    period = 1.0 / peak
    return abs(period - reference) / reference, "period %.5f s (reference %.5f s)" % (period, reference)


def relaxation_error(out, config):
    """Mean sheet velocity at t = tau against the continuous solution U (1 - exp(-t / tau))."""
    f = h5py.File(os.path.join(out, "structure.h5"), "r")
    t = f["time_s"][:]
    v = f["structures/sheet/velocity_m_per_s"][:].mean(axis=1)
    rho = config["structures"][0]["material"]["mass_per_area_kg_per_m2"]
    k = config["coupling"]["stiffness_n_per_m3"]
    dt = config["run"]["time_step_s"]
    u = np.array(config["fluid"]["prescribed"]["uniform"]["velocity_m_per_s"])
    tau = rho / (k * dt)
    i = int(np.argmin(abs(t - tau)))
    exact = u * (1 - math.exp(-t[i] / tau))
    return float(np.linalg.norm(v[i] - exact) / np.linalg.norm(u)), "V(t = %.3g s) against U (1 - e^-1)" % t[i]


def studies(quick):
    chain_ladder = [(n, 1.0 / (n - 1) / 100.0) for n in ([11, 21, 41] if quick else [11, 21, 41, 81])]
    relax_ladder = [2e-4, 1e-4, 5e-5] if quick else [4e-4, 2e-4, 1e-4, 5e-5, 2.5e-5]
    return [
        Study("hanging chain (structure only)", "hanging-filament",
              "first period of a hanging chain, T_1 = 4 pi / (j_01 sqrt(g/L)) (Bessel; continuous, inextensible)",
              [({"structures": [{"n_points": n}], "run": {"time_step_s": dt, "output_interval_s": 0.02,
                                                          "end_time_s": 20.0}}, "n = %d" % n, dt)
               for n, dt in chain_ladder],
              chain_period_error),
        Study("sheet relaxing in a uniform flow (3 processes)", "sheet-in-uniform-flow",
              "V(t) = U (1 - exp(-t / tau)), tau = rho_1 / (K dt), from Eqs. (4)-(5); K dt kept constant",
              [({"run": {"time_step_s": dt, "output_interval_s": 0.005},
                 "coupling": {"stiffness_n_per_m3": 3.2e4 * 5e-5 / dt}}, "dt = %g s" % dt, dt)
               for dt in relax_ladder],
              relaxation_error, cores=3),
    ]


# ---- running -------------------------------------------------------------------------------

def deep_merge(base, overlay):
    if isinstance(base, dict) and isinstance(overlay, dict):
        out = dict(base)
        for key, value in overlay.items():
            out[key] = deep_merge(base[key], value) if key in base else value
        return out
    if isinstance(base, list) and isinstance(overlay, list) and len(base) == len(overlay):
        return [deep_merge(b, o) for b, o in zip(base, overlay)]
    return overlay


def run_one(bin_dir, study, overlay, workdir, label):
    case = os.path.join(workdir, "case")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "cases", study.case), case, ignore=shutil.ignore_patterns("output"))
    config = deep_merge(yaml.safe_load(open(os.path.join(case, "case.yaml"))), overlay)
    yaml.safe_dump(config, open(os.path.join(case, "case.yaml"), "w"))
    out = os.path.join(workdir, "out")
    start = time.monotonic()
    result = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "fsi_launch.py"), "--bin-dir", bin_dir,
                             "-o", out, case], stdin=subprocess.DEVNULL, capture_output=True)
    wall = time.monotonic() - start
    if result.returncode != 0:
        raise RuntimeError("%s, %s failed (exit %d): %s" % (study.name, label, result.returncode,
                                                           result.stderr.decode()[-1500:]))
    error, detail = study.measure(out, config)
    return wall, config["run"]["end_time_s"], error, detail


def machine():
    model = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    return "%s, %d cores, %s; commit %s" % (model, os.cpu_count(), platform.platform(), commit)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--out", default=os.path.join(ROOT, "report"))
    parser.add_argument("--quick", action="store_true", help="shorter ladders (a few minutes)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    lines = ["# Speed against error", "",
             "Machine: %s. Written %s by `./fsi report`." % (machine(), datetime.datetime.now().strftime("%Y-%m-%d %H:%M")),
             "", "Core-seconds per simulated second = wall time x processes / simulated time (each process",
             "of a coupled run is single-threaded). Observed order = log(e_i-1 / e_i) / log(h_i-1 / h_i).", ""]
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for study in studies(args.quick):
        print("report: %s" % study.name, flush=True)
        lines += ["## %s: `cases/%s`" % (study.name, study.case), "", "Reference: %s." % study.reference_text, "",
                  "| resolution | dt (s) | wall (s) | core-s per simulated s | relative error | observed order | measured |",
                  "|---|---|---|---|---|---|---|"]
        costs, errors, previous = [], [], None
        with tempfile.TemporaryDirectory(prefix="fsi-report-") as workdir:
            for overlay, label, dt in study.ladder:
                wall, simulated, error, detail = run_one(args.bin_dir, study, overlay, workdir, label)
                cost = wall * study.cores / simulated
                order = ""
                if previous is not None and error > 0 and previous[1] > 0:
                    order = "%.2f" % (math.log(previous[1] / error) / math.log(previous[0] / dt))
                previous = (dt, error)
                costs.append(cost)
                errors.append(error)
                lines.append("| %s | %.3g | %.2f | %.3g | %.3e | %s | %s |" % (label, dt, wall, cost, error, order, detail))
                print("  %s: error %.3e, %.1f s" % (label, error, wall), flush=True)
        ax.loglog(costs, errors, "o-", label=study.name)
        lines.append("")
    ax.set_xlabel("core-seconds per simulated second")
    ax.set_ylabel("relative error against the reference")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "error_vs_cost.png"), dpi=120)
    lines += ["![error against cost](error_vs_cost.png)", ""]
    open(os.path.join(args.out, "REPORT.md"), "w").write("\n".join(lines))
    print("report: %s" % os.path.join(args.out, "REPORT.md"))


if __name__ == "__main__":
    main()
