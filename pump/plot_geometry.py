#!/usr/bin/env python3
"""Draws DIR/geometry.png from DIR/impeller.stl and DIR/casing.stl: a top view of the impeller
inside the volute (the triangles cut by the mid-channel plane), a side section (cut by the
plane through the axis and the discharge), and the impeller in 3-D seen from below, from the
suction side into its eye, shaded and coloured by region. Usage: plot_geometry.py DIR"""
import sys
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection


def read_regions(path):
    regions, current, corners = {}, None, []
    with open(path) as stl:
        for line in stl:
            words = line.split()
            if not words:
                continue
            if words[0] == "solid":
                current = words[1]
                regions.setdefault(current, [])
            elif words[0] == "vertex":
                corners.append([float(w) for w in words[1:4]])
                if len(corners) == 3:
                    regions[current].append(corners)
                    corners = []
    return {name: np.array(tris) for name, tris in regions.items()}


def cut(tris, axis, level):
    """Segments where the plane x[axis] = level cuts the triangles (n x 2 x 3)."""
    d = tris[:, :, axis] - level
    segments = []
    for tri, dist in zip(tris, d):
        points = []
        for i in range(3):
            a, b = i, (i + 1) % 3
            if (dist[a] < 0) != (dist[b] < 0):
                t = dist[a] / (dist[a] - dist[b])
                points.append(tri[a] + t * (tri[b] - tri[a]))
        if len(points) == 2:
            segments.append(points)
    return np.array(segments).reshape(-1, 2, 3)


def impeller_view(ax, impeller, colours):
    """The impeller's triangles from below and aside (the eye and its leading edge in sight)."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    light = np.array([0.3, -0.5, -0.8])
    light /= np.linalg.norm(light)
    for k, (name, tris) in enumerate(sorted(impeller.items())):
        normals = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
        normals /= np.maximum(np.linalg.norm(normals, axis=1), 1e-30)[:, None]
        shade = 0.35 + 0.65 * np.clip(normals @ light, 0.0, 1.0)
        base = np.array(matplotlib.colors.to_rgb(colours[k % len(colours)]))
        ax.add_collection3d(Poly3DCollection(tris, facecolors=shade[:, None] * base, edgecolors="none", label=name))
    points = np.concatenate(list(impeller.values())).reshape(-1, 3)
    centre, half = 0.5 * (points.max(0) + points.min(0)), 0.5 * (points.max(0) - points.min(0)).max()
    for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        setter(c - half, c + half)
    ax.view_init(elev=-65, azim=-75)
    ax.set_box_aspect((1, 1, 1))
    ax.set_title("impeller from the suction side (into the eye)")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")


def main(folder):
    impeller = read_regions(f"{folder}/impeller.stl")
    casing = read_regions(f"{folder}/casing.stl")
    all_imp = np.concatenate(list(impeller.values()))
    z_mid = 0.5 * (all_imp[:, :, 2].min() + all_imp[:, :, 2].max())
    fig = plt.figure(figsize=(21, 7.5))
    top, side = fig.add_subplot(1, 3, 1), fig.add_subplot(1, 3, 2)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]  # the impeller's regions
    casing_colours = ["0.25", "0.45", "0.6", "tab:cyan", "tab:olive", "k"]  # the casing's, in greys
    for ax, axis, level, plane in ((top, 2, z_mid, (0, 1)), (side, 1, None, (0, 2))):
        for parts, width in ((casing, 1.2), (impeller, 1.6)):
            for k, (name, tris) in enumerate(sorted(parts.items())):
                at = level
                if at is None:  # the side section: through the axis, parallel to the discharge
                    at = 0.0
                segs = cut(tris, axis, at + 1e-7)
                if len(segs):
                    palette = casing_colours if parts is casing else colours
                    ax.add_collection(LineCollection(segs[:, :, plane], colors=palette[k % len(palette)],
                                                     linewidths=width, label=name))
        ax.set_aspect("equal")
        ax.autoscale()
        ax.grid(alpha=0.3)
    top.set_title(f"top view: section z = {z_mid:.3f} m (looking along -z)")
    top.set_xlabel("x (m)")
    top.set_ylabel("y (m)")
    side.set_title("side section y = 0 (axis z up; suction pipe below)")
    side.set_xlabel("x (m)")
    side.set_ylabel("z (m)")
    side.legend(loc="upper right", fontsize=7)
    impeller_view(fig.add_subplot(1, 3, 3, projection="3d"), impeller, colours)
    fig.tight_layout()
    fig.savefig(f"{folder}/geometry.png", dpi=110)


if __name__ == "__main__":
    main(sys.argv[1])
