#!/usr/bin/python3
"""The coupling laws and schemes side by side on real coupled runs (issue 15; docs/coupling.md).

    ./fsi coupling-study [--only laws|pole|pump|implicit] [-o DIR]

Writes DIR/COUPLING.md (default study/coupling) and keeps every run's results in DIR/runs/.

- laws: the flapping flag (cases/flag-in-crossflow, coarse) with the penalty (drag) law, the
  paper's two point sets and the feedback law at equal cost (same mesh, dt and stiffness:
  two_point_sets with the same K, feedback with alpha = K and beta = K dt): St_L and A/L against
  the case's references, wall time.
- pole, pump: the same three laws on the rag behind the pole (its path) and the rag in the pump
  at Q_BEP (residence and wrap), coarse, the precursor run once and reused.
- implicit: the flag at mass ratio rho_1 / (rho_f L) = 0.025 (rho_1 = 1 kg/m^2, phi and zeta
  scaled with rho_1 so that K_T and K_B stay those of the case), where the explicit penalty law
  at the case's K = 6.4e9 N/m^3 has a = K dt^2 / rho_1 = 4 (limit 2): explicit diverges;
  explicit at its largest stable dt; implicit (IQN-ILS, Aitken) at that K and at 10x; the same
  for the paper's light pump rag (rho_1 = 0.03 kg/m^2, phi = 10 N/m) in the OpenFOAM channel of
  cases/sheet-in-openfoam-channel. Each row: outcome, coupling iterations a step, wall time per
  simulated second.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np

from fsi import ROOT, case_module

flapping = case_module("flag-in-crossflow", "flapping")  # cases/flag-in-crossflow/flapping.py


def edit(text, pattern, replacement):
    new, n = re.subn(pattern, replacement, text, count=1)
    if n != 1:
        raise SystemExit("coupling_study: no match for %r in a case file" % pattern)
    return new


def law_lines(law, k, dt, scheme=None):
    if law == "penalty":
        lines = "  law: penalty\n  stiffness_n_per_m_per_measure: %g\n" % k
    elif law == "two_point_sets":
        lines = "  law: two_point_sets\n  stiffness_n_per_m_per_measure: %g\n" % k
    else:
        lines = "  law: feedback\n  alpha_n_per_m_per_measure: %g\n  beta_n_s_per_m_per_measure: %g\n" % (k, k * dt)
    if scheme:
        lines += ("  scheme: implicit\n  implicit:\n    acceleration: %s\n    relaxation: 0.1\n    tolerance: 1.0e-4\n"
                  "    max_iterations: 30\n" % scheme)
    return lines


def make_case(runs_dir, name, source, law="penalty", k=None, dt=None, scheme=None, rho=None, phi=None,
              zeta=None, end_time_s=None):
    case = os.path.join(runs_dir, name, "case")
    shutil.rmtree(os.path.dirname(case), ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "cases", source), case,
                    ignore=shutil.ignore_patterns("output", "*.png", "*.gif", "keys"))
    path = os.path.join(case, "case.yaml")
    with open(path) as f:
        text = f.read()
    old_dt = float(re.search(r"time_step_s: ([0-9.e+-]+)", text).group(1))
    old_k = float(re.search(r"stiffness_n_per_m_per_measure: ([0-9.e+-]+)", text).group(1))
    dt = dt or old_dt
    k = k or old_k
    text = edit(text, r"time_step_s: [0-9.e+-]+", "time_step_s: %g" % dt)
    if end_time_s:
        text = edit(text, r"end_time_s: [0-9.e+-]+", "end_time_s: %g" % end_time_s)
    text = edit(text, r"  law: penalty\n(?:  #[^\n]*\n)*  stiffness_n_per_m_per_measure: [^\n]*\n",
                law_lines(law, k, dt, scheme))
    if rho is not None:
        text = edit(text, r"mass_per_area_kg_per_m2: [0-9.e+-]+", "mass_per_area_kg_per_m2: %g" % rho)
        text = edit(text, r"coefficients: \{[^}]*\}",
                    "coefficients: {tension_coefficient_n_per_m: %g, bending_rigidity_n_m: %g}" % (phi, zeta))
    with open(path, "w") as f:
        f.write(text)
    return case


def run(case, bin_dir, timeout_s=3600):
    out = os.path.join(os.path.dirname(case), "out")
    started = time.time()
    made = subprocess.run([sys.executable, os.path.join(ROOT, "python", "fsi", "fsi_launch.py"), "--bin-dir", bin_dir,
                           "-o", out, case], stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=timeout_s)
    wall = time.time() - started
    row = {"out": out, "code": made.returncode, "wall_s": wall}
    script = os.path.join(case, "postprocess.py")  # the case's own quantities, as ./fsi run makes them
    if os.path.exists(script) and os.path.exists(os.path.join(out, "structure.h5")):
        env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"))
        subprocess.run([sys.executable, script, out, case], stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, env=env)
    with h5py.File(os.path.join(out, "coupling.h5"), "r") as f:
        n = int(f.attrs.get("complete_steps", len(f["step"])))
        row["steps"] = n
        row["t_end"] = float(f["time_s"][n - 1]) if n else 0.0
        row["iterations"] = float(np.mean(f["coupling_iterations"][:n])) if n else float("nan")
        step_wall = f["timings"]["step_wall_s"][:n]
        row["wall_per_sim_s"] = float(step_wall.sum() / row["t_end"]) if n else float("nan")
    if made.returncode != 0:
        found = re.search(r"diverged at step (\d+)[^\n]*?: ([^\n]*?)(?: Likely cause|$)", made.stdout, re.M)
        row["outcome"] = "diverged at step %s" % found.group(1) if found else "failed (exit %d)" % made.returncode
    else:
        row["outcome"] = "completed"
    return row


def flag_figures(row):
    if row["code"] != 0:
        return ""
    figures = flapping.analyse(row["out"])
    return "St_L %.3f, A/L %.3f" % (figures["St_L"], figures["A"] / figures["L"])


def laws(runs_dir, bin_dir):
    lines = ["## The laws at equal cost: the flapping flag (coarse, L/16, dt = 2.5e-5 s, K = 6.4e9 N/m^3)", "",
             "| law | St_L | A/L | wall (s) | outcome |", "|---|---|---|---|---|"]
    for law in ("penalty", "two_point_sets", "feedback"):
        row = run(make_case(runs_dir, "flag-" + law, "flag-in-crossflow", law), bin_dir)
        figures = flapping.analyse(row["out"]) if row["code"] == 0 else None
        lines.append("| %s | %s | %s | %.1f | %s |" % (
            law, "%.3f" % figures["St_L"] if figures else "-",
            "%.3f" % (figures["A"] / figures["L"]) if figures else "-", row["wall_s"], row["outcome"]))
        print(lines[-1], flush=True)
    lines += ["", "References of the case (cases/flag-in-crossflow/reference.yaml): coarse 0.323 / 0.854, "
              "medium 0.322 / 0.892, fine 0.313 / 0.920 (St_L / A/L).", ""]
    return lines


def pole(runs_dir, bin_dir):
    """The rag behind the pole (coarse, 0.6 s): its upstream edge's path (rag_path.csv) per law."""
    lines = ["## The laws at equal cost: the rag behind the pole (coarse, dt = 1e-4 s, K = 2.5e5 N/m^3)", "",
             "| law | u* at t* = 1, 2, 4 | z* at t* = 4 | pitch at t* = 2, 4 (deg) | wall (s) | outcome |",
             "|---|---|---|---|---|---|"]
    precursor = None
    for law in ("penalty", "two_point_sets", "feedback"):
        case = make_case(runs_dir, "pole-" + law, "rag-behind-pole", law)
        seed_precursor(precursor, case)
        row = run(case, bin_dir)
        precursor = precursor or os.path.join(row["out"], "precursor")
        cells = ["-"] * 3
        path = os.path.join(row["out"], "rag_path.csv")
        if os.path.exists(path):
            data = np.loadtxt(path, delimiter=",", ndmin=2, skiprows=1)  # a header line without '#'
            t, z, u, pitch = data[:, 0], data[:, 2], data[:, 3], data[:, 5]
            at = lambda series, ts: ", ".join("%.2f" % np.interp(x, t, series) for x in ts)  # noqa: E731
            cells = [at(u, (1, 2, 4)), at(z, (4,)), at(pitch, (2, 4))]
        lines.append("| %s | %s | %.0f | %s |" % (law, " | ".join(cells), row["wall_s"], row["outcome"]))
        print(lines[-1], flush=True)
    return lines + [""]


