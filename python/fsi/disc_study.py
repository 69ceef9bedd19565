#!/usr/bin/python3
"""The rotating disc in its housing with both methods, side by side (cases/rotating-disc; issue 30
part 4): the penalized disc (our fluid, through the launcher) and the disc as a mesh boundary
(stock pimpleFoam) on the same wedge mesh, at several resolutions, against the references.

    ./fsi disc-study [--only laminar|turbulent] [--levels N] [--jobs N] [-o DIR]

- laminar (Re = 400, G = 0.05, Daily & Nece's regime I): the swirl across the gap at r = R/2
  against the similarity solution (relative L2 error), and the torque of the penalized disc
  without and with the immersed wall model and of the body-fitted disc, against each other and
  against the similarity solution's faces plus the rim's Couette flow.
- turbulent (Re = 1.5e6, Spalart-Allmaras): the torque of the penalized disc without and with the
  immersed wall model (fluid.openfoam.immersed_wall_model) and of the body-fitted disc (Spalding's
  wall function), against Daily & Nece's regime IV correlation (and III).
Writes DIR/DISC.md, DIR/disc.csv and DIR/disc.png (default study/rotating-disc); every run's
results stay in DIR/runs/<name>/ and a finished run is reused while the case is unchanged.
"""

import argparse
import csv
import hashlib
import os
import subprocess
import sys
import time

from fsi import ROOT, case_module, fsi_launch, study_pool, rotating_disc
from fsi.foam_case import LAMINAR_FV_SCHEMES, OPENFOAM_ENVIRONMENT

CASE = os.path.join(ROOT, "cases", "rotating-disc")
LAUNCHER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fsi_launch.py")
make_case = case_module("rotating-disc", "make_case")

# (regime, preset, folder of make_case.RESOLUTIONS) per level, finest last.
LEVELS = {"laminar": [("coarse", "openfoam"), ("medium", "openfoam-medium"), ("fine", "openfoam-fine")],
          "turbulent": [("turbulent", "openfoam-turbulent"), ("turbulent-medium", "openfoam-turbulent-medium")]}


say = fsi_launch.speaker("disc-study")


def case_fingerprint():
    h = hashlib.sha256()
    for root, _dirs, files in sorted(os.walk(CASE)):
        for name in sorted(files):
            if "__pycache__" in root:
                continue
            path = os.path.join(root, name)
            h.update(os.path.relpath(path, CASE).encode())
            with open(path, "rb") as f:
                h.update(f.read())
    for module in (rotating_disc.__file__,):
        with open(module, "rb") as f:
            h.update(f.read())
    return h.hexdigest()[:16]


def resolution(folder):
    for name, disc, per_gap, dt, end, turbulent in make_case.RESOLUTIONS:
        if name == folder:
            return disc, disc.axial_gap_m / per_gap, dt, end, turbulent
    raise KeyError(folder)


class Run:
    def __init__(self, regime, preset, folder, method, wall_model, out):
        self.regime, self.preset, self.folder, self.method, self.wall_model = regime, preset, folder, method, wall_model
        self.disc, self.h, self.dt, self.end, self.turbulent = resolution(folder)
        self.name = "%s-%s%s" % (preset, method, "-" + wall_model if method == "penalized" else "")
        self.out = os.path.join(out, "runs", self.name)
        self.result = None
        self.error = None

    def cells(self):
        n_in, n_tip, n_gap, n_disc = self.disc.cells(self.h)
        return (n_in + n_tip) * (2 * n_gap + n_disc) - (n_in * n_disc if self.method == "body-fitted" else 0)


