#!/usr/bin/python3
"""After a run of centrifugal-pump (./fsi run calls it; ./fsi pump-curve calls it per point): the
operating point averaged over the last whole revolutions (python/fsi/pump_point.py: head H, shaft
torque T, efficiency, psi, phi, the once-per-revolution pulsation), written to
operating_point.yaml, and operating_point.png: T and H against revolutions with the averaged
window, and the spectrum of T in multiples of the rotation frequency (24 Hz), where a single
blade shows its once-per-revolution pulsation. With ParaView's Python, also the head budget of
the last fields (python/fsi/pump_head_budget.py: the total head at the suction pipe, the
impeller's outlet, the volute and the discharge pipe, beside the Euler head T omega / (rho g Q)
the shaft puts in): where the head is made and lost.
Usage: postprocess.py RESULTS_DIR CASE_DIR"""

import math
import os
import sys

import matplotlib
import yaml

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from fsi import pump_head_budget  # noqa: E402
from fsi import pump_point  # noqa: E402


def flow_rate(out):
    """The inlet's volume flow rate the run imposed (m^3/s): fluid.openfoam.operating_point of
    its effective configuration."""
    with open(os.path.join(out, "config.effective.yaml")) as f:
        return float(yaml.safe_load(f)["fluid"]["openfoam"]["operating_point"]["flow_rate_m3_per_s"])


def picture(out, omega, axis, point, path):
    (t_t, torque), (t_h, head) = pump_point.histories(out, omega, axis)
    rev = omega / (2 * math.pi)
    fig, (a, b, c) = plt.subplots(3, 1, figsize=(7, 8.5))
    a.plot(t_t * rev, torque, lw=0.8)
    b.plot(t_h * rev, head, lw=0.8, color="C1")
    for ax, t, y in ((a, t_t, torque), (b, t_h, head)):
        ax.axvspan(point["averaged_from_s"] * rev, point["averaged_to_s"] * rev, color="0.9", zorder=0)
        later = y[t * rev >= 1.0]  # the start-up transient (first revolution) off the scale
        if len(later) > 2:
            lo, hi = np.percentile(later, [0.5, 99.5])
            ax.set_ylim(lo - 0.2 * (hi - lo), hi + 0.2 * (hi - lo))
    a.axhline(point["shaft_torque_n_m"], color="k", lw=0.6, ls="--")
    b.axhline(point["head_m"], color="k", lw=0.6, ls="--")
    a.set_ylabel("shaft torque T (N m)")
    b.set_ylabel("head H (m)")
    b.set_xlabel("revolutions (shaded: averaged)")
    a.set_title("Q = %.4g L/s: H = %.3g m, T = %.3g N m, eta = %.2f"
                % (1e3 * point["flow_rate_m3_per_s"], point["head_m"], point["shaft_torque_n_m"],
                   point["efficiency"]))
    keep = (t_t > point["averaged_from_s"]) & (t_t <= point["averaged_to_s"])
    y = torque[keep] - np.mean(torque[keep])
    if len(y) > 8:
        dt = np.median(np.diff(t_t[keep]))
        spectrum = np.abs(np.fft.rfft(y)) * 2 / len(y)
        freq = np.fft.rfftfreq(len(y), dt) / rev
        c.plot(freq, spectrum, lw=0.8, color="C2")
        c.set_xlim(0, 10)
    c.set_xlabel("frequency / rotation frequency (%.3g Hz)" % rev)
    c.set_ylabel("|T| amplitude (N m)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def budget(out, design, point):
    """The head budget of the last fields, or nothing without ParaView's Python or fields."""
    try:
        rows = pump_head_budget.head_budget(os.path.join(out, "openfoam"), design)
    except (ImportError, ValueError) as error:
        sys.stderr.write("postprocess.py: no head budget (%s)\n" % error)
        return {}
    euler = point["shaft_power_w"] / (pump_head_budget.RHO * pump_head_budget.G * point["flow_rate_m3_per_s"])
    return {"head_budget_of_the_last_fields": {
        "euler_head_of_the_mean_torque_m": euler,
        "stations": [{k: round(v, 5) if isinstance(v, float) else v for k, v in row.items()} for row in rows]}}


def main():
    out, case_dir = sys.argv[1], sys.argv[2]
    omega, axis = pump_point.rotation(case_dir, "postprocess.py")
    with open(os.path.join(case_dir, "pump.yaml")) as f:
        design = yaml.safe_load(f)
    radius = 0.5 * design["impeller"]["outer_diameter_m"]
    point = pump_point.operating_point(out, omega, axis, radius, flow_rate(out))
    point.update(budget(out, design, point))
    with open(os.path.join(out, "operating_point.yaml"), "w") as f:
        f.write("# The operating point of this run (python/fsi/pump_point.py), SI units.\n")
        yaml.safe_dump(point, f, sort_keys=False)
    picture(out, omega, axis, point, os.path.join(out, "operating_point.png"))
    print("operating_point.yaml (H = %.3g m, T = %.3g N m, eta = %.2f), operating_point.png"
          % (point["head_m"], point["shaft_torque_n_m"], point["efficiency"]))


if __name__ == "__main__":
    main()