def pump(runs_dir, bin_dir):
    """The rag in the pump (coarse, Q_BEP): residence and wrap (rag_metrics.csv) per law."""
    lines = ["## The laws at equal cost: the rag in the pump (coarse, Q_BEP, dt = 2.5e-4 s, K = 2e4 N/m^3)", "",
             "| law | outcome | residence (rev) | wrap fraction of the run | longest wrap (rev) | max strain | "
             "wall (s) |", "|---|---|---|---|---|---|---|"]
    precursor = None
    for law in ("penalty", "two_point_sets", "feedback"):
        case = make_case(runs_dir, "pump-" + law, "rag-in-pump", law)
        seed_precursor(precursor, case)
        row = run(case, bin_dir, timeout_s=7200)
        precursor = precursor or os.path.join(row["out"], "precursor")
        metrics = {}
        path = os.path.join(row["out"], "rag_metrics.csv")
        if os.path.exists(path):
            with open(path) as f:
                keys, values = f.readline().strip().split(","), f.readline().strip().split(",")
            metrics = dict(zip(keys, values))
        cell = lambda key: metrics.get(key) or "-"  # noqa: E731
        lines.append("| %s | %s | %s | %s | %s | %s | %.0f |" % (
            law, cell("outcome"), cell("residence_time_revolutions"), cell("wrap_fraction_of_run"),
            cell("longest_wrap_revolutions"), cell("max_strain"), row["wall_s"]))
        print(lines[-1], flush=True)
    return lines + [""]


