#!/usr/bin/python3
"""The speed-against-error report (./fsi report): for each case with a reference, run a ladder
of resolutions / time steps through the launcher, measure the wall time and the error against
the reference, and write report/REPORT.md (table: resolution, dt, wall time, core-seconds per
simulated second, error, observed order) and report/error_vs_cost.png, then the speed benchmarks
against their references in the same run (coupling against raw TCP, membrane step per point,
collisions on 1 thread against all cores, the fluid against stock pimpleFoam on 1 and 2 ranks).
The report names the machine and the commit. Usage: report.py --bin-dir build/bin [--out report]
[--quick] [--skip-stability] [--skip-speed | --only-speed (report/SPEED.md)]"""

import argparse
import datetime
import json
import math
import os
import platform
import re
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

from fsi import ROOT, case_module
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
    k = config["coupling"]["stiffness_n_per_m_per_measure"]
    dt = config["run"]["time_step_s"]
    u = np.array(config["fluid"]["prescribed"]["uniform"]["velocity_m_per_s"])
    tau = rho / (k * dt)
    i = int(np.argmin(abs(t - tau)))
    exact = u * (1 - math.exp(-t[i] / tau))
    return float(np.linalg.norm(v[i] - exact) / np.linalg.norm(u)), "V(t = %.3g s) against U (1 - e^-1)" % t[i]


def edge_centroid(out, structure, edge_index=0):
    """Time and the trapezoid-weighted centroid of the sheet's edge s1 = edge_index (position and
    velocity, [t, 3]) from structure.h5."""
    with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
        g = f["structures"][structure]
        n1, n2 = (int(v) for v in g.attrs["grid_shape"])
        x = g["position_m"][:].reshape(-1, n1, n2, 3)[:, edge_index]
        v = g["velocity_m_per_s"][:].reshape(-1, n1, n2, 3)[:, edge_index]
        t = f["time_s"][:]
    w = np.ones(n2)
    w[[0, -1]] = 0.5
    w /= w.sum()
    return t, np.einsum("j,tjk->tk", w, x), np.einsum("j,tjk->tk", w, v)


def path_difference(t_a, x_a, t_b, x_b, length):
    """Largest distance between two point paths over their common saved times, per length."""
    n = min(len(t_a), len(t_b))
    assert np.allclose(t_a[:n], t_b[:n]), "the runs saved at different times"
    return float(np.max(np.linalg.norm(x_a[:n] - x_b[:n], axis=1)) / length)


class FinerReference:
    """Error of a run against the finest run of its ladder (no external reference): the largest
    distance between their free-edge centre paths over the run, per flag length. The ladder runs
    the finest first and keeps its path."""

    def __init__(self, structure, edge_index, length):
        self.structure, self.edge_index, self.length = structure, edge_index, length
        self.reference = None

    def __call__(self, out, config):
        t, x, _ = edge_centroid(out, self.structure, self.edge_index)
        if self.reference is None:
            self.reference = (t, x)
            return 0.0, "reference (finest)"
        error = path_difference(t, x, self.reference[0], self.reference[1], self.length)
        return error, "max distance of the free-edge centre from the finest run's, per length"


def studies(quick):
    chain_ladder = [(n, 1.0 / (n - 1) / 100.0) for n in ([11, 21, 41] if quick else [11, 21, 41, 81])]
    # (dt = 4e-4 s would put Delta s / Delta t = 12.5 m/s below the stretching wave, 15.8 m/s.)
    relax_ladder = [2e-4, 1e-4, 5e-5] if quick else [2e-4, 1e-4, 5e-5, 2.5e-5, 1.25e-5]
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
                 "coupling": {"stiffness_n_per_m_per_measure": 3.2e4 * 5e-5 / dt}}, "dt = %g s" % dt, dt)
               for dt in relax_ladder],
              relaxation_error, cores=3),
        # No analytic reference for the flag on the swinging bar: the finest run is the reference
        # (listed first). Delta s / Delta t = 100 m/s throughout (section 2.2).
        Study("paper flag on a swinging pendulum bar, in vacuum (structure only)", "pendulum-in-vacuum",
              "the finest run of the ladder (Delta s = 0.004 m, the paper's): no analytic solution exists",
              [({"structures": [{"n_points": [n1, n2]}], "run": {"time_step_s": ds / 100.0,
                                                                  "end_time_s": 0.5 if quick else 1.0}},
                "Delta s = %.4g m" % ds, ds / 100.0)
               for n1, n2, ds in ((n1, n2, max(0.05 / (n1 - 1), 0.1 / (n2 - 1)))
                                  for n1, n2 in ([(13, 26), (7, 13), (5, 9)] if quick else
                                                 [(26, 51), (13, 26), (9, 18), (7, 13), (5, 9)]))],
              FinerReference("flag", -1, 0.05)),
    ] + tension_studies(quick) + [flag_study(quick)]


