#!/usr/bin/python3
"""After a run of rag-behind-pole (./fsi run calls it): the motion of the centroid of the rag's
upstream edge as in the paper's Figs. 7-8, nondimensional: t* = t U / L, x* = (x - x_0) / L,
z* = (z - z_0) / L (the paper's vertical y), u* = u / U, w* = w / U, with U = 0.69 m/s the inflow,
L = 0.1 m the rag length and (x_0, z_0) the edge's start. Writes rag_path.csv and rag_path.png in
the results folder, and redraws the flow pictures (flow_t*.png) in the paper's Fig. 4 view: |U| on
the vertical plane through the rag (normal y), where the jet under the pole shows.
Usage: postprocess.py RESULTS_DIR CASE_DIR"""

import os
import subprocess
import sys

import h5py
import matplotlib
import yaml

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

U_IN = 0.69  # m/s, the inflow of make_case.py


def edges(h5_path, name):
    """Times; the centroid (trapezoid weights) of the upstream edge s1 = 0, its velocity, and the
    centroid of the downstream edge s1 = L."""
    with h5py.File(h5_path, "r") as f:
        g = f["structures"][name]
        n1, n2 = (int(v) for v in g.attrs["grid_shape"])
        x = g["position_m"][:].reshape(-1, n1, n2, 3)
        v = g["velocity_m_per_s"][:].reshape(-1, n1, n2, 3)[:, 0]
        t = f["time_s"][:]
    w = np.ones(n2)
    w[[0, -1]] = 0.5
    w /= w.sum()
    return (t, np.einsum("j,tjk->tk", w, x[:, 0]), np.einsum("j,tjk->tk", w, v),
            np.einsum("j,tjk->tk", w, x[:, -1]))


def main(out, case_dir):
    config = yaml.safe_load(open(os.path.join(case_dir, "case.yaml")))
    rag = config["structures"][0]
    length = rag["size_m"][0]
    t, x, v, x_down = edges(os.path.join(out, "structure.h5"), rag["name"])
    chord = x_down - x
    pitch = np.degrees(np.arctan2(chord[:, 2], chord[:, 0]))  # counterclockwise seen along +y (x right, z up)
    star = np.column_stack([t * U_IN / length, (x[:, 0] - x[0, 0]) / length, (x[:, 2] - x[0, 2]) / length,
                            v[:, 0] / U_IN, v[:, 2] / U_IN, pitch, t, x, v])
    np.savetxt(os.path.join(out, "rag_path.csv"), star, delimiter=",", fmt="%.9g",
               header="t_star,x_star,z_star,u_star,w_star,pitch_deg,time_s,x_m,y_m,z_m,u_m_per_s,v_m_per_s,"
                      "w_m_per_s", comments="")
    fig, axes = plt.subplots(2, 3, figsize=(14, 6), sharex=True)
    axes[0, 2].plot(star[:, 0], pitch)
    axes[0, 2].set_ylabel("pitch of the rag (deg, counterclockwise)")
    axes[0, 2].grid(alpha=0.3)
    axes[1, 2].axis("off")
    for ax, column, label in ((axes[0, 0], 1, "x* = (x - x0) / L"), (axes[1, 0], 3, "u* = u / U"),
                              (axes[0, 1], 2, "z* = (z - z0) / L (vertical)"), (axes[1, 1], 4, "w* = w / U")):
        ax.plot(star[:, 0], star[:, column])
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for ax in (axes[1, 0], axes[1, 1], axes[0, 2]):
        ax.set_xlabel("t* = t U / L")
    fig.suptitle("rag behind a pole: centroid of the upstream edge (paper Figs. 7-8), U = %g m/s, L = %g m"
                 % (U_IN, length), fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "rag_path.png"), dpi=110)
    made = ["rag_path.png", "rag_path.csv"]
    if os.path.isdir(os.path.join(out, "openfoam")):
        script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "fsi", "plot_flow.py")
        if subprocess.run([sys.executable, script, out, "--normal", "y"], capture_output=True).returncode == 0:
            made.append("flow_t*.png (side view)")
    print(", ".join(made))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