def seed_precursor(source, case):
    """The first run's precursor (the flow alone: the law does not change it), hard-linked into
    the next run's results, where the launcher reuses it when its fingerprint matches."""
    target = os.path.join(os.path.dirname(case), "out", "precursor")
    if source and os.path.isdir(source) and not os.path.exists(target):
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copytree(source, target, copy_function=os.link)


def implicit_flag(runs_dir, bin_dir):
    lines = []
    # The flag at mass ratio 0.025: K_T = phi / (rho_1 U^2) = 15 and K_B = 1e-4 kept.
    rho, U, L = 1.0, 15.0, 0.04
    light = dict(rho=rho, phi=15.0 * rho * U * U, zeta=1e-4 * rho * U * U * L * L)
    k, dt = 6.4e9, 2.5e-5
    k_limit = 2.0 * rho / dt ** 2
    dt_limit = (2.0 * rho / k) ** 0.5
    cases = [("explicit, K = 6.4e9 (a = 4)", dict(k=k)),
             ("explicit, K = 6.4e9 at dt = 1.6e-5 s (a = 1.64, below the law's limit %.3g s)" % dt_limit,
              dict(k=k, dt=1.6e-5)),
             ("explicit, K = 2.9e9 (0.9 of the law's limit %.3g)" % k_limit, dict(k=2.9e9)),
             ("explicit, K = 6.4e9 at dt = 1e-5 s (a = 0.64)", dict(k=k, dt=1e-5)),
             ("explicit, K = 8e8 (a = 0.5)", dict(k=8e8)),
             ("explicit, K = 5e8 (a = 0.31)", dict(k=5e8)),
             ("implicit IQN-ILS, K = 6.4e9 (2x the limit)", dict(k=k, scheme="iqn_ils")),
             ("implicit Aitken, K = 6.4e9", dict(k=k, scheme="aitken")),
             ("implicit IQN-ILS, K = 3.2e10 (10x the law's limit)", dict(k=5 * k, scheme="iqn_ils")),
             ("implicit IQN-ILS, K = 6.4e10 (20x the law's limit)", dict(k=10 * k, scheme="iqn_ils"))]
    lines += ["## Implicit coupling: the flag at mass ratio 0.025 (rho_1 = 1 kg/m^2; explicit limit K < %.3g N/m^3 "
              "at dt = 2.5e-5 s)" % k_limit, "",
              "| run | outcome | iterations/step | wall s per simulated s | flapping |", "|---|---|---|---|---|"]
    for i, (label, options) in enumerate(cases):
        row = run(make_case(runs_dir, "light-flag-%d" % i, "flag-in-crossflow", **light, **options), bin_dir)
        lines.append("| %s | %s | %.2f | %.0f | %s |" % (label, row["outcome"], row["iterations"],
                                                         row["wall_per_sim_s"], flag_figures(row)))
        print(lines[-1], flush=True)
    return lines


