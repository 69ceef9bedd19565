#!/usr/bin/python3
"""The quantities of a run against time: each probe's position and velocity (structure.h5,
/probes/<name>) and, in coupled runs, the forces (coupling.h5: the total force of the
structures on the fluid, and the force and torque of the fluid on each rigid body).
Usage: plot_quantities.py OUTPUT_DIR
Writes OUTPUT_DIR/quantities.png (a row per probe: x, y, z and u, v, w; a row of forces; a row
per rigid body: force and torque) and, when coupling.h5 is there, OUTPUT_DIR/forces.csv. A
run with neither probes nor coupling.h5 gets neither file (one left by an earlier run is
removed) and the script exits 0 without a word. Reads only the documented HDF5 layout
(docs/results.md). Needs Debian's python3-h5py, python3-matplotlib and python3-yaml (the
/usr/bin/python3 interpreter); runs without a display."""
import csv
import os
import sys

import h5py
import numpy as np
import yaml

from fsi.results_file import complete_rows

AXES = ("x", "y", "z")
VELOCITY_AXES = ("u", "v", "w")


def probe_order(f):
    """Probe names in the order of the case file (from the saved configuration), else sorted."""
    names = sorted(f["probes"].keys())
    try:
        config = yaml.safe_load(f.attrs["config_yaml"]) or {}
        listed = [p["name"] for p in config.get("probes") or []]
    except (KeyError, TypeError, yaml.YAMLError):
        return names
    return [n for n in listed if n in names] + [n for n in names if n not in listed]


def read_probes(h5_path):
    """[(name, time_s, position [n, 3], velocity [n, 3])], rows aligned with /time_s."""
    if not os.path.exists(h5_path):
        return []
    with h5py.File(h5_path, "r") as f:
        if "probes" not in f:
            return []
        time_s = f["time_s"][:complete_rows(f)]
        probes = []
        for name in probe_order(f):
            g = f["probes"][name]
            n = min(len(time_s), len(g["position_m"]), len(g["velocity_m_per_s"]))
            if n > 0:
                probes.append((name, time_s[:n], g["position_m"][:n], g["velocity_m_per_s"][:n]))
        return probes


def read_forces(h5_path):
    """(time_s, total force on the fluid [n, 3], {body: (force [n, 3], torque [n, 3])}) or None."""
    if not os.path.exists(h5_path):
        return None
    with h5py.File(h5_path, "r") as f:
        if "time_s" not in f or "total_force_on_fluid_n" not in f:
            return None
        bodies = {}
        for name, g in (f["rigid_bodies"].items() if "rigid_bodies" in f else []):
            bodies[name] = (g["force_n"][:], g["torque_n_m"][:])
        rows = complete_rows(f)
        time_s, total = f["time_s"][:rows], f["total_force_on_fluid_n"][:rows]
    n = min([len(time_s), len(total)] + [min(len(a), len(b)) for a, b in bodies.values()])
    return time_s[:n], total[:n], {k: (a[:n], b[:n]) for k, (a, b) in bodies.items()}


def write_forces_csv(path, forces):
    time_s, total, bodies = forces
    header = ["time_s"] + [f"total_force_on_fluid.{a}_n" for a in AXES]
    columns = [time_s[:, None], total]
    for name, (force, torque) in bodies.items():
        header += [f"{name}.force_{a}_n" for a in AXES] + [f"{name}.torque_{a}_n_m" for a in AXES]
        columns += [force, torque]
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(header)
        for row in np.hstack(columns):
            writer.writerow([f"{v + 0.0:.15g}" for v in row])  # + 0.0: no "-0"


def draw_components(ax, time_s, values, labels, ylabel, title):
    for k, label in enumerate(labels):
        ax.plot(time_s, values[:, k], label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="best")


def draw(png_path, title, probes, forces):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    bodies = forces[2] if forces else {}
    n_rows = len(probes) + (1 if forces else 0) + len(bodies)
    fig = plt.figure(figsize=(12, 2.8 * n_rows + 0.6))
    grid = fig.add_gridspec(n_rows, 2)
    row = 0
    for name, time_s, position, velocity in probes:
        draw_components(fig.add_subplot(grid[row, 0]), time_s, position, [f"{a} (m)" for a in AXES],
                        "position (m)", f"probe {name}: position")
        draw_components(fig.add_subplot(grid[row, 1]), time_s, velocity,
                        [f"{a} (m/s)" for a in VELOCITY_AXES], "velocity (m/s)", f"probe {name}: velocity")
        row += 1
    if forces:
        time_s, total, _ = forces
        draw_components(fig.add_subplot(grid[row, :]), time_s, total, [f"F_{a} (N)" for a in AXES], "force (N)",
                        "total force of the structures on the fluid (sum of F_fsi over the points)")
        row += 1
        for name, (force, torque) in bodies.items():
            draw_components(fig.add_subplot(grid[row, 0]), time_s, force, [f"F_{a} (N)" for a in AXES],
                            "force (N)", f"rigid body {name}: force of the fluid")
            draw_components(fig.add_subplot(grid[row, 1]), time_s, torque, [f"M_{a} (N m)" for a in AXES],
                            "torque (N m)", f"rigid body {name}: torque of the fluid")
            row += 1
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(png_path, dpi=100)
    plt.close(fig)


def remove_stale(path):
    if os.path.exists(path):
        os.remove(path)


def main(output_dir):
    png_path = os.path.join(output_dir, "quantities.png")
    csv_path = os.path.join(output_dir, "forces.csv")
    probes = read_probes(os.path.join(output_dir, "structure.h5"))
    forces = read_forces(os.path.join(output_dir, "coupling.h5"))
    if forces:
        write_forces_csv(csv_path, forces)
    else:
        remove_stale(csv_path)
    if probes or (forces and len(forces[0]) > 0):
        shown = " and ".join(w for w, present in (("probes", probes), ("forces", forces)) if present)
        draw(png_path, f"{output_dir}: {shown}", probes, forces)
    else:
        remove_stale(png_path)


if __name__ == "__main__":
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        sys.exit(__doc__)
    main(sys.argv[1])
