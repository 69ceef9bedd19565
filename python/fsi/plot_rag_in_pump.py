#!/usr/bin/python3
"""Pictures of a rag carried through the centrifugal pump (the paper's section 4.2, Figs. 12-14),
from a coupled run of cases/rag-in-pump (finished or interrupted):

  RUN_DIR/rag_sequence.png  Figs. 12-13: the rag at FRAMES saved times after its release, evenly
                            spaced from the release to the end of the run (or to the first frame
                            where the rag has left the casing), each time as a top view (looking
                            down the rotation axis z: casing and impeller cut at the volute's
                            mid-height, the impeller at its pose at that time, the sump dashed)
                            and a side view (the xz plane through the axis: sump, suction pipe,
                            impeller chamber; the impeller cut at its pose). The rag is seen
                            whole (projected), its grid lines and its points coloured by their
                            distance to the nearest wall (casing or impeller at that pose); its
                            centroid's path so far is dotted.
  RUN_DIR/rag_wrap.png      Fig. 14: the saved time of the rag's largest bend round the leading edge
                            (rag_metrics.yaml, when it wrapped), else when the most rag points are within
                            1.5 x collisions.threshold_m of the impeller (the first such time of
                            a tie; with no point that close, the time of the closest approach),
                            in 3D: the impeller's triangles at that pose (its blade leading edge
                            darker), the rag in red, the points in contact black; beside it the
                            number of points in contact against time. The PNG's "Description"
                            text chunk names the frame.
  RUN_DIR/rag_passage.mp4   every saved frame, top and side view side by side (ffmpeg, libx264;
                            skipped with --no-animation, a warning when ffmpeg fails).

Usage: plot_rag_in_pump.py RUN_DIR CASE_DIR [--frames 8] [--no-animation]
Python: write_pictures(run_dir, case_dir, frames=8, animation=True) -> list of files written.

Reads RUN_DIR/structure.h5 (docs/results.md) and, as python/fsi/rag_metrics.py does, the run's
configuration (RUN_DIR/config.effective.yaml, else CASE_DIR/case.yaml): the collision threshold
and surfaces, the rotating one the impeller (collisions.surfaces[].motion.rotation: its pose at
time t is its STL turned by rate_rad_per_s * t about axis_direction through axis_point_m,
right-hand rule), the other the casing; ASCII STL files with named regions. The rotation axis
must be along z. Distances (exact, rag_metrics.TriangleSet: the solver's BVH): to the walls,
the casing without its openings (inlet, outlet) and the impeller at its pose; to the impeller.
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import textwrap
import time
import warnings

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")  # read a structure.h5 still being written

import h5py  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import ListedColormap, Normalize  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

from fsi import rag_metrics  # noqa: E402  (python/fsi/rag_metrics.py: the pump's regions, exact distances)

CONTACT_FACTOR = 1.5      # a rag point is in contact within CONTACT_FACTOR x threshold of the impeller
FAR_FACTOR = 6.0          # distances are told up to FAR_FACTOR x threshold (the colour scale)
MM = 1e3                  # the pictures are in mm
CASING_GREY, IMPELLER_GREY = "0.6", "0.2"


# ---------------------------------------------------------------------------------- the run

class Run:
    """The saved frames of structure.h5: time_s [n], points [n, P, 3] (every structure's points
    one after the other) and per structure (name, first point, n1, n2)."""

    def __init__(self, run_dir):
        path = os.path.join(run_dir, "structure.h5")
        with h5py.File(path, "r") as f:
            status = f.attrs.get("status", "")
            self.status = status.decode() if isinstance(status, bytes) else str(status)
            time_s = f["time_s"][:]
            blocks, self.structures, start = [], [], 0
            for name in f["structures"]:
                g = f["structures"][name]
                n1, n2 = (int(v) for v in g.attrs["grid_shape"])
                blocks.append(g["position_m"][:])
                self.structures.append((name, start, n1, n2))
                start += n1 * n2
        if not blocks:
            raise ValueError("%s holds no structure" % path)
        n = min([len(time_s)] + [len(b) for b in blocks])  # a file still being written
        if n == 0:
            raise ValueError("%s holds no saved frame yet" % path)
        self.time_s = np.asarray(time_s[:n], float)
        self.points = np.concatenate([b[:n] for b in blocks], axis=1)
        pairs = []   # the grid lines along s1 and s2: pairs of point indices
        for _, start, n1, n2 in self.structures:
            index = start + np.arange(n1 * n2).reshape(n1, n2)
            pairs.append(np.stack([index[:-1].ravel(), index[1:].ravel()], axis=1))
            pairs.append(np.stack([index[:, :-1].ravel(), index[:, 1:].ravel()], axis=1))
        self.pairs = np.concatenate(pairs).astype(int)

    def grid_segments(self, points):
        """The rag's grid lines (along s1 and s2) as segments [m, 2, 3] of one frame's points."""
        return points[self.pairs]

    def centroids(self):
        return self.points.mean(axis=1)


# ---------------------------------------------------------------------------------- geometry

def cut(tris, point, normal):
    """The segments [m, 2, 3] where the plane through `point` with `normal` cuts the triangles
    [T, 3, 3] (vectorised: a triangle with a vertex on the plane counts it on the positive side)."""
    if len(tris) == 0:
        return np.zeros((0, 2, 3))
    d = (tris - point) @ normal                                 # [T, 3]
    a, b = d, np.roll(d, -1, axis=1)                            # the edges (0, 1), (1, 2), (2, 0)
    crosses = (a < 0) != (b < 0)
    keep = crosses.sum(axis=1) == 2
    if not keep.any():
        return np.zeros((0, 2, 3))
    tris, a, b, crosses = tris[keep], a[keep], b[keep], crosses[keep]
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(crosses, a / (a - b), 0.0)
    p = tris + s[:, :, None] * (np.roll(tris, -1, axis=1) - tris)   # [T, 3 edges, 3]
    first = np.argsort(~crosses, axis=1, kind="stable")[:, :2]       # the two crossed edges
    return np.take_along_axis(p, first[:, :, None], axis=1)


class Pump:
    """The collision surfaces of the run (rag_metrics.load_geometry: the rotating impeller, the
    casing, their regions and exact distances), with the sections the views draw."""

    def __init__(self, run_dir, case_dir):
        config, source = rag_metrics.read_config(run_dir, case_dir)
        try:
            self.geometry, self.threshold_m, _, _, _ = rag_metrics.load_geometry(case_dir, config, source)
        except rag_metrics.MetricsError:
            # config.effective.yaml names the STL files as the run was given them (relative to
            # where it was started, e.g. cases/rag-in-pump/geometry/...): the case's own then.
            path = os.path.join(case_dir, "case.yaml")
            with open(path) as f:
                config = yaml.safe_load(f) or {}
            self.geometry, self.threshold_m, _, _, _ = rag_metrics.load_geometry(case_dir, config, path)
        g = self.geometry
        self.impeller, self.casing = g.impeller, g.casing
        self.axis, self.axis_point, self.rate = g.axis, g.origin, g.rate
        if abs(abs(self.axis[2]) - 1) > 1e-9:
            raise ValueError("the impeller's axis %s is not along z" % list(self.axis))
        self.impeller_tris = self.all_tris(self.impeller)
        self.casing_tris = self.all_tris(self.casing)
        both = np.concatenate([self.impeller_tris, self.casing_tris]).reshape(-1, 3)
        self.box = both.min(axis=0), both.max(axis=0)
        # The top view's plane: the volute's mid-height (the impeller's without a volute_wall).
        volute = self.casing.get("volute_wall")
        heights = (volute if volute is not None and len(volute) else self.impeller_tris)[:, :, 2]
        self.z_mid = 0.5 * (heights.min() + heights.max())
        up, side = np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0])
        self.casing_top_at = np.array([0, 0, self.z_mid + 1e-7])
        self.casing_top = cut(self.casing_tris, self.casing_top_at, up)
        self.impeller_top = cut(self.impeller_tris, self.casing_top_at, up)   # turned per frame
        self.side_at = self.axis_point + 1e-7 * side
        self.casing_side = cut(self.casing_tris, self.side_at, side)
        # The sump (or suction pipe) just above the inlet, dashed in the top view.
        inlet = self.casing.get("inlet")
        self.sump_top = np.zeros((0, 2, 3))
        if inlet is not None and len(inlet):
            z = inlet[:, :, 2].max() + 0.1 * (self.z_mid - inlet[:, :, 2].max())
            self.sump_top = cut(self.casing_tris, np.array([0, 0, z]), up)

    @staticmethod
    def all_tris(regions):
        tris = [t for t in regions.values() if len(t)]
        return np.concatenate(tris) if tris else np.zeros((0, 3, 3))

    def revolutions(self, t):
        return abs(self.rate) * t / (2 * math.pi)

    def turn(self, points, t):
        """Points (any shape [..., 3]) turned with the impeller from its STL pose to time t."""
        return rag_metrics.rotate(points, self.axis, self.rate * t, self.axis_point)

    def impeller_top_at(self, t):
        return self.turn(self.impeller_top, t)

    def impeller_side_at(self, t):
        return cut(self.turn(self.impeller_tris, t), self.side_at, np.array([0.0, 1.0, 0.0]))

    def impeller_region_at(self, name, t):
        return self.turn(self.impeller.get(name, np.zeros((0, 3, 3))), t)


# ---------------------------------------------------------------------------------- distances

def distances(run, pump):
    """(distance of each point of each frame to the nearest wall, to the impeller) [n, P] in m,
    exact (rag_metrics.TriangleSet). The walls: the casing without its openings (inlet, outlet)
    and the impeller at its pose."""
    n, p, _ = run.points.shape
    g = pump.geometry
    to_casing = g.casing_walls.distance(run.points.reshape(-1, 3)).reshape(n, p)
    turned = g.to_impeller_frame(run.time_s, run.points)
    to_impeller = g.impeller_all.distance(turned.reshape(-1, 3)).reshape(n, p)
    return np.minimum(to_casing, to_impeller), to_impeller


def contact_counts(to_impeller, threshold_m):
    """Per frame, how many points are within CONTACT_FACTOR x threshold of the impeller."""
    return (to_impeller <= CONTACT_FACTOR * threshold_m).sum(axis=1)


def wrap_frame(to_impeller, threshold_m):
    """The frame with the most points in contact with the impeller (the first of a tie); with
    none in contact, the frame of the closest approach."""
    counts = contact_counts(to_impeller, threshold_m)
    if counts.max() > 0:
        return int(np.argmax(counts))
    return int(np.argmin(to_impeller.min(axis=1)))


def most_wrapped_frame(run_dir, times):
    """(frame, words) of the rag's largest bend round the leading edge, from the metrics'
    rag_metrics.yaml (max_wrap_angle_deg at max_wrap_angle_time_s) when it has one of at least
    its wrap angle; else None."""
    path = os.path.join(run_dir, "rag_metrics.yaml")
    if not os.path.isfile(path):
        return None
    import yaml
    with open(path) as f:
        doc = yaml.safe_load(f) or {}
    angle, time_s = doc.get("max_wrap_angle_deg"), doc.get("max_wrap_angle_time_s")
    threshold = (doc.get("parameters") or {}).get("wrap_angle_deg")
    if angle is None or time_s is None or threshold is None or angle < threshold:
        return None
    frame = int(np.argmin(np.abs(np.asarray(times, float) - time_s)))
    return frame, "its largest bend round the leading edge, %.0f deg" % angle


def sequence_frames(run, pump, count):
    """`count` frames evenly spaced from the first to the last one, or to the first frame where
    the rag is wholly out of the casing's box (it has passed)."""
    low, high = pump.box
    outside = np.any((run.points < low) | (run.points > high), axis=2).all(axis=1)
    last = int(np.argmax(outside)) if outside.any() else len(run.time_s) - 1
    count = max(1, min(count, last + 1))
    return sorted(set(int(round(v)) for v in np.linspace(0, last, count)))