def run_one(run, args, fingerprint):
    stamp = os.path.join(run.out, "study.complete")
    expected = "%s %s\n" % (fingerprint, run.name)
    if os.path.exists(stamp) and open(stamp).read() == expected:
        say("%s: up to date, reused" % run.name)
    else:
        if os.path.exists(stamp):
            os.remove(stamp)
        os.makedirs(run.out, exist_ok=True)
        start = time.monotonic()
        say("%s: running (%d cells, %d steps)" % (run.name, run.cells(), round(run.end / run.dt)))
        if run.method == "penalized":
            command = [sys.executable, LAUNCHER, "--bin-dir", args.bin_dir, "-o", run.out, "--resolution", run.preset]
            command += ["--set", "fluid.openfoam.immersed_wall_model=%s" % run.wall_model]
            with open(os.path.join(run.out, "study.log"), "w") as log:
                code = subprocess.call(command + [CASE], stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT)
            if code != 0:
                raise RuntimeError("%s: the run failed (exit %d): see %s/study.log" % (run.name, code, run.out))
            history = rotating_disc.penalized_torque(run.out)
            result = {}
        else:
            os.environ.update(OPENFOAM_ENVIRONMENT)
            fitted = rotating_disc.run_body_fitted(
                os.path.join(run.out, "openfoam"), run.disc, run.h, run.end, run.dt,
                make_case.TURBULENT_FV_SCHEMES if run.turbulent else LAMINAR_FV_SCHEMES, make_case.FV_SOLUTION,
                run.turbulent, logs=run.out)
            history = fitted["history"]
            result = {"faces_n_m": -fitted["faces_n_m"], "rim_n_m": -fitted["rim_n_m"]}
        result["wall_s"] = time.monotonic() - start
        with open(os.path.join(run.out, "history.csv"), "w") as f:
            f.write("time_s,torque_n_m\n" + "".join("%.9g,%.9g\n" % row for row in history))
        with open(os.path.join(run.out, "result.csv"), "w") as f:
            f.write("".join("%s,%r\n" % kv for kv in result.items()))
        with open(stamp, "w") as f:
            f.write(expected)
    with open(os.path.join(run.out, "history.csv")) as f:
        history = [(float(r["time_s"]), float(r["torque_n_m"])) for r in csv.DictReader(f)]
    with open(os.path.join(run.out, "result.csv")) as f:
        result = {k: float(v) for k, v in (line.strip().split(",") for line in f if line.strip())}
    mean, spread = rotating_disc.window_mean(history)
    scale = run.disc.torque_scale_n_m()
    result.update({"torque_n_m": -mean, "torque_std_n_m": spread, "cm": -mean / scale})
    if "faces_n_m" in result:
        result["cm_faces"] = result["faces_n_m"] / scale
    if not run.turbulent:
        folder = os.path.join(run.out, "openfoam")
        times = [d for d in os.listdir(folder) if d.replace(".", "", 1).isdigit() and float(d) > 0]
        latest = max(times, key=float)
        eta, swirl, _r = rotating_disc.gap_profile(folder, latest, run.disc, 0.5 * run.disc.radius_m)
        result["profile_l2"] = rotating_disc.profile_error(eta, swirl, run.disc.gap_reynolds)
        result["profile"] = (eta.tolist(), swirl.tolist())
    run.result = result
    say("%s: |M| = %.4g N m, C_M = %.4g, wall %.0f s" % (run.name, result["torque_n_m"], result["cm"], result["wall_s"]))
    return run


def plan(args):
    runs = []
    for regime in ("laminar", "turbulent"):
        if args.only and args.only != regime:
            continue
        for preset, folder in LEVELS[regime][:args.levels]:
            runs += [Run(regime, preset, folder, "penalized", "none", args.out),
                     Run(regime, preset, folder, "penalized", "spalding", args.out),
                     Run(regime, preset, folder, "body-fitted", "", args.out)]
    return runs


def report(runs, out, failed=()):
    lines = ["# The rotating disc in its housing, both methods", "",
             "Generated by `./fsi disc-study` (python/fsi/disc_study.py); the case: cases/rotating-disc/README.md.",
             "C_M = 2 |M| / (rho omega^2 R^5) of the whole disc (faces and rim), mean over the last 20 % of the run.", ""]
    for regime in ("laminar", "turbulent"):
        chosen = [r for r in runs if r.regime == regime]
        if not chosen:
            continue
        disc = chosen[0].disc
        refs = rotating_disc.references(disc)
        lines += ["## %s: Re = %.4g, G = s/R = %.3g" % (refs["regime"], disc.reynolds, disc.gap_ratio), ""]
        if regime == "laminar":
            lam = rotating_disc.laminar_reference(disc)
            lines += ["References: faces by the similarity solution C_M = %.4f (|g'(0)| = %.5f; Daily & Nece's regime I, "
                      "Couette: %.4f), rim by Couette flow %.4f; faces + rim %.4f." % (
                          lam["cm_faces_similarity"], lam["wall_shear_factor"], lam["cm_regime_I"], lam["cm_rim"],
                          lam["cm_faces_similarity"] + lam["cm_rim"]), "",
                      "| h | method | cells | C_M | vs body-fitted | faces C_M (vs similarity) | swirl at R/2: L2 vs similarity | wall s |",
                      "|---|---|---|---|---|---|---|---|"]
        else:
            lines += ["References: Daily & Nece regime IV C_M = %.5f (faces; III: %.5f)." % (
                refs["cm_regime_IV"], refs["cm_regime_III"]), "",
                "| h | method | cells | C_M | vs body-fitted | faces C_M (vs regime IV) | torque std / mean | wall s |",
                "|---|---|---|---|---|---|---|---|"]
        for r in chosen:
            fitted = next((x for x in chosen if x.preset == r.preset and x.method == "body-fitted"), None)
            if fitted is None:
                continue
            res = r.result
            label = r.method + (" (" + r.wall_model + ")" if r.method == "penalized" else "")
            faces = ("%.5f (%+.1f %%)" % (res["cm_faces"], 100.0 * (res["cm_faces"] / (
                refs["cm_regime_IV"] if r.turbulent else rotating_disc.laminar_reference(disc)["cm_faces_similarity"]) - 1.0))
                if "cm_faces" in res else "")
            last = ("%.2e" % res["profile_l2"]) if not r.turbulent else "%.3f" % (res["torque_std_n_m"] / res["torque_n_m"])
            lines.append("| s/%d | %s | %d | %.5f | %+.1f %% | %s | %s | %.0f |" % (
                round(disc.axial_gap_m / r.h), label, r.cells(), res["cm"], 100.0 * (res["cm"] / fitted.result["cm"] - 1.0),
                faces, last, res["wall_s"]))
        lines.append("")
    if failed:
        lines += ["## Failed runs", ""] + ["- %s: %s" % (r.name, r.error) for r in failed] + [""]
    with open(os.path.join(out, "DISC.md"), "w") as f:
        f.write("\n".join(lines))
    with open(os.path.join(out, "disc.csv"), "w") as f:
        f.write("run,regime,h_m,method,wall_model,cells,torque_n_m,cm,cm_faces,profile_l2,wall_s\n")
        for r in runs:
            res = r.result
            f.write("%s,%s,%g,%s,%s,%d,%.6g,%.6g,%s,%s,%.1f\n" % (
                r.name, r.regime, r.h, r.method, r.wall_model, r.cells(), res["torque_n_m"], res["cm"],
                "%.6g" % res["cm_faces"] if "cm_faces" in res else "",
                "%.4g" % res["profile_l2"] if "profile_l2" in res else "", res["wall_s"]))
    draw(runs, os.path.join(out, "disc.png"))
    return "\n".join(lines)


