#!/usr/bin/python3
"""Summary picture of a structure run: snapshots of every structure in 3D at a few times,
and the energies against time. Usage: plot_structure.py RESULTS.h5 OUTPUT.png
Reads only the documented HDF5 layout (see docs/results.md). Needs Debian's python3-h5py
and python3-matplotlib (the /usr/bin/python3 interpreter); runs without a display."""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from fsi.results_file import complete_rows  # noqa: E402
import numpy as np  # noqa: E402


def snapshot_indices(n_saved, count=5):
    return sorted(set(np.linspace(0, n_saved - 1, min(count, n_saved)).astype(int)))


def draw_structure(ax, positions, grid_shape, color, label):
    n1, n2 = (int(v) for v in grid_shape)
    x, y, z = (positions[:, k].reshape(n1, n2) for k in range(3))
    if n2 == 1:
        ax.plot(x[:, 0], y[:, 0], z[:, 0], color=color, label=label)
    else:
        ax.plot_wireframe(x, y, z, color=color, linewidth=0.5, label=label,
                          rstride=max(1, n1 // 12), cstride=max(1, n2 // 12))


def main(h5_path, png_path):
    with h5py.File(h5_path, "r") as f:
        time_s = f["time_s"][:complete_rows(f)]
        status = f.attrs["status"]
        names = list(f["structures"].keys())
        fig = plt.figure(figsize=(12, 5.5))
        ax3d = fig.add_subplot(1, 2, 1, projection="3d")
        ax_e = fig.add_subplot(1, 2, 2)
        picks = snapshot_indices(len(time_s))
        colors = plt.cm.viridis(np.linspace(0.0, 0.9, len(picks)))
        for name in names:
            g = f["structures"][name]
            for color, k in zip(colors, picks):
                draw_structure(ax3d, g["position_m"][k], g.attrs["grid_shape"], color, f"{name} t = {time_s[k]:.3g} s")
            kinetic, elastic, potential = (g[d][:] for d in ("kinetic_energy_j", "elastic_energy_j", "potential_energy_j"))
            ax_e.plot(time_s, kinetic, label=f"{name}: kinetic")
            ax_e.plot(time_s, elastic, label=f"{name}: elastic")
            ax_e.plot(time_s, potential - potential[0], label=f"{name}: potential - initial")
            ax_e.plot(time_s, kinetic + elastic + potential - potential[0], "k--", label=f"{name}: total - initial potential")
        ax3d.set_xlabel("x (m)")
        ax3d.set_ylabel("y (m)")
        ax3d.set_zlabel("z (m)")
        ax3d.set_title("snapshots")
        ax3d.legend(fontsize=7, loc="upper left")
        try:
            ax3d.set_box_aspect(np.ptp(np.concatenate(
                [f["structures"][n]["position_m"][picks].reshape(-1, 3) for n in names]), axis=0) + 1e-9)
        except AttributeError:
            pass
        ax_e.set_xlabel("time (s)")
        ax_e.set_ylabel("energy (J)")
        ax_e.set_title("energies")
        ax_e.legend(fontsize=7)
        ax_e.grid(alpha=0.3)
        fig.suptitle(f"{h5_path} ({status})", fontsize=9)
        fig.tight_layout()
        fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