# ---------------------------------------------------------------------------------- drawing

def distance_cmap():
    """Turbo reversed without its near-black ends: dark red at the wall, blue far from it."""
    return ListedColormap(plt.get_cmap("turbo_r")(np.linspace(0.04, 0.96, 256)))


class View:
    """One panel (top: x, y; side: x, z) whose impeller, rag and path follow set_frame."""

    def __init__(self, ax, kind, run, pump, wall, norm, limits, title_size=9):
        self.ax, self.kind, self.run, self.pump = ax, kind, run, pump
        self.wall = np.minimum(wall, 2 * norm.vmax / MM)   # the far ones (inf) in the "over" colour
        self.plane = (0, 1) if kind == "top" else (0, 2)
        self.title_size = title_size
        self.centroids = run.centroids()[:, self.plane] * MM
        if kind == "top":
            ax.add_collection(LineCollection(self.xy(pump.sump_top), colors=CASING_GREY,
                                             linewidths=0.7, linestyles="--"))
            casing = pump.casing_top
        else:
            casing = pump.casing_side
        ax.add_collection(LineCollection(self.xy(casing), colors=CASING_GREY, linewidths=1.0))
        self.impeller = ax.add_collection(LineCollection([], colors=IMPELLER_GREY, linewidths=1.0))
        self.path, = ax.plot([], [], ":", color="0.3", linewidth=0.9)
        self.grid = ax.add_collection(LineCollection([], cmap=norm.cmap, norm=norm, linewidths=0.9,
                                                     zorder=3))
        n = run.points.shape[1]
        self.dots = ax.scatter(np.zeros(n), np.zeros(n), s=4, c=np.zeros(n), cmap=norm.cmap,
                               norm=norm, zorder=4, linewidths=0)
        ax.set_xlim(*limits[0])
        ax.set_ylim(*limits[1])
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)", fontsize=8, labelpad=1)
        ax.set_ylabel(("y" if kind == "top" else "z") + " (mm)", fontsize=8, labelpad=1)
        ax.tick_params(labelsize=7, pad=1.5)
        ax.grid(alpha=0.2)

    def xy(self, segments):
        return np.asarray(segments)[..., self.plane] * MM

    def moving(self):
        return [self.impeller, self.path, self.grid, self.dots]

    def set_frame(self, k, title=None):
        t = self.run.time_s[k]
        points = self.run.points[k]
        self.impeller.set_segments(self.xy(self.pump.impeller_top_at(t) if self.kind == "top"
                                           else self.pump.impeller_side_at(t)))
        self.grid.set_segments(self.xy(self.run.grid_segments(points)))
        self.grid.set_array(self.wall[k][self.run.pairs].mean(axis=1) * MM)
        self.dots.set_offsets(points[:, self.plane] * MM)
        self.dots.set_array(self.wall[k] * MM)
        self.path.set_data(self.centroids[:k + 1, 0], self.centroids[:k + 1, 1])
        if title is not None:
            self.ax.set_title(title, fontsize=self.title_size, pad=3)