class FinerStrouhal:
    """Strouhal number St_L = f L / U of a flapping flag (cases/flag-in-crossflow/flapping.py)
    against the finest run of the ladder (the first one): the published values quoted in the
    case README are not verified, so the report does not use them."""

    def __init__(self):
        self.reference = None

    def __call__(self, out, config):
        flapping = case_module("flag-in-crossflow", "flapping")  # the case's own measurement
        result = flapping.analyse(out)
        if self.reference is None:
            self.reference = result["St_L"]
            return 0.0, "St_L = %.4f, A / L = %.3f (reference: the finest run)" % (result["St_L"], result["A_over_L"])
        return (abs(result["St_L"] - self.reference) / self.reference,
                "St_L = %.4f, A / L = %.3f (finest: St_L = %.4f)" % (result["St_L"], result["A_over_L"],
                                                                     self.reference))


def preset(case, name):
    """cases/<case>/presets/<name>.yaml as an overlay."""
    with open(os.path.join(ROOT, "cases", case, "presets", name + ".yaml")) as f:
        return yaml.safe_load(f) or {}


def flag_study(quick):
    names = ["medium", "coarse"] if quick else ["fine", "medium", "coarse"]
    ladder = []
    for name in names:
        overlay = preset("flag-in-crossflow", name)
        dt = overlay.get("run", {}).get("time_step_s", 2.5e-5)
        ladder.append((overlay, name, dt))
    return Study("flapping flag, quasi-2D (3 processes)", "flag-in-crossflow",
                 "the finest run of the ladder (%s); St_L, with the flapping frequency from the trailing edge's "
                 "upward zero crossings over the second half of the run" % names[0], ladder, FinerStrouhal(), cores=3)


def tension_studies(quick):
    """The pendulum flag made 10 times stiffer (phi = 1000 N/m: stretching waves at 158 m/s) on
    the medium grid (Delta s = 8.3 mm, frozen-tension limit about 5e-5 s), with the paper's frozen
    tension and with solver.tension: stabilized and linearized, against one reference: the frozen tension at the
    smallest step (the first run)."""
    reference = FinerReference("flag", -1, 0.05)
    end = 0.25 if quick else 0.5

    def overlay(tension, dt):
        return ({"structures": [{"n_points": [7, 13], "solver": {"tension": tension},
                                 "material": {"coefficients": {"tension_coefficient_n_per_m": 1000.0}}}],
                 "run": {"time_step_s": dt, "end_time_s": end}}, "%s, dt = %g s" % (tension, dt), dt)

    frozen = [6.25e-6, 2.5e-5, 5e-5] if quick else [3.125e-6, 6.25e-6, 1.25e-5, 2.5e-5, 5e-5]
    stabilized = [5e-5, 2e-4, 1e-3] if quick else [2.5e-5, 5e-5, 1e-4, 2e-4, 5e-4, 1e-3]  # dividing 0.01 s
    text = ("the frozen-tension run at dt = %g s (no analytic solution; the frozen tension diverges above about "
            "5e-5 s here)" % frozen[0])
    return [Study("stiff pendulum flag (phi = 1000 N/m), frozen tension (paper)", "pendulum-in-vacuum", text,
                  [overlay("frozen", dt) for dt in frozen], reference),
            Study("stiff pendulum flag (phi = 1000 N/m), stabilized tension", "pendulum-in-vacuum", text,
                  [overlay("stabilized", dt) for dt in stabilized], reference),
            Study("stiff pendulum flag (phi = 1000 N/m), linearized tension", "pendulum-in-vacuum", text,
                  [overlay("linearized", dt) for dt in stabilized], reference)]


