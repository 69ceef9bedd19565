#!/usr/bin/python3
"""Flapping frequency and amplitude of a flag-in-crossflow run, from its structure.h5.

    /usr/bin/python3 cases/flag-in-crossflow/flapping.py OUT [--from T0]

OUT is the run's results folder (holding structure.h5 and config.effective.yaml). The
trailing edge's cross-stream offset y(t) (mean over the span, from the clamped edge's y) is
analysed after T0 (default: the second half of the run): the flapping period is the mean
spacing of its upward zero crossings, the amplitude A the peak-to-peak excursion of y over
that window. Prints f, St_L = f L / U, A / L and St_A = f A / U, U the inflow speed read from
the OpenFOAM case's 0/U.
"""

import argparse
import os
import re
import sys

import h5py
import numpy as np
import yaml


def inflow_speed(out):
    with open(os.path.join(out, "openfoam", "0", "U")) as f:
        text = f.read()
    match = re.search(r"inlet\s*\{[^}]*value\s+uniform\s+\(([^)]*)\)", text)
    return float(np.linalg.norm([float(v) for v in match.group(1).split()]))


def analyse(out, t0=None):
    with open(os.path.join(out, "config.effective.yaml")) as f:
        case = yaml.safe_load(f)
    flag = case["structures"][0]
    L = float(flag["size_m"][0])
    with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
        t = f["time_s"][:]
        g = f["structures"][flag["name"]]
        n1, n2 = (int(v) for v in g.attrs["grid_shape"])
        x = g["position_m"][:]
    y = x[:, (n1 - 1) * n2:, 1].mean(axis=1) - x[0, :n2, 1].mean()
    if t0 is None:
        t0 = t[-1] / 2
    keep = t >= t0
    tt, yy = t[keep], y[keep] - y[keep].mean()
    ups = [tt[i - 1] + (tt[i] - tt[i - 1]) * yy[i - 1] / (yy[i - 1] - yy[i])
           for i in range(1, len(tt)) if yy[i - 1] < 0 <= yy[i]]
    if len(ups) < 2:
        raise SystemExit("fewer than two upward crossings after t = %g s: no flapping to measure" % t0)
    period = float(np.mean(np.diff(ups)))
    U = inflow_speed(out)
    A = float(np.ptp(y[keep]))
    f = 1.0 / period
    return {"L": L, "U": U, "f": f, "periods": len(ups) - 1, "A": A, "St_L": f * L / U,
            "A_over_L": A / L, "St_A": f * A / U, "t0": t0}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out")
    parser.add_argument("--from", dest="t0", type=float, default=None)
    args = parser.parse_args()
    r = analyse(args.out, args.t0)
    print("after t = %.4g s (%d periods): f = %.4g Hz, St_L = f L/U = %.3f, peak-to-peak A = %.4g m "
          "= %.3f L, St_A = f A/U = %.3f" % (r["t0"], r["periods"], r["f"], r["St_L"], r["A"],
                                            r["A_over_L"], r["St_A"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