def view_limits(pump, run, kind):
    """Equal-aspect limits (mm) holding the casing's section (without the discharge pipe in the
    top view) and the rag at every frame."""
    plane = (0, 1) if kind == "top" else (0, 2)
    if kind == "top":
        regions = {k: v for k, v in pump.casing.items() if k not in ("discharge_wall", "outlet")}
        sections = cut(pump.all_tris(regions or pump.casing), pump.casing_top_at, np.array([0.0, 0, 1]))
        if len(sections) == 0:
            sections = pump.casing_top
    else:
        sections = pump.casing_side
    pts = [run.points.reshape(-1, 3)[:, plane]]
    if len(sections):
        pts.append(sections.reshape(-1, 3)[:, plane])
    pts = np.concatenate(pts) * MM
    low, high = np.nanmin(pts, axis=0), np.nanmax(pts, axis=0)   # NaN: a fed rag not in the scene
    margin = 0.03 * max(high - low) + 1.0
    return (low[0] - margin, high[0] + margin), (low[1] - margin, high[1] + margin)


def span(limits):
    return limits[1] - limits[0]


def frame_title(pump, t):
    return "t = %.4g s (%.2f rev)" % (t, pump.revolutions(t))


def distance_norm(pump):
    norm = Normalize(0.0, FAR_FACTOR * pump.threshold_m * MM)
    norm.cmap = distance_cmap()
    return norm