# ---- model only what a scene needs ---------------------------------------------------------

class Comparison:
    """One case run with the full model and with the cheaper one the scene allows: the cost of
    each and the difference in the answer. variant(config) -> the cheaper case file;
    difference(out_full, out_cheap, config) -> (number, text)."""

    def __init__(self, name, case, full, cheap, variant, difference, cores_full, cores_cheap, overlay=None,
                 preset=None):
        self.name, self.case, self.full, self.cheap = name, case, full, cheap
        self.variant, self.difference = variant, difference
        self.cores_full, self.cores_cheap = cores_full, cores_cheap
        self.overlay, self.preset = overlay or {}, preset


def openfoam_inflow(case_dir, config):
    """The uniform inflow velocity of the case's OpenFOAM folder (0/U, the inlet patch)."""
    text = open(os.path.join(case_dir, config["fluid"]["openfoam"]["case_directory"], "0", "U")).read()
    match = re.search(r"inlet\s*\{[^}]*value\s+uniform\s+\(([^)]*)\)", text)
    return [float(v) for v in match.group(1).split()]


def to_prescribed_uniform(case_dir, config):
    config = dict(config)
    config["fluid"] = {"prescribed": {"uniform": {"velocity_m_per_s": openfoam_inflow(case_dir, config)}}}
    return config


def to_laminar(case_dir, config):
    config = deep_merge(config, {"fluid": {"openfoam": {"case_directory": "openfoam-coarse-laminar"}}})
    return config


def mean_velocity_difference(out_full, out_cheap, config):
    """|mean sheet velocity, full - cheap| at the end, per the stream speed."""
    name = config["structures"][0]["name"]
    v = []
    for out in (out_full, out_cheap):
        with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
            v.append(f["structures"][name]["velocity_m_per_s"][-1].mean(axis=0))
    speed = np.linalg.norm(v[1]) if np.linalg.norm(v[1]) > 0 else 1.0
    return (float(np.linalg.norm(v[0] - v[1]) / speed),
            "mean sheet velocity at the end: NS %s m/s, prescribed %s m/s"
            % (np.array2string(v[0], precision=4), np.array2string(v[1], precision=4)))


def rag_path_difference(out_full, out_cheap, config):
    """Largest distance between the upstream-edge centroids of the two runs, per rag length."""
    s = config["structures"][0]
    length = s["size_m"][0]
    paths = [edge_centroid(out, s["name"], 0) for out in (out_full, out_cheap)]
    d = path_difference(paths[0][0], paths[0][1], paths[1][0], paths[1][1], length)
    end = [p[1][-1] for p in paths]
    return d, "upstream edge centroid at the end: DDES %s m, laminar %s m" % (
        np.array2string(end[0], precision=3), np.array2string(end[1], precision=3))


def comparisons(quick):
    return [
        Comparison("sheet carried by a uniform stream", "sheet-in-openfoam-channel",
                   "Navier-Stokes (OpenFOAM, two-way)", "prescribed uniform flow (one-way)",
                   to_prescribed_uniform, mean_velocity_difference, 3, 3),
        Comparison("rag behind a pole, Re = 0.69e5", "rag-behind-pole", "Spalart-Allmaras DDES", "laminar",
                   to_laminar, rag_path_difference, 3, 3,
                   overlay={"run": {"end_time_s": 0.1 if quick else 0.6}}),
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


def prepare_case(case_name, workdir, overlay, variant=None):
    """A copy of cases/<case_name> in workdir with the overlay merged into its case.yaml (and
    variant(case_dir, config) applied). Returns (case folder, config)."""
    case = os.path.join(workdir, "case")
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "cases", case_name), case, ignore=shutil.ignore_patterns("output"))
    config = deep_merge(yaml.safe_load(open(os.path.join(case, "case.yaml"))), overlay)
    if variant is not None:
        config = variant(case, config)
    yaml.safe_dump(config, open(os.path.join(case, "case.yaml"), "w"))
    return case, config