def implicit_rag(runs_dir, bin_dir):
    # The paper's pump rag in the OpenFOAM channel: rho_1 = 0.03, phi = 10, zeta = 1e-8, dt = 5e-5.
    lines = []
    rag = dict(rho=0.03, phi=10.0, zeta=1e-8)
    k_limit = 2.0 * 0.03 / 5e-5 ** 2
    cases = [("explicit, K = 1e5 (the paper's)", dict(k=1e5)),
             ("explicit, K = 2.2e7 (0.9 of the limit)", dict(k=0.9 * k_limit)),
             ("explicit, K = 2.4e8 (10x the limit)", dict(k=10 * k_limit)),
             ("implicit IQN-ILS, K = 2.4e8 (10x the limit)", dict(k=10 * k_limit, scheme="iqn_ils")),
             ("implicit Aitken, K = 2.4e8 (10x the limit)", dict(k=10 * k_limit, scheme="aitken"))]
    lines += ["", "## Implicit coupling: the pump's light rag (rho_1 = 0.03 kg/m^2, phi = 10 N/m) in the OpenFOAM "
              "channel (dt = 5e-5 s; explicit limit K < %.3g N/m^3)" % k_limit, "",
              "| run | outcome | iterations/step | wall s per simulated s |", "|---|---|---|---|"]
    for i, (label, options) in enumerate(cases):
        row = run(make_case(runs_dir, "light-rag-%d" % i, "sheet-in-openfoam-channel", dt=5e-5, **rag, **options),
                  bin_dir)
        lines.append("| %s | %s | %.2f | %.0f |" % (label, row["outcome"], row["iterations"], row["wall_per_sim_s"]))
        print(lines[-1], flush=True)
    return lines + [""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin-dir", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("-o", "--out", default=os.path.join(ROOT, "study", "coupling"))
    parser.add_argument("--only", choices=("laws", "pole", "pump", "implicit", "implicit-flag", "implicit-rag"),
                        help="one part: laws (the flag, about 1 min), pole (about 10 min), pump (about 40 min), "
                             "implicit (about 10 min)")
    args = parser.parse_args()
    runs_dir = os.path.join(args.out, "runs")
    os.makedirs(runs_dir, exist_ok=True)
    lines = ["# Coupling laws and schemes (./fsi coupling-study)", ""]
    if args.only in (None, "laws"):
        lines += laws(runs_dir, args.bin_dir)
    if args.only in (None, "pole"):
        lines += pole(runs_dir, args.bin_dir)
    if args.only in (None, "pump"):
        lines += pump(runs_dir, args.bin_dir)
    if args.only in (None, "implicit", "implicit-flag"):
        lines += implicit_flag(runs_dir, args.bin_dir)
    if args.only in (None, "implicit", "implicit-rag"):
        lines += implicit_rag(runs_dir, args.bin_dir)
    path = os.path.join(args.out, "COUPLING.md" if not args.only else "COUPLING-%s.md" % args.only)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("table: %s" % path)


if __name__ == "__main__":
    main()