def add_colorbar(fig, mappable, axes, pump, **kwargs):
    bar = fig.colorbar(mappable, ax=axes, extend="max", **kwargs)
    bar.set_label("rag: distance to the nearest wall (mm); lines: threshold, x %.1f" % CONTACT_FACTOR,
                  fontsize=8)
    bar.ax.tick_params(labelsize=7)
    for level, style in ((pump.threshold_m, "-"), (CONTACT_FACTOR * pump.threshold_m, "--")):
        bar.ax.axhline(level * MM, color="k", linewidth=1.0, linestyle=style)
    return bar


def draw_sequence(run, pump, wall, frames, path, title):
    norm = distance_norm(pump)
    top_lim, side_lim = view_limits(pump, run, "top"), view_limits(pump, run, "side")
    columns = min(len(frames), 4)
    pairs = int(math.ceil(len(frames) / columns))
    width = max(3.3, 6.0 / columns)   # a single frame gets a larger panel
    top_h = width * span(top_lim[1]) / span(top_lim[0])
    side_h = width * span(side_lim[1]) / span(side_lim[0])
    fig_w = columns * width + 1.6
    title = "\n".join(textwrap.fill(line, int(13 * fig_w)) for line in title.split("\n"))
    fig = plt.figure(figsize=(fig_w, pairs * (top_h + side_h + 0.9) + 0.25 * title.count("\n") + 0.5),
                     constrained_layout=True)
    fig.set_constrained_layout_pads(w_pad=0.02, h_pad=0.02, wspace=0.02, hspace=0.02)
    axes = fig.subplots(2 * pairs, columns, squeeze=False,
                        gridspec_kw={"height_ratios": [top_h, side_h] * pairs})
    for n in range(pairs * columns):
        row, col = 2 * (n // columns), n % columns
        if n >= len(frames):
            axes[row, col].axis("off")
            axes[row + 1, col].axis("off")
            continue
        k = frames[n]
        t = run.time_s[k]
        top = View(axes[row, col], "top", run, pump, wall, norm, top_lim)
        top.set_frame(k, "%s\ntop (z = %.0f mm)" % (frame_title(pump, t), pump.z_mid * MM))
        side = View(axes[row + 1, col], "side", run, pump, wall, norm, side_lim)
        side.set_frame(k, "side (y = %.0f mm)" % (pump.axis_point[1] * MM))
    add_colorbar(fig, top.dots, axes, pump, fraction=0.03, pad=0.01, aspect=40, shrink=0.5)
    fig.suptitle(title, fontsize=10)
    fig.savefig(path, dpi=100)
    plt.close(fig)


def draw_wrap(run, pump, to_impeller, k, path, title):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    t = run.time_s[k]
    counts = contact_counts(to_impeller, pump.threshold_m)
    contact = CONTACT_FACTOR * pump.threshold_m
    fig = plt.figure(figsize=(14, 7.5))
    ax = fig.add_axes([0.0, 0.0, 0.6, 0.84], projection="3d", computed_zorder=False)
    looks = {"blade_leading_edge": ("navy", 0.9), "blade_pressure_side": ("tab:blue", 0.3),
             "blade_suction_side": ("tab:blue", 0.3), "blade_trailing_edge": ("tab:blue", 0.3)}
    for name, tris in sorted(pump.impeller.items(), key=lambda item: item[0] in looks):
        colour, alpha = looks.get(name, ("lightblue", 0.12))
        ax.add_collection3d(Poly3DCollection(pump.impeller_region_at(name, t) * MM, facecolors=colour,
                                             alpha=alpha, edgecolors="none", zorder=1))
    points = run.points[k]
    near = to_impeller[k] <= contact
    ax.add_collection3d(Line3DCollection(run.grid_segments(points) * MM, colors="red",
                                         linewidths=1.0, zorder=3))
    ax.scatter(*(points[~near] * MM).T, s=6, color="red", zorder=4, depthshade=False, label="rag")
    ax.scatter(*(points[near] * MM).T, s=18, color="k", zorder=5, depthshade=False,
               label="rag points within %.1f mm of the impeller: %d" % (contact * MM, near.sum()))
    both = np.concatenate([pump.impeller_tris.reshape(-1, 3), points]) * MM
    low, high = both.min(axis=0), both.max(axis=0)
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_zlim(low[2], high[2])
    ax.set_box_aspect(np.maximum(high - low, 1e-9), zoom=1.15)
    ax.view_init(elev=-28, azim=-60)   # from below: into the eye, where the rag comes from
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_zlabel("z (mm)")
    ax.legend(loc="lower left", fontsize=8)
    side = fig.add_axes([0.66, 0.12, 0.31, 0.68])
    revs = pump.revolutions(run.time_s)
    side.plot(revs, counts, "-o", markersize=2.5, linewidth=1.0)
    side.plot([revs[k]], [counts[k]], "o", color="red", markersize=7, label="pictured")
    side.set_xlabel("revolutions since the release")
    side.set_ylabel("rag points within %.1f mm of the impeller" % (contact * MM))
    side.yaxis.set_major_locator(MaxNLocator(integer=True))
    side.set_title("contact with the impeller (of %d points)" % run.points.shape[1], fontsize=10)
    side.grid(alpha=0.3)
    side.legend(fontsize=8)
    fig.suptitle("%s\n%s: the impeller at its pose (blades blue, leading edge dark blue, hub and "
                 "shroud light) and the rag (red), seen from below" % (title, frame_title(pump, t)),
                 fontsize=11)
    fig.savefig(path, dpi=100, metadata={
        "Description": "frame %d of %d, t = %.9g s, %d points in contact" % (k, len(run.time_s), t, counts[k])})
    plt.close(fig)


def draw_animation(run, pump, wall, path, title):
    """Every frame, top and side views side by side, piped to ffmpeg; False when it failed."""
    ffmpeg = shutil.which("ffmpeg")
    if ffmpeg is None:
        warnings.warn("plot_rag_in_pump.py: no ffmpeg on PATH: no %s" % path)
        return False
    norm = distance_norm(pump)
    top_lim, side_lim = view_limits(pump, run, "top"), view_limits(pump, run, "side")
    height = 5.0
    top_w = height * span(top_lim[0]) / span(top_lim[1])
    side_w = height * span(side_lim[0]) / span(side_lim[1])
    fig = plt.figure(figsize=(top_w + side_w + 1.4, height + 0.8), dpi=100, constrained_layout=True)
    axes = fig.subplots(1, 2, gridspec_kw={"width_ratios": [top_w, side_w]})
    top = View(axes[0], "top", run, pump, wall, norm, top_lim, title_size=10)
    side = View(axes[1], "side", run, pump, wall, norm, side_lim, title_size=10)
    top.ax.set_title("top (section z = %.0f mm)" % (pump.z_mid * MM), fontsize=10)
    side.ax.set_title("side (section y = %.0f mm)" % (pump.axis_point[1] * MM), fontsize=10)
    add_colorbar(fig, top.dots, [top.ax, side.ax], pump, fraction=0.025, pad=0.02)
    stamp = fig.suptitle("%s: %s, frame %d of %d" % (title, frame_title(pump, run.time_s[-1]), len(run.time_s),
                                                    len(run.time_s)), fontsize=11)
    fig.canvas.draw()
    fig.set_layout_engine("none")   # the layout of this first draw for every frame
    moving = [stamp] + top.moving() + side.moving()
    for artist in moving:
        artist.set_animated(True)
    fig.canvas.draw()                # everything that does not move, once
    background = fig.canvas.copy_from_bbox(fig.bbox)
    w, h = fig.canvas.get_width_height()
    fps = min(20, max(4, int(round(len(run.time_s) / 10))))
    command = [ffmpeg, "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgba",
               "-s", "%dx%d" % (w, h), "-r", str(fps), "-i", "-",
               "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white", "-c:v", "libx264",
               "-preset", "veryfast", "-crf", "26", "-pix_fmt", "yuv420p", "-movflags", "+faststart",
               path]
    ok = False
    try:
        process = subprocess.Popen(command, stdin=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            for k, t in enumerate(run.time_s):
                top.set_frame(k)
                side.set_frame(k)
                stamp.set_text("%s: %s, frame %d of %d" % (title, frame_title(pump, t), k + 1, len(run.time_s)))
                fig.canvas.restore_region(background)
                for artist in moving:
                    fig.draw_artist(artist)
                process.stdin.write(fig.canvas.buffer_rgba().tobytes())
            process.stdin.close()
        except BrokenPipeError:
            pass
        error = process.stderr.read().decode("utf-8", "replace")
        ok = process.wait() == 0
        if not ok:
            warnings.warn("plot_rag_in_pump.py: ffmpeg failed (%s): no %s" % (error.strip()[-300:], path))
    except OSError as e:
        warnings.warn("plot_rag_in_pump.py: ffmpeg failed (%s): no %s" % (e, path))
    plt.close(fig)
    if not ok and os.path.exists(path):
        os.remove(path)
    return ok


def write_pictures(run_dir, case_dir, frames=8, animation=True):
    """rag_sequence.png, rag_wrap.png and (animation) rag_passage.mp4 in run_dir; returns the
    paths written."""
    run = Run(run_dir)
    pump = Pump(run_dir, case_dir)
    wall, to_impeller = distances(run, pump)
    name = os.path.basename(os.path.normpath(case_dir))
    title = "%s (%s)" % (name, run.status)
    written = []
    picks = sequence_frames(run, pump, frames)
    path = os.path.join(run_dir, "rag_sequence.png")
    draw_sequence(run, pump, wall, picks, path,
                  "%s: the rag at %d saved time%s after its release\ntop: the section at the volute's "
                  "mid-height, looking down the axis; side: the section through the axis; casing light "
                  "grey (sump dashed),\nimpeller dark grey at its pose; the rag seen whole, coloured by "
                  "the distance to the nearest wall; its centroid's path dotted"
                  % (title, len(picks), "" if len(picks) == 1 else "s"))
    written.append(path)
    k, what = wrap_frame(to_impeller, pump.threshold_m), "its largest contact with the impeller"
    wrapped = most_wrapped_frame(run_dir, run.time_s)
    if wrapped is not None:
        k, what = wrapped
    path = os.path.join(run_dir, "rag_wrap.png")
    draw_wrap(run, pump, to_impeller, k, path,
              "%s: the rag at %s (frame %d of %d)" % (title, what, k, len(run.time_s)))
    written.append(path)
    if animation:
        path = os.path.join(run_dir, "rag_passage.mp4")
        if draw_animation(run, pump, wall, path, title):
            written.append(path)
    return written


def main(argv=None):
    p = argparse.ArgumentParser(prog="plot_rag_in_pump.py", description=__doc__.split("\n\n")[0])
    p.add_argument("run_dir")
    p.add_argument("case_dir")
    p.add_argument("--frames", type=int, default=8, help="panels of rag_sequence.png (default 8)")
    p.add_argument("--no-animation", action="store_true", help="no rag_passage.mp4")
    args = p.parse_args(argv)
    start = time.time()
    for path in write_pictures(args.run_dir, args.case_dir, args.frames, not args.no_animation):
        print("picture: %s" % path)
    print("plot_rag_in_pump.py: %.1f s" % (time.time() - start))
    return 0


if __name__ == "__main__":
    sys.exit(main())