def launch(bin_dir, case, out, what):
    """Runs the case through the launcher. Returns the wall time (s) of the coupled time loop
    (the sum of coupling.h5's step times: start-up, meshing and a precursor are not counted), or
    of the whole run for a structure-only case."""
    start = time.monotonic()
    result = subprocess.run([sys.executable, os.path.join(ROOT, "python", "fsi", "fsi_launch.py"), "--bin-dir", bin_dir,
                             "-o", out, case], stdin=subprocess.DEVNULL, capture_output=True)
    wall = time.monotonic() - start
    if result.returncode != 0:
        raise RuntimeError("%s failed (exit %d): %s" % (what, result.returncode, result.stderr.decode()[-1500:]))
    coupling = os.path.join(out, "coupling.h5")
    if os.path.exists(coupling):
        with h5py.File(coupling, "r") as f:
            wall = float(f["timings/step_wall_s"][:].sum())
    return wall


def run_one(bin_dir, study, overlay, workdir, label):
    case, config = prepare_case(study.case, workdir, overlay)
    out = os.path.join(workdir, "out")
    shutil.rmtree(out, ignore_errors=True)
    wall = launch(bin_dir, case, out, "%s, %s" % (study.name, label))
    error, detail = study.measure(out, config)
    return wall, config["run"]["end_time_s"], error, detail


def run_comparison(bin_dir, comparison, workdir):
    """Both models of one case; returns the table row's numbers."""
    walls, outs = [], []
    for label, variant in (("full", None), ("cheap", comparison.variant)):
        case, config = prepare_case(comparison.case, os.path.join(workdir, label), comparison.overlay, variant)
        out = os.path.join(workdir, label, "out")
        walls.append(launch(bin_dir, case, out, "%s (%s model)" % (comparison.name, label)))
        outs.append(out)
    simulated = config["run"]["end_time_s"]
    difference, detail = comparison.difference(outs[0], outs[1], config)
    costs = (walls[0] * comparison.cores_full / simulated, walls[1] * comparison.cores_cheap / simulated)
    return costs, difference, detail


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


def model_cost_section(args):
    lines = ["## Model only what a scene needs", "",
             "Each case run with the full model and with the cheaper one the scene allows, the same",
             "resolution and time step: the cost of each (core-seconds per simulated second of the time",
             "loop) and how much the answer moves.", "",
             "| case | full model | cheaper model | cost full | cost cheaper | cost ratio | difference | measured |",
             "|---|---|---|---|---|---|---|---|"]
    for comparison in comparisons(args.quick):
        print("report: %s, %s against %s" % (comparison.name, comparison.full, comparison.cheap), flush=True)
        with tempfile.TemporaryDirectory(prefix="fsi-report-") as workdir:
            try:
                (full, cheap), difference, detail = run_comparison(args.bin_dir, comparison, workdir)
            except RuntimeError as e:
                reason = str(e).strip().splitlines()[-1][:300].replace("|", "/")
                lines.append("| `%s` | %s | %s | - | - | - | - | failed: %s |" % (
                    comparison.case, comparison.full, comparison.cheap, reason))
                print("  failed (%s)" % reason, flush=True)
                continue
        lines.append("| `%s` | %s | %s | %.3g | %.3g | %.2f | %.3g | %s |" % (
            comparison.case, comparison.full, comparison.cheap, full, cheap, full / cheap, difference, detail))
        print("  cost %.3g against %.3g core-s/s, difference %.3g" % (full, cheap, difference), flush=True)
    return lines + ["", "Difference: sheet, |V_NS - V_prescribed| / |V_prescribed| at the end; rag, the largest "
                        "distance between the two upstream-edge paths per rag length.", ""]