def draw(runs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    laminar = [r for r in runs if r.regime == "laminar"]
    if laminar:
        ax = axes[0]
        disc = laminar[0].disc
        eta = np.linspace(0.0, 1.0, 101)
        ax.plot(rotating_disc.similarity_solution(disc.gap_reynolds)(eta)[4], eta, "k-", lw=1.5, label="similarity solution")
        for r in laminar:
            e, s = r.result["profile"]
            ax.plot(s, e, "o" if r.method == "penalized" else "s", ms=3, mfc="none",
                    label="%s%s, h = s/%d" % (r.method, " (%s)" % r.wall_model if r.wall_model else "",
                                              round(disc.axial_gap_m / r.h)))
        ax.set_xlabel("u_theta / (r omega) at r = R/2")
        ax.set_ylabel("(z - t/2) / s (disc at 0, housing at 1)")
        ax.set_title("Laminar, Re = %.0f: swirl across the gap" % disc.reynolds)
        ax.legend(fontsize=7)
    for ax, regime in ((axes[1], "laminar"), (axes[2], "turbulent")):
        chosen = [r for r in runs if r.regime == regime]
        if not chosen:
            ax.set_visible(False)
            continue
        disc = chosen[0].disc
        refs = rotating_disc.references(disc)
        series = {}
        for r in chosen:
            key = r.method + (" (%s)" % r.wall_model if r.method == "penalized" else "")
            series.setdefault(key, []).append((disc.axial_gap_m / r.h, r.result["cm"]))
        for key, points in series.items():
            points.sort()
            ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label=key)
        if regime == "laminar":
            ax.axhline(refs["cm_faces_and_rim"], color="k", ls="--", lw=1, label="similarity faces + Couette rim")
            ax.axhline(refs["cm_regime_I"], color="grey", ls=":", lw=1, label="Daily & Nece I (faces)")
        else:
            ax.axhline(refs["cm_regime_IV"], color="k", ls="--", lw=1, label="Daily & Nece IV (faces)")
            ax.axhline(refs["cm_regime_III"], color="grey", ls=":", lw=1, label="Daily & Nece III (faces)")
        ax.set_xscale("log", base=2)
        ax.set_xlabel("cells across the axial gap s / h")
        ax.set_ylabel("C_M (whole disc)")
        ax.set_ylim(bottom=0)
        ax.set_title("%s, Re = %.3g" % ("Laminar" if regime == "laminar" else "Turbulent (SA)", disc.reynolds))
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(prog="./fsi disc-study", description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--only", choices=["laminar", "turbulent"])
    parser.add_argument("--levels", type=int, default=2, help="resolutions per regime, coarsest first (default 2)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("-o", dest="out", default=os.path.join(ROOT, "study", "rotating-disc"))
    args = parser.parse_args(argv)
    try:
        fsi_launch.prepare_case(CASE, args.bin_dir)
    except fsi_launch.UserError as e:
        raise SystemExit("disc-study: %s" % e)
    os.makedirs(args.out, exist_ok=True)
    fingerprint = case_fingerprint()
    runs = plan(args)
    failed = study_pool.run_all(runs, lambda r: run_one(r, args, fingerprint), args.jobs, say)
    print(report([r for r in runs if r.result is not None], args.out, failed))
    if failed:
        raise SystemExit("disc-study: %d run(s) failed: %s" % (len(failed), ", ".join(r.name for r in failed)))
    say("wrote %s/DISC.md, disc.csv, disc.png" % args.out)


if __name__ == "__main__":
    main(sys.argv[1:])
