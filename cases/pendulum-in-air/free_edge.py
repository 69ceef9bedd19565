#!/usr/bin/python3
"""The free-edge centre of a pendulum run (pendulum-in-air, pendulum-in-vacuum) relative to the
rigid bar, as in Figs. 2 and 3 of the paper, and the flag's motion relative to the bar.

    /usr/bin/python3 cases/pendulum-in-air/free_edge.py OUT [OUT_VACUUM] [--png FILE]

OUT is a run's results folder (structure.h5, config.effective.yaml). The bar is the clamped
edge: its centre c(t) lies at distance l_c from the pendulum axis (the y axis through the
origin); the rigid position of the free-edge centre is (l_c + L1) c / |c|, L1 the flag's length
down from the clamp. The free-edge centre's deflection from it is split into
  normal:        along the swing, e_t = e_y x c / |c| (positive in the direction of +theta)
  longitudinal:  along the bar, c / |c| (positive outwards, away from the axis)
Also: the flag's kinetic energy relative to the rigid rotation of the bar,
E_rel = 1/2 sum m_i |v_i - omega e_y x x_i|^2, omega the bar's angular velocity from c(t),
and the deflections' RMS after the first 0.1 s. With a second folder (the same flag in
vacuum), prints both and their differences; --png draws the free-edge deflections of both.
"""

import argparse
import os
import sys

import h5py
import numpy as np
import yaml


def load(out):
    with open(os.path.join(out, "config.effective.yaml")) as f:
        case = yaml.safe_load(f)
    flag = case["structures"][0]
    with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
        t = f["time_s"][:]
        g = f["structures"][flag["name"]]
        n1, n2 = (int(v) for v in g.attrs["grid_shape"])
        x = g["position_m"][:].reshape(len(t), n1, n2, 3)
        v = g["velocity_m_per_s"][:].reshape(len(t), n1, n2, 3)
    rho = float(flag["material"]["mass_per_area_kg_per_m2"])
    l1, l2 = (float(s) for s in flag["size_m"])
    w1 = np.full(n1, l1 / (n1 - 1))
    w1[[0, -1]] /= 2
    w2 = np.full(n2, l2 / (n2 - 1))
    w2[[0, -1]] /= 2
    mass = rho * np.outer(w1, w2)
    return t, x, v, mass, l1


def analyse(out):
    t, x, v, mass, l1 = load(out)
    n2 = x.shape[2]
    clamp = x[:, 0, :, :].mean(axis=1)             # bar bottom (the clamped edge's centre)
    clamp[:, 1] = 0.0
    l_c = np.linalg.norm(clamp, axis=1)
    e_r = clamp / l_c[:, None]                      # along the bar, outwards
    e_t = np.cross(np.array([0.0, 1.0, 0.0]), e_r)  # along the swing (+theta)
    rigid = (l_c + l1)[:, None] * e_r
    tip = x[:, -1, n2 // 2, :]
    d = tip - rigid
    normal = np.einsum("ti,ti->t", d, e_t)
    longitudinal = np.einsum("ti,ti->t", d, e_r)
    theta = np.unwrap(np.arctan2(-clamp[:, 0], -clamp[:, 2]))
    omega = np.gradient(theta, t)
    # velocity of the rigid rotation about the y axis: omega e_y x x
    rigid_v = omega[:, None, None, None] * np.cross(np.array([0.0, 1.0, 0.0]), x)
    e_rel = 0.5 * np.einsum("ij,tijk->t", mass, (v - rigid_v) ** 2)
    late = t >= 0.1
    return {"t": t, "theta": theta, "normal": normal, "longitudinal": longitudinal, "e_rel": e_rel,
            "normal_rms": float(np.sqrt(np.mean(normal[late] ** 2))),
            "longitudinal_rms": float(np.sqrt(np.mean(longitudinal[late] ** 2))),
            "e_rel_mean": float(np.mean(e_rel[late])), "theta_max_deg": float(np.degrees(np.abs(theta).max()))}


def report(name, r):
    print("%s: t = 0..%.3g s, bar |theta| <= %.2f deg; free-edge centre from the rigid bar: "
          "normal RMS %.4g m (max %.4g), longitudinal RMS %.4g m (min %.4g); E_rel mean %.4g J"
          % (name, r["t"][-1], r["theta_max_deg"], r["normal_rms"], np.abs(r["normal"]).max(),
             r["longitudinal_rms"], r["longitudinal"].min(), r["e_rel_mean"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out")
    parser.add_argument("vacuum", nargs="?")
    parser.add_argument("--png")
    args = parser.parse_args()
    air = analyse(args.out)
    report(args.out, air)
    vac = None
    if args.vacuum:
        vac = analyse(args.vacuum)
        report(args.vacuum, vac)
        n = min(len(air["t"]), len(vac["t"]))
        diff = air["normal"][:n] - vac["normal"][:n]
        print("normal deflection, air - vacuum: max |diff| %.4g m; E_rel air / vacuum = %.3g"
              % (np.abs(diff).max(), air["e_rel_mean"] / vac["e_rel_mean"]))
    if args.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(3, 1, figsize=(9, 9), sharex=True)
        for r, label in ((air, "fluid"), (vac, "vacuum")):
            if r is None:
                continue
            axes[0].plot(r["t"], 1e3 * r["normal"], label=label)
            axes[1].plot(r["t"], 1e3 * r["longitudinal"], label=label)
            axes[2].plot(r["t"], r["e_rel"], label=label)
        axes[0].set_ylabel("normal (mm)")
        axes[1].set_ylabel("longitudinal (mm)")
        axes[2].set_ylabel("E_rel (J)")
        axes[2].set_xlabel("time (s)")
        axes[0].set_title("free-edge centre relative to the rigid bar")
        for a in axes:
            a.grid(True, alpha=0.3)
            a.legend()
        ax2 = axes[0].twinx()
        ax2.plot(air["t"], np.degrees(air["theta"]), "k:", lw=0.8)
        ax2.set_ylabel("bar angle (deg, dotted)")
        fig.tight_layout()
        fig.savefig(args.png, dpi=100)
        print("wrote", args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