def stability_section(args):
    """The stability suite (ctest label `stability`, the same as ./fsi test --stability): its table
    of measured thresholds."""
    build_dir = os.path.dirname(os.path.abspath(args.bin_dir))
    table = os.path.join(build_dir, "stability", "stability.md")
    if args.skip_stability:
        if not os.path.exists(table):
            return ["## Stability", "", "Not run (--skip-stability) and no earlier table in %s." % table, ""]
    else:
        print("report: the stability suite (ctest -L stability)", flush=True)
        shutil.rmtree(os.path.join(build_dir, "stability", "rows"), ignore_errors=True)
        if os.path.exists(table):
            os.remove(table)
        subprocess.run(["ctest", "--test-dir", build_dir, "-L", "stability", "-j", str(os.cpu_count() or 1),
                        "--timeout", "900"], stdin=subprocess.DEVNULL, capture_output=True)
    if not os.path.exists(table):
        return ["## Stability", "", "The stability suite wrote no table (see ctest -L stability).", ""]
    text = open(table).read().splitlines()
    body = [line for line in text if not line.startswith("# ")]
    return ["## Stability (`./fsi test --stability`)", ""] + body + [""]


def run_bench(name, argv, env=None, timeout=3600):
    """Runs build/bin/bench_<name> (or a bench script) and returns its standard output, or raises
    RuntimeError naming the bench and the end of its error output."""
    result = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=timeout,
                            env=dict(os.environ, **(env or {})))
    if result.returncode != 0:
        raise RuntimeError("%s failed (exit %d): %s" % (name, result.returncode, result.stderr.strip()[-300:]))
    return result.stdout


def speed_section(args):
    """The benchmarks of issue 12 in one run, each against its reference in the same run: the
    coupling against raw TCP, the membrane step per point, the collision correction on one thread
    against all cores, and (not with --quick) the OpenFOAM fluid against stock pimpleFoam on 1 and 2
    MPI ranks."""
    bin_dir = os.path.abspath(args.bin_dir)
    lines = ["## Speed (`./fsi bench ...`): each figure against its reference in the same run", ""]

    print("report: speed, coupling over TCP loopback", flush=True)
    try:
        text = run_bench("bench_coupling", [os.path.join(bin_dir, "bench_coupling"), "--rounds", "3"])
        lines += ["### Coupling overhead per step (`./fsi bench coupling --rounds 3`)", "", "```"] + \
            text.strip().splitlines() + ["```", ""]
    except (RuntimeError, subprocess.TimeoutExpired) as e:
        lines += ["### Coupling overhead per step", "", "failed: %s" % e, ""]

    print("report: speed, membrane step per point", flush=True)
    try:
        text = run_bench("bench_structure", [
            os.path.join(bin_dir, "bench_structure"), "--benchmark_filter=n_side:(32|100|316)/collisions:0",
            "--benchmark_format=json"])
        rows = json.loads(text)["benchmarks"]
        lines += ["### Membrane step (`./fsi bench structure`), no collisions", "",
                  "| points | ms a step | ns a point | CG iterations a step |", "|---|---|---|---|"]
        for row in rows:
            ms_per_step = row["real_time"]  # the benchmark's unit is ms
            lines.append("| %d | %.3f | %.0f | %.1f |" % (row["points"], ms_per_step, 1e6 * ms_per_step / row["points"],
                                                          row["cg_iterations"]))
        lines.append("")
    except (RuntimeError, subprocess.TimeoutExpired, ValueError, KeyError) as e:
        lines += ["### Membrane step", "", "failed: %s" % e, ""]

    print("report: speed, collision correction on 1 and %d threads" % (os.cpu_count() or 1), flush=True)
    try:
        timings = {}
        for threads in ("1", str(os.cpu_count() or 1)) * 2:  # alternated, twice
            text = run_bench("bench_mesh_surface", [os.path.join(bin_dir, "bench_mesh_surface"), "3"],
                             env={"OMP_NUM_THREADS": threads, "BENCH_ONLY": "none"})
            for contact, ms_per_call in re.findall(r"contact\s+([0-9.]+) %:\s+([0-9.]+) ms per call", text):
                timings.setdefault(contact, {}).setdefault(threads, []).append(float(ms_per_call))
        many = str(os.cpu_count() or 1)
        lines += ["### Collision correction, 10^4 points against a 102k-triangle torus (`./fsi bench mesh_surface`)",
                  "", "| contact | 1 thread (ms) | %s threads (ms) | ratio |" % many, "|---|---|---|---|"]
        for contact, by_threads in timings.items():
            one, all_ = min(by_threads["1"]), min(by_threads[many])
            lines.append("| %s %% | %.2f | %.2f | %.2f |" % (contact, one, all_, all_ / one))
        lines += ["", "Best of two alternated runs each; the goal of issue 12 is under 5 ms at 100 % contact.", ""]
    except (RuntimeError, subprocess.TimeoutExpired, KeyError) as e:
        lines += ["### Collision correction", "", "failed: %s" % e, ""]

    if args.quick:
        return lines + ["(The fluid against stock pimpleFoam: not with --quick; `./fsi bench fluid --ranks 1,2`.)", ""]
    print("report: speed, the OpenFOAM fluid against stock pimpleFoam on 1 and 2 ranks (about 15 minutes)", flush=True)
    with tempfile.TemporaryDirectory(prefix="fsi-report-fluid-") as workdir:
        try:
            run_bench("bench_fluid", ["/usr/bin/python3", os.path.join(ROOT, "bench", "fluid", "bench_fluid.py"),
                                            "--bin-dir", bin_dir, "-o", workdir, "--variants", "stock,a,b,c,c2",
                                            "--ranks", "1,2", "--rounds", "1"], timeout=7200)
            table = open(os.path.join(workdir, "results.md")).read().splitlines()
            lines += [("#" + line) if line.startswith("# ") else line for line in table] + [""]
        except (RuntimeError, subprocess.TimeoutExpired, OSError) as e:
            lines += ["### The OpenFOAM fluid", "", "failed: %s" % e, ""]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--out", default=os.path.join(ROOT, "report"))
    parser.add_argument("--quick", action="store_true", help="shorter ladders (a few minutes)")
    parser.add_argument("--skip-stability", action="store_true",
                        help="do not run the stability suite; use its last table, if any")
    parser.add_argument("--skip-speed", action="store_true", help="do not run the speed benchmarks")
    parser.add_argument("--only-speed", action="store_true", help="only the speed benchmarks (report/SPEED.md)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.only_speed:
        lines = ["# Speed", "", "Machine: %s. Written %s by `./fsi report --only-speed`." % (
            machine(), datetime.datetime.now().strftime("%Y-%m-%d %H:%M")), ""] + speed_section(args)
        open(os.path.join(args.out, "SPEED.md"), "w").write("\n".join(lines))
        print("report: %s" % os.path.join(args.out, "SPEED.md"))
        return
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
                try:
                    wall, simulated, error, detail = run_one(args.bin_dir, study, overlay, workdir, label)
                except RuntimeError as e:  # a run that fails is a result too: say so, go on
                    reason = str(e).strip().splitlines()[-1][:300]
                    lines.append("| %s | %.3g | - | - | - | - | failed: %s |" % (label, dt, reason.replace("|", "/")))
                    print("  %s: failed (%s)" % (label, reason), flush=True)
                    continue
                cost = wall * study.cores / simulated
                order = ""
                if previous is not None and error > 0 and previous[1] > 0:
                    order = "%.2f" % (math.log(previous[1] / error) / math.log(previous[0] / dt))
                previous = (dt, error)
                costs.append(cost)
                errors.append(error)
                lines.append("| %s | %.3g | %.2f | %.3g | %.3e | %s | %s |" % (label, dt, wall, cost, error, order, detail))
                print("  %s: error %.3e, %.1f s" % (label, error, wall), flush=True)
        shown = [(c, e) for c, e in zip(costs, errors) if e > 0]  # a finest-run reference has none
        if shown:
            ax.loglog(*zip(*shown), "o-", label=study.name)
        lines.append("")
    lines += model_cost_section(args)
    lines += stability_section(args)
    if not args.skip_speed:
        lines += speed_section(args)
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
