#!/usr/bin/python3
"""The clogging metrics of a rag carried through a centrifugal pump (issue 13), per run.

    rag_metrics.py RUN_DIR CASE_DIR [--n-max-revolutions N] [--wrap-angle-deg A] [--wrap-reach-m R]
                   [--contact-distance-m D] [--clean-operating-point FILE] [--structure NAME]

RUN_DIR is a coupled run's output folder (structure.h5; forces.csv or coupling.h5 and
openfoam/postProcessing for what the rag costs the pump), CASE_DIR the case folder (case.yaml,
the collision surfaces: the rotating impeller STL and the casing STL with their named regions).
Writes RUN_DIR/rag_metrics.csv (one row), RUN_DIR/rag_metrics.yaml (the same with the
parameters and the definitions) and RUN_DIR/rag_summary.png (one page for a pump designer).
docs/rag-metrics.md defines every metric exactly as computed here.

As a module: write_metrics(run_dir, case_dir, **options) -> metrics dict (what the CLI does);
compute_metrics(times, positions, grid_shape, geometry, threshold_m, ...) -> metrics dict from
arrays (tests feed synthetic trajectories); PumpGeometry (the regions and the derived radii and
heights); TriangleSet.distance (exact point-to-triangle-mesh distances). The geometry (STL
regions, distances, self-contacts) is the solver's own, through surface_engine.

Frames and durations: the saved frames t_0 < ... < t_{n-1} of structure.h5; frame k stands for
the times nearer to it than to any other frame, [e_k, e_{k+1}] with e_0 = t_0,
e_k = (t_{k-1} + t_k) / 2, e_n = t_{n-1} (so the durations sum to the run). A contact lasting
from frame a to frame b counts e_{b+1} - e_a: exact within one frame's duration.
Frames of reference: the impeller at time t is its STL rotated by rate * t about the axis
(right-hand rule); rag points are compared with the impeller's regions after rotating them by
-rate * t, with the casing's regions as they are.
"""

import argparse
import csv
import math
import os
import sys
import types

import numpy as np

from fsi import surface_engine
from fsi.results_file import complete_rows


IMPELLER_REGIONS = ("blade_leading_edge", "blade_pressure_side", "blade_suction_side", "blade_trailing_edge",
                    "hub", "shroud", "eye")
CASING_REGIONS = ("inlet", "suction_wall", "volute_wall", "cut_water", "discharge_wall", "outlet")
REQUIRED_IMPELLER = ("blade_leading_edge",)
REQUIRED_CASING = ("suction_wall", "volute_wall", "cut_water", "discharge_wall")
OPENINGS = ("inlet", "outlet")  # not walls: no contacts, no wall distance
BLADE = ("blade_leading_edge", "blade_pressure_side", "blade_suction_side", "blade_trailing_edge")

# Trap sites, in the order of the histogram, with what defines them (docs/rag-metrics.md).
SITES = ("eye_and_hub", "shroud", "leading_edge", "blade_sides", "side_gap", "cut_water", "volute_wall",
         "discharge", "suction")
SITE_DEFINITIONS = {
    "eye_and_hub": "the eye region; the hub inside the blade channel; the shroud's eye lip (a point on the "
                   "suction side of the channel inside the eye radius)",
    "shroud": "the shroud inside the blade channel (its channel face)",
    "leading_edge": "blade_leading_edge",
    "blade_sides": "blade_pressure_side, blade_suction_side, blade_trailing_edge",
    "side_gap": "the hub or the shroud touched from outside the blade channel: a point beyond the blade outlet "
                "radius, above the channel's hub-side bound, or below its shroud-side bound outside the eye radius",
    "cut_water": "cut_water",
    "volute_wall": "volute_wall (the spiral and the chamber's walls)",
    "discharge": "discharge_wall",
    "suction": "suction_wall (the suction pipe, and the sump when there is one)",
}

# Section 4.2 of the paper (the long rag, 15 cm x 5 cm). Its wrap fraction is of the simulated
# time, about 5 revolutions (1.5 rev = 30 %, 2.4 rev = 50 %).
PAPER = {
    "Q_BEP": {"wrap_fraction_of_run": 0.30, "longest_wrap_revolutions": 1.5, "time_to_cut_water_s": 0.10},
    "0.36 Q_BEP": {"wrap_fraction_of_run": 0.50, "longest_wrap_revolutions": 2.4, "time_to_cut_water_s": 0.14},
    "max_strain": 0.03,
}

DEFAULTS = {
    "n_max_revolutions": 10.0,
    "wrap_angle_deg": 90.0,
    "wrap_reach_m": 0.02,
    "contact_distance_m": None,      # None: 1.5 d_c
    "cut_water_distance_m": None,    # None: 2 d_c
    "site_min_points": 1,
    "self_contact_distance_m": None,  # None: d_c
    "phase_bins": 12,
    "settle_revolutions": None,      # None: 0 after a precursor, else 1 (write_metrics)
    "clean_operating_point": None,
    "structure": None,
    "discharge_radius_m": None,      # None: the volute's outer radius from the geometry
    "picture": True,
}

G = 9.81
EDGE_WINDOW_M = 0.02   # the leading edge's triangles within this of a point give its local direction


class MetricsError(Exception):
    """A missing file, key or region, said with what is allowed."""


# --------------------------------------------------------------------------------------------
# Geometry: STL regions and exact distances


def read_stl_regions(path):
    """{solid name: triangles [n, 3, 3]} of an ASCII STL with named solids (the generator's
    regions), read by the solver's STL reader (surface_engine). Raises MetricsError for a
    missing file, a binary STL or a file the reader refuses."""
    if not os.path.isfile(path):
        raise MetricsError("%s: no such file" % path)
    with open(path, "rb") as f:
        head = f.read(4096)
    if not head.lstrip().lower().startswith(b"solid") or b"facet" not in head:
        raise MetricsError("%s: not an ASCII STL with named solids (the regions are read from 'solid NAME' "
                           "blocks; a binary STL has none)" % path)
    try:
        return surface_engine.engine().regions(path)
    except surface_engine.EngineError as error:
        raise MetricsError(str(error))


class TriangleSet:
    """A triangle set (one region, or several with a label per triangle) with exact distances,
    answered by the solver's triangle BVH (surface_engine; zero-area triangles are left out)."""

    def __init__(self, triangles, labels=None):
        tri = np.asarray(triangles, float).reshape(-1, 3, 3)
        self.labels = np.zeros(len(tri), int) if labels is None else np.asarray(labels)
        self.engine = surface_engine.engine()
        try:
            self.id, self.n = self.engine.add_set(tri)
        except surface_engine.EngineError as error:
            raise MetricsError(str(error))

    def distance(self, points, cap=None, return_index=False):
        """Distances of points [m, 3] to the set. Without cap: exact. With cap (a number or one
        per point): exact where the distance is <= cap, else inf. return_index: also the
        nearest triangle (-1 beyond the cap)."""
        points = np.asarray(points, float).reshape(-1, 3)
        caps = None if cap is None else np.broadcast_to(np.asarray(cap, float), (len(points),))
        best, nearest = self.engine.nearest(self.id, points, caps)
        return (best, nearest) if return_index else best


def rotate(points, axis, angle, origin):
    """Points [..., 3] rotated by angle (rad; scalar or one per leading index of a [F, N, 3]
    array) about the unit axis through origin, right-hand rule (Rodrigues)."""
    v = np.asarray(points, float) - origin
    angle = np.asarray(angle, float)
    if angle.ndim == 1:
        angle = angle[:, None, None]
    cos, sin = np.cos(angle), np.sin(angle)
    cross = np.cross(axis, v)
    along = (v @ axis)[..., None] * axis
    return v * cos + cross * sin + along * (1.0 - cos) + origin


class PumpGeometry:
    """The impeller's and the casing's regions and what the metrics derive from them:
    up            unit vector along the axis from the suction towards the impeller
    entry_axial   the chamber's entry: the top of suction_wall (its largest axial coordinate)
    volute_radius the largest distance from the axis of volute_wall and cut_water (or given)
    blade_outlet_radius  the largest distance from the axis of the blade regions
    channel       the blade channel's axial range: blade_trailing_edge's (else the blade's)
    eye_radius    the eye region's largest distance from the axis (else the shroud's smallest)
    le_hub_axial, le_shroud_axial  the leading edge's axial ends on the hub and the shroud side
    Axial coordinates are (x - axis point) . up, in m."""

    def __init__(self, impeller_regions, casing_regions, axis_point_m, axis_direction, rate_rad_per_s,
                 discharge_radius_m=None, impeller_file="impeller", casing_file="casing"):
        missing = [r for r in REQUIRED_IMPELLER if r not in impeller_regions]
        if missing:
            raise MetricsError("%s: no region %s (found %s; the metrics need %s)" % (
                impeller_file, ", ".join(missing), ", ".join(sorted(impeller_regions)), ", ".join(REQUIRED_IMPELLER)))
        missing = [r for r in REQUIRED_CASING if r not in casing_regions]
        if missing:
            raise MetricsError("%s: no region %s (found %s; the metrics need %s)" % (
                casing_file, ", ".join(missing), ", ".join(sorted(casing_regions)), ", ".join(REQUIRED_CASING)))
        axis = np.asarray(axis_direction, float)
        if not np.linalg.norm(axis) > 0:
            raise MetricsError("rotation axis_direction %s: not a direction" % list(axis_direction))
        self.axis = axis / np.linalg.norm(axis)
        self.origin = np.asarray(axis_point_m, float)
        self.rate = float(rate_rad_per_s)
        self.impeller = {k: np.asarray(v, float) for k, v in impeller_regions.items()}
        self.casing = {k: np.asarray(v, float) for k, v in casing_regions.items()}
        self.sets = {("impeller", k): TriangleSet(v) for k, v in self.impeller.items()}
        self.sets.update({("casing", k): TriangleSet(v) for k, v in self.casing.items()})
        low = self.casing["inlet"] if "inlet" in self.casing else self.casing["suction_wall"]
        impeller_centre = np.concatenate([v.reshape(-1, 3) for v in self.impeller.values()]).mean(axis=0)
        sign = 1.0 if (impeller_centre - low.reshape(-1, 3).mean(axis=0)) @ self.axis >= 0 else -1.0
        self.up = sign * self.axis
        self.entry_axial = float(np.max(self.axial(self.casing["suction_wall"].reshape(-1, 3))))
        rim = np.concatenate([self.casing["volute_wall"].reshape(-1, 3), self.casing["cut_water"].reshape(-1, 3)])
        self.volute_radius = float(discharge_radius_m) if discharge_radius_m else float(np.max(self.radius(rim)))
        blade = np.concatenate([self.impeller[k].reshape(-1, 3) for k in BLADE if k in self.impeller])
        self.blade_outlet_radius = float(np.max(self.radius(blade)))
        channel = self.impeller.get("blade_trailing_edge", blade).reshape(-1, 3)
        self.channel = (float(np.min(self.axial(channel))), float(np.max(self.axial(channel))))
        if "eye" in self.impeller:
            self.eye_radius = float(np.max(self.radius(self.impeller["eye"].reshape(-1, 3))))
        elif "shroud" in self.impeller:
            self.eye_radius = float(np.min(self.radius(self.impeller["shroud"].reshape(-1, 3))))
        else:
            self.eye_radius = 0.0
        le = self.axial(self.impeller["blade_leading_edge"].reshape(-1, 3))
        lo, hi = float(np.min(le)), float(np.max(le))
        if "hub" in self.impeller and "shroud" in self.impeller:
            hub_above = np.mean(self.axial(self.impeller["hub"].reshape(-1, 3))) > np.mean(
                self.axial(self.impeller["shroud"].reshape(-1, 3)))
            self.le_hub_axial, self.le_shroud_axial = (hi, lo) if hub_above else (lo, hi)
            self.hub_above = bool(hub_above)
        else:
            self.le_hub_axial, self.le_shroud_axial = None, None
            self.hub_above = True
        self.leading_edge_axes = EdgeAxes(self.impeller["blade_leading_edge"],
                                          self.sets[("impeller", "blade_leading_edge")], EDGE_WINDOW_M)
        walls = [k for k in self.casing if k not in OPENINGS]
        self.casing_walls = TriangleSet(np.concatenate([self.casing[k] for k in walls]),
                                        np.concatenate([[k] * len(self.casing[k]) for k in walls]))
        self.impeller_all = TriangleSet(np.concatenate([self.impeller[k] for k in self.impeller]),
                                        np.concatenate([[k] * len(self.impeller[k]) for k in self.impeller]))

    def axial(self, x):
        return (np.asarray(x, float) - self.origin) @ self.up

    def radius(self, x):
        v = np.asarray(x, float) - self.origin
        return np.linalg.norm(v - (v @ self.axis)[..., None] * self.axis, axis=-1)

    def to_impeller_frame(self, times, positions):
        """Positions [F, N, 3] at times [F] in the impeller's frame (rotated by -rate t)."""
        return rotate(positions, self.axis, -self.rate * np.asarray(times, float), self.origin)

    def describe(self):
        return {"rotation_axis": [float(v) + 0.0 for v in self.axis], "axis_point_m": [float(v) + 0.0 for v in self.origin],
                "rotation_rate_rad_per_s": self.rate, "up_towards_impeller": [float(v) + 0.0 for v in self.up],
                "chamber_entry_axial_m": self.entry_axial, "volute_radius_m": self.volute_radius,
                "blade_outlet_radius_m": self.blade_outlet_radius, "blade_channel_axial_m": list(self.channel),
                "eye_radius_m": self.eye_radius,
                "leading_edge_hub_end_axial_m": self.le_hub_axial, "leading_edge_shroud_end_axial_m": self.le_shroud_axial,
                "impeller_regions": sorted(self.impeller), "casing_regions": sorted(self.casing)}


# --------------------------------------------------------------------------------------------
# Metrics from arrays


def frame_edges(times):
    """e_0 = t_0, e_k = (t_{k-1} + t_k) / 2, e_n = t_{n-1}: frame k stands for [e_k, e_{k+1}]."""
    t = np.asarray(times, float)
    return np.concatenate([[t[0]], 0.5 * (t[1:] + t[:-1]), [t[-1]]])


def clipped_durations(edges, lo, hi):
    return np.clip(np.minimum(edges[1:], hi) - np.maximum(edges[:-1], lo), 0.0, None)


def runs_of(flags):
    """[(first, last)] of the runs of consecutive True."""
    f = np.concatenate([[False], np.asarray(flags, bool), [False]])
    d = np.diff(f.astype(int))
    return list(zip(np.nonzero(d == 1)[0], np.nonzero(d == -1)[0] - 1))


def grid_edges(grid_shape):
    """Index pairs of the grid's edges: (i1, i2)-(i1+1, i2) and (i1, i2)-(i1, i2+1)."""
    n1, n2 = int(grid_shape[0]), int(grid_shape[1]) if len(grid_shape) > 1 else 1
    index = np.arange(n1 * n2).reshape(n1, n2)
    pairs = [np.stack([index[:-1, :].ravel(), index[1:, :].ravel()], axis=1)]
    if n2 > 1:
        pairs.append(np.stack([index[:, :-1].ravel(), index[:, 1:].ravel()], axis=1))
    return np.concatenate(pairs)


def _self_pairs(positions, grid_shape, distance):
    """[P, 3] (frame, i, j): the pairs of points of each frame closer than distance that are not
    grid neighbours (|i1 - j1| <= 1 and |i2 - j2| <= 1); the pairs from the solver's spatial
    hash (surface_engine)."""
    n2 = int(grid_shape[1]) if len(grid_shape) > 1 else 1
    return surface_engine.engine().pairs(positions, distance, grid_columns=n2)


def self_contacts(positions, grid_shape, distance):
    """Per frame, the pairs of points closer than distance that are not grid neighbours."""
    positions = np.asarray(positions, float)
    return np.bincount(_self_pairs(positions, grid_shape, distance)[:, 0], minlength=len(positions)).astype(int)


def in_contact(positions, grid_shape, distance):
    """[F, N] points with another point of the rag closer than distance that is not a grid
    neighbour: the rag touching itself."""
    positions = np.asarray(positions, float)
    touching = np.zeros(positions.shape[:2], bool)
    pairs = _self_pairs(positions, grid_shape, distance)
    touching[pairs[:, 0], pairs[:, 1]] = True
    touching[pairs[:, 0], pairs[:, 2]] = True
    return touching


def phase_mean(t, y, rate, bins):
    """Mean of y over the samples, phase-averaged when every one of `bins` impeller-angle bins
    has samples (each bin's mean weighted equally: the once-per-revolution pulsation drops
    out); else the plain mean. (value, phase_averaged) or (None, None) without samples."""
    if len(y) == 0:
        return None, None
    phase = np.floor(np.mod(rate * np.asarray(t), 2 * math.pi) / (2 * math.pi) * bins).astype(int) % bins
    counts = np.bincount(phase, minlength=bins)
    if bins > 0 and np.all(counts > 0):
        sums = np.bincount(phase, weights=y, minlength=bins)
        return float(np.mean(sums / counts)), True
    return float(np.mean(y)), False


def _opt(x):
    """None (an empty field: never reached, no data) or a float."""
    return None if x is None or not math.isfinite(float(x)) else float(x)


def analyse(times, positions, grid_shape, geometry, threshold_m, loads=None, clean=None, **options):
    """(metrics, series) of a trajectory: times [F] (s), positions [F, N, 3] (m, lab frame),
    grid_shape (n1, n2), a PumpGeometry, threshold_m = d_c. loads: optional
    {"torque": (t, shaft torque N m), "head": (t, head m)}; clean: optional {"torque": N m,
    "head": m} of the clean pump. options: see DEFAULTS. Metrics are SI floats, None where
    undefined (never reached, no data: an empty field)."""
    opt = _analysis_options(options)
    run = _Trajectory(times, positions, grid_shape, geometry, threshold_m, opt)
    exit_ = _outcome_and_exit(run, geometry)
    stay = _residence(run, geometry, exit_.t_exit)
    cut_water = _cut_water(run)
    wrap = _wrap(run, geometry, stay, grid_shape)
    sites = _trap_sites(run, geometry)
    mechanics = _rag_mechanics(run, geometry, grid_shape)
    cost = _cost(run.t, run.edges, wrap.flags, loads, clean, run.rate, opt)
    metrics = {**exit_.metrics, **stay.metrics, **cut_water, **wrap.metrics, **sites.metrics, **cost,
               **mechanics.metrics, **_run_extent(run)}
    series = {"time_s": run.t, "strain": mechanics.strain, "strain_clear": mechanics.strain_clear,
              "wrap": wrap.flags, "wrap_angle_deg": wrap.angle,
              "self_contacts": mechanics.self_contacts, "sites": sites.frames, "entry_time_s": stay.t_entry,
              "exit_time_s": exit_.t_exit, "parameters": _analysis_parameters(run, opt), "period_s": run.period}
    return metrics, series


def _analysis_options(options):
    """DEFAULTS updated with the options given (None: the default); MetricsError for an unknown one."""
    opt = dict(DEFAULTS)
    unknown = set(options) - set(DEFAULTS)
    if unknown:
        raise MetricsError("unknown option(s) %s (allowed: %s)" % (", ".join(sorted(unknown)), ", ".join(DEFAULTS)))
    opt.update({k: v for k, v in options.items() if v is not None})
    return opt


class _Trajectory:
    """A checked trajectory with what every metric group reads: the frames (t, x, edges,
    durations), the distances, the points' axial and radial coordinates in the lab frame and
    in the impeller's frame (xi), the distances to each wall region (near, capped: exact up to
    the contact, for cut_water the cut-water, distance) and who touches what."""

    def __init__(self, times, positions, grid_shape, geometry, threshold_m, opt):
        t = np.asarray(times, float)
        x = np.asarray(positions, float)
        if x.ndim != 3 or x.shape[2] != 3 or len(t) != len(x) or len(t) < 1:
            raise MetricsError("positions must be [n_frames, n_points, 3] with one time per frame (got %s and %d "
                               "times)" % (x.shape, len(t)))
        if np.any(np.diff(t) <= 0):
            raise MetricsError("the frames' times must increase")
        n_frames, n_points = x.shape[:2]
        if int(np.prod(grid_shape)) != n_points:
            raise MetricsError("grid_shape %s does not hold %d points" % (list(grid_shape), n_points))
        self.t, self.x, self.n_frames, self.n_points = t, x, n_frames, n_points
        self.d_c = float(threshold_m)
        self.contact = float(opt["contact_distance_m"] or 1.5 * self.d_c)
        self.cut_water_distance = float(opt["cut_water_distance_m"] or 2.0 * self.d_c)
        self.self_distance = float(opt["self_contact_distance_m"] or self.d_c)
        self.n_max = float(opt["n_max_revolutions"])
        self.wrap_angle = float(opt["wrap_angle_deg"])
        self.wrap_reach = float(opt["wrap_reach_m"])
        if not (0.0 < self.wrap_angle <= 720.0) or not self.wrap_reach > 0.0:
            raise MetricsError("wrap_angle_deg %g, wrap_reach_m %g: the angle is in (0, 720] deg and the reach "
                               "above 0 m" % (self.wrap_angle, self.wrap_reach))
        self.min_points = int(opt["site_min_points"])
        self.rate = geometry.rate
        self.period = 2 * math.pi / abs(self.rate) if self.rate else float("inf")
        self.edges = frame_edges(t)
        self.durations = np.diff(self.edges)
        self.flat = x.reshape(-1, 3)
        self.xi = geometry.to_impeller_frame(t, x).reshape(-1, 3)
        self.axial = geometry.axial(self.flat).reshape(n_frames, n_points)
        self.radius = geometry.radius(self.flat).reshape(n_frames, n_points)
        self.near = {}
        for (body, name), tset in geometry.sets.items():
            if name in OPENINGS:
                continue
            cap = max(self.contact, self.cut_water_distance) if name == "cut_water" else self.contact
            self.near[name] = tset.distance(self.xi if body == "impeller" else self.flat,
                                            cap=cap).reshape(n_frames, n_points)
        self.touching = {k: d <= self.contact for k, d in self.near.items()}
        self._none = np.zeros((n_frames, n_points), bool)

    def rev(self, s):
        """s seconds in revolutions (None without a time or a rotation)."""
        return None if s is None or not self.rate else s * abs(self.rate) / (2 * math.pi)

    def touch(self, name):
        """[F, N] points within the contact distance of region name (none when it is missing)."""
        return self.touching.get(name, self._none)


def _outcome_and_exit(run, geometry):
    """outcome (passed, passed_late, hung_up, running) and the exit: the first frame with every point
    in the discharge. The residence rule: a rag still in the pump n_max_revolutions after its
    release is held; passed_late when it left later in the run, hung_up when it was still in at
    the run's end."""
    exit_frame = _exit_frame(run, geometry)
    t_exit = float(run.t[exit_frame]) if exit_frame is not None else None
    t_end = float(run.t[-1])
    rate, rev = run.rate, run.rev
    if t_exit is not None and (not rate or rev(t_exit) <= run.n_max + 1e-9):
        outcome = "passed"
    elif t_exit is not None:
        outcome = "passed_late"
    elif rate and rev(t_end) >= run.n_max - 1e-9:
        outcome = "hung_up"
    else:
        outcome = "running"
    metrics = {
        "outcome": outcome,
        "exit_time_s": _opt(t_exit),
        "exit_revolution": rev(t_exit),
        "time_from_release_to_exit_s": _opt(t_exit),
    }
    return types.SimpleNamespace(metrics=metrics, t_exit=t_exit)


def _exit_frame(run, geometry):
    """The first frame beyond the volute radius whose points are all nearer to discharge_wall or
    outlet than to any other casing region (None: no such frame)."""
    candidates = np.nonzero(np.all(run.radius > geometry.volute_radius, axis=1))[0]
    discharge = [geometry.sets[("casing", k)] for k in ("discharge_wall", "outlet") if ("casing", k) in geometry.sets]
    others = [tset for (body, k), tset in geometry.sets.items()
              if body == "casing" and k not in ("discharge_wall", "outlet")]
    if not len(candidates):
        return None
    p = run.x[candidates].reshape(-1, 3)
    # Nearest casing region discharge_wall or outlet: its distance u first; the other regions
    # only where they come at least as near (capped at u).
    u = np.min([tset.distance(p) for tset in discharge], axis=0)
    d2 = np.min([tset.distance(p, cap=u) for tset in others], axis=0)
    inside = np.all((u < d2).reshape(len(candidates), run.n_points), axis=1)
    return int(candidates[np.argmax(inside)]) if np.any(inside) else None


def _residence(run, geometry, t_exit):
    """Residence: from the chamber entry (the first frame with a point above the entry) to the
    exit (or the end of the run); with each frame's duration inside it and inside the run."""
    entered = np.any(run.axial > geometry.entry_axial, axis=1)
    entry = int(np.argmax(entered)) if np.any(entered) else None
    t_entry = float(run.t[entry]) if entry is not None else None
    t_out = t_exit if t_exit is not None else float(run.t[-1])
    residence = (t_out - t_entry) if t_entry is not None else None
    in_residence = clipped_durations(run.edges, t_entry, t_out) if t_entry is not None else np.zeros(run.n_frames)
    in_run = clipped_durations(run.edges, 0.0, t_out)
    metrics = {
        "chamber_entry_time_s": _opt(t_entry),
        "chamber_entry_revolution": run.rev(t_entry),
        "residence_time_s": _opt(residence),
        "residence_time_revolutions": run.rev(residence),
        "residence_until": ("" if t_entry is None else "exit" if t_exit is not None else "end_of_run"),
    }
    return types.SimpleNamespace(metrics=metrics, t_entry=t_entry, t_out=t_out, residence=residence,
                                 in_residence=in_residence, in_run=in_run)


def _cut_water(run):
    """The first frame with a point within the cut-water distance of cut_water."""
    cw = np.any(run.near["cut_water"] <= run.cut_water_distance, axis=1)
    t_cut_water = float(run.t[np.argmax(cw)]) if np.any(cw) else None
    return {"time_to_cut_water_s": _opt(t_cut_water), "time_to_cut_water_revolutions": run.rev(t_cut_water)}


def _wrap(run, geometry, stay, grid_shape):
    """Wrap on the leading edge: the frames whose rag bends round blade_leading_edge by at least
    wrap_angle_deg (wrap_angles); their time in the residence and in the run, the episodes, the
    span."""
    le = run.touch("blade_leading_edge")
    angle = wrap_angles(run.xi.reshape(run.n_frames, run.n_points, 3), grid_shape, le,
                        geometry.leading_edge_axes, run.wrap_reach)
    wrap = angle >= run.wrap_angle
    wrap_in_residence = float(np.sum(stay.in_residence[wrap]))
    wrap_in_run = float(np.sum(stay.in_run[wrap]))
    episodes = runs_of(wrap)
    longest = max((run.edges[b + 1] - run.edges[a] for a, b in episodes), default=0.0)
    span = None
    if np.any(wrap) and geometry.le_hub_axial is not None and geometry.le_shroud_axial != geometry.le_hub_axial:
        weights = (le * run.durations[:, None])[wrap]
        if weights.sum() > 0:
            mean_axial = float(np.sum(weights * run.axial[wrap]) / np.sum(weights))
            span = (mean_axial - geometry.le_hub_axial) / (geometry.le_shroud_axial - geometry.le_hub_axial)
    residence, t_out = stay.residence, stay.t_out
    metrics = {
        "wrap_time_s": wrap_in_residence if residence else None,
        "wrap_fraction_of_residence": wrap_in_residence / residence if residence else None,
        "wrap_fraction_of_run": wrap_in_run / t_out if t_out > 0 else None,
        "longest_wrap_s": float(longest),
        "longest_wrap_revolutions": run.rev(float(longest)) if run.rate else None,
        "wrap_episodes": len(episodes),
        "max_wrap_angle_deg": float(np.max(angle)),
        "max_wrap_angle_time_s": float(run.t[int(np.argmax(angle))]) if np.max(angle) > 0 else None,
        "wrap_span_fraction": _opt(span),
    }
    return types.SimpleNamespace(metrics=metrics, flags=wrap, angle=angle)


def material_lines(grid_shape):
    """The rag's material lines as index arrays: the rows (i1 fixed) and the columns (i2 fixed)
    of the n1 x n2 grid (point index i1 n2 + i2)."""
    n1, n2 = int(grid_shape[0]), int(grid_shape[1]) if len(grid_shape) > 1 else 1
    index = np.arange(n1 * n2).reshape(n1, n2)
    lines = [index[i, :] for i in range(n1)] if n2 > 1 else []
    return lines + [index[:, j] for j in range(n2)] if n1 > 1 else lines


def _signed_angles(u, v, axis):
    """The angles (rad, in (-pi, pi]) from the vectors u to v [m, 3], about axis."""
    return np.arctan2(np.cross(u, v) @ axis, np.sum(u * v, axis=1))


def turning_angle_deg(points, axis):
    """|signed turning| (deg) of the polyline points [m, 3] seen along axis: the sum of the
    angles between consecutive segments projected on the plane normal to axis. Segments that
    nearly run along the axis (projected length under a fifth of theirs) are skipped. A straight
    line turns 0, a U 180, a loop 360."""
    d = np.diff(np.asarray(points, float), axis=0)
    projected = d - np.outer(d @ axis, axis)
    q = projected[np.linalg.norm(projected, axis=1) > 0.2 * np.linalg.norm(d, axis=1)]
    return abs(math.degrees(float(np.sum(_signed_angles(q[:-1], q[1:], axis))))) if len(q) >= 2 else 0.0


def winding_angle_deg(points, axis, centre):
    """|signed angle| (deg) the polyline points [m, 3] sweep round the line through centre
    along axis: the sum of the angles between consecutive points seen from it."""
    r = np.asarray(points, float) - centre
    r = r - np.outer(r @ axis, axis)
    return abs(math.degrees(float(np.sum(_signed_angles(r[:-1], r[1:], axis))))) if len(r) >= 2 else 0.0


def bend_round_edge_deg(points, axis, centre):
    """How far the polyline bends round the edge through centre along axis (deg): the smaller
    of its turning (a straight line passing the edge turns 0) and its winding round the edge
    (a fold beside the edge, not round it, winds little)."""
    return min(turning_angle_deg(points, axis), winding_angle_deg(points, axis, centre))


def wrap_angles(xi, grid_shape, touching, edge_axes, reach):
    """Per frame, the largest angle (deg) by which a material line of the rag bends round the
    leading edge: of each row and column of the grid, each stretch of consecutive points within
    reach of the edge that holds a point touching it (touching [F, N]); its bend round the edge
    (bend_round_edge_deg) seen along the edge's local direction at its touching point nearest
    the edge, round the edge's local centre there (EdgeAxes.local). xi [F, N, 3] in the
    impeller's frame."""
    n_frames, n_points = xi.shape[:2]
    near = edge_axes.distance(xi.reshape(-1, 3), reach).reshape(n_frames, n_points) <= reach
    lines = material_lines(grid_shape)
    angles = np.zeros(n_frames)
    for k in np.nonzero(np.any(touching, axis=1))[0]:
        for line in lines:
            if not np.any(touching[k, line]):
                continue
            for a, b in runs_of(near[k, line]):
                stretch = line[a:b + 1]
                hits = stretch[touching[k, stretch]]
                if len(stretch) < 3 or not len(hits):
                    continue
                anchor = xi[k, hits[np.argmin(edge_axes.distance(xi[k, hits], reach))]]
                axis, centre = edge_axes.local(anchor)
                angles[k] = max(angles[k], bend_round_edge_deg(xi[k, stretch], axis, centre))
    return angles


class EdgeAxes:
    """The leading edge's local direction and centre near a point, from the region's triangles
    within `window` of it. The direction is the one along which the surface does not turn: the
    eigenvector of the smallest eigenvalue of their area-weighted normals' scatter matrix (a
    rounded nose's normals turn round the edge, never along it); where the triangles are nearly
    flat (the two smaller eigenvalues both under a tenth of the largest), the principal
    direction of their centroids. The centre is their area-weighted centroid, inside a convex
    nose. Triangles in the impeller's frame."""

    def __init__(self, triangles, tset, window):
        tri = np.asarray(triangles, float).reshape(-1, 3, 3)
        n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        area = 0.5 * np.linalg.norm(n, axis=1)
        ok = area > 0
        self.normals = n[ok] / (2 * area[ok])[:, None]
        self.area = area[ok]
        self.centroids = tri[ok].mean(axis=1)
        # where a triangle is: its vertices, edge midpoints and centroid (long triangles are found
        # by the sample nearest the point)
        t = tri[ok]
        self.samples = np.concatenate([t, 0.5 * (t + np.roll(t, -1, axis=1)), t.mean(axis=1)[:, None]], axis=1)
        self.tset, self.window = tset, float(window)

    def distance(self, points, cap):
        return self.tset.distance(points, cap=cap)

    def local(self, point):
        """(unit direction, centre) of the edge near point."""
        near = np.min(np.linalg.norm(self.samples - point, axis=2), axis=1) <= self.window
        if not np.any(near):
            near = np.ones(len(self.area), bool)
        n, w = self.normals[near], self.area[near]
        centre = np.average(self.centroids[near], axis=0, weights=w)
        values, vectors = np.linalg.eigh((n * w[:, None]).T @ n)
        if values[1] >= 0.1 * values[2]:
            return vectors[:, 0], centre
        c = self.centroids[near] - centre
        _, vectors = np.linalg.eigh((c * w[:, None]).T @ c)
        return vectors[:, 2], centre


def _trap_sites(run, geometry):
    """Contact time per trap site (SITE_DEFINITIONS): the frames with at least site_min_points
    points touching the site."""
    touch = run.touch
    lo, hi = geometry.channel
    beyond_hub = run.axial > hi if geometry.hub_above else run.axial < lo
    beyond_shroud = run.axial < lo if geometry.hub_above else run.axial > hi
    outside_radius = run.radius > geometry.blade_outlet_radius
    in_eye = beyond_shroud & (run.radius <= geometry.eye_radius)
    outside_channel = outside_radius | beyond_hub | (beyond_shroud & ~in_eye)
    discs = touch("hub") | touch("shroud")
    site_points = {
        "eye_and_hub": touch("eye") | (touch("hub") & ~outside_channel) | (touch("shroud") & in_eye),
        "shroud": touch("shroud") & ~outside_channel & ~in_eye,
        "leading_edge": touch("blade_leading_edge"),
        "blade_sides": touch("blade_pressure_side") | touch("blade_suction_side") | touch("blade_trailing_edge"),
        "side_gap": discs & outside_channel,
        "cut_water": touch("cut_water"),
        "volute_wall": touch("volute_wall"),
        "discharge": touch("discharge_wall"),
        "suction": touch("suction_wall"),
    }
    frames = {k: np.count_nonzero(v, axis=1) >= run.min_points for k, v in site_points.items()}
    metrics = {"trap_contact_time_s." + site: float(np.sum(run.durations[frames[site]])) for site in SITES}
    return types.SimpleNamespace(metrics=metrics, frames=frames)


def _rag_mechanics(run, geometry, grid_shape):
    """The rag's largest strain (against frame 0's edge lengths), over all its edges and over
    the edges clear of any contact; its closest approach to a wall; its most self-contacts."""
    pairs = grid_edges(grid_shape)
    lengths = np.linalg.norm(run.x[:, pairs[:, 1]] - run.x[:, pairs[:, 0]], axis=2)
    rest = lengths[0]
    if np.any(rest <= 0):
        raise MetricsError("frame 0 has grid edges of zero length: no rest length")
    edge_strain = lengths / rest - 1.0
    strain = np.max(edge_strain, axis=1)
    k_strain = int(np.argmax(strain))
    contact = in_contact(run.x, grid_shape, run.contact)
    for touching in run.touching.values():
        contact |= touching
    clear = ~(contact[:, pairs[:, 0]] | contact[:, pairs[:, 1]])
    strain_clear = np.max(np.where(clear, edge_strain, -np.inf), axis=1)
    k_clear = int(np.argmax(strain_clear))
    flat_best, wall_min, region = _closest_wall(run, geometry)
    frame_min = flat_best // run.n_points
    selfc = self_contacts(run.x, grid_shape, run.self_distance)
    k_self = int(np.argmax(selfc))
    metrics = {
        "max_strain": float(strain[k_strain]),
        "max_strain_time_s": float(run.t[k_strain]),
        "strain_over_limit_fraction": float(np.mean(strain > PAPER["max_strain"])),
        "max_strain_clear": _opt(strain_clear[k_clear]),
        "max_strain_clear_time_s": float(run.t[k_clear]) if np.isfinite(strain_clear[k_clear]) else None,
        "strain_clear_over_limit_fraction": float(np.mean(strain_clear > PAPER["max_strain"])),
        "min_wall_distance_m": wall_min,
        "min_wall_distance_time_s": float(run.t[frame_min]),
        "min_wall_distance_region": str(region),
        "max_self_contacts": int(selfc[k_self]),
        "max_self_contacts_time_s": float(run.t[k_self]),
    }
    return types.SimpleNamespace(metrics=metrics, strain=strain, strain_clear=strain_clear, self_contacts=selfc)


def _closest_wall(run, geometry):
    """(flat index of the point, distance, region) of the closest approach to a wall: from the
    capped distances when a point came within the contact distance of a wall; else from every
    point's exact distance to the impeller and to the casing's walls."""
    wall_regions = [k for k in run.near]
    stacked = np.stack([run.near[k].ravel() for k in wall_regions])
    if np.min(stacked) <= run.contact:
        flat_best = int(np.argmin(np.min(stacked, axis=0)))
        wall_min = float(np.min(stacked[:, flat_best]))
        region = wall_regions[int(np.argmin(stacked[:, flat_best]))]
        return flat_best, wall_min, region
    di, ti = geometry.impeller_all.distance(run.xi, return_index=True)
    dc, tc = geometry.casing_walls.distance(run.flat, return_index=True)
    exact = np.minimum(di, dc)
    j = int(np.argmin(exact))
    region = geometry.impeller_all.labels[ti[j]] if di[j] <= dc[j] else geometry.casing_walls.labels[tc[j]]
    return j, float(exact[j]), region


def _run_extent(run):
    """How much trajectory there was."""
    t_end = float(run.t[-1])
    return {"n_frames": int(run.n_frames), "n_points": int(run.n_points), "end_time_s": t_end,
            "revolutions_run": run.rev(t_end)}


def _analysis_parameters(run, opt):
    """The distances and thresholds the metrics used (series["parameters"])."""
    return {
        "threshold_m": run.d_c, "contact_distance_m": run.contact, "cut_water_distance_m": run.cut_water_distance,
        "self_contact_distance_m": run.self_distance, "n_max_revolutions": run.n_max,
        "wrap_angle_deg": run.wrap_angle, "wrap_reach_m": run.wrap_reach, "site_min_points": run.min_points, "phase_bins": int(opt["phase_bins"]),
        "settle_revolutions": float(opt["settle_revolutions"] or 0.0),
    }


def compute_metrics(times, positions, grid_shape, geometry, threshold_m, loads=None, clean=None, **options):
    """The metrics dict of analyse() (see there)."""
    return analyse(times, positions, grid_shape, geometry, threshold_m, loads=loads, clean=clean, **options)[0]


COST_KEYS = ("torque_wrap_n_m", "torque_rest_n_m", "torque_clean_n_m", "torque_wrap_minus_rest_n_m",
             "torque_wrap_minus_clean_n_m", "torque_phase_averaged", "head_wrap_m", "head_rest_m", "head_clean_m",
             "head_wrap_minus_rest_m", "head_wrap_minus_clean_m", "head_phase_averaged")


def _cost(t, edges, wrap, loads, clean, rate, opt):
    """Mean shaft torque and head over the samples whose nearest frame wraps, against the other
    samples of the frames' time span after the settling revolutions, and against the clean pump."""
    out = {k: None for k in COST_KEYS}
    settle = float(opt["settle_revolutions"] or 0.0)
    t_settle = settle * 2 * math.pi / abs(rate) if rate else 0.0
    bins = int(opt["phase_bins"])
    for name, unit in (("torque", "n_m"), ("head", "m")):
        reference = (clean or {}).get(name)
        if reference is not None:
            out["%s_clean_%s" % (name, unit)] = float(reference)
        series = (loads or {}).get(name)
        if series is None:
            continue
        ts, ys = np.asarray(series[0], float), np.asarray(series[1], float)
        keep = (ts >= edges[0]) & (ts <= edges[-1]) & (ts >= t_settle) & np.isfinite(ys)
        ts, ys = ts[keep], ys[keep]
        frame = np.clip(np.searchsorted(edges, ts, side="right") - 1, 0, len(wrap) - 1)
        w = wrap[frame]
        mw, pw = phase_mean(ts[w], ys[w], rate, bins)
        mr, pr = phase_mean(ts[~w], ys[~w], rate, bins)
        out["%s_wrap_%s" % (name, unit)] = _opt(mw)
        out["%s_rest_%s" % (name, unit)] = _opt(mr)
        if mw is not None and mr is not None:
            out["%s_wrap_minus_rest_%s" % (name, unit)] = mw - mr
        if mw is not None and reference is not None:
            out["%s_wrap_minus_clean_%s" % (name, unit)] = mw - float(reference)
        flags = [p for p in (pw, pr) if p is not None]
        out["%s_phase_averaged" % name] = bool(all(flags)) if flags else None
    return out


# --------------------------------------------------------------------------------------------
# Reading a run and a case


def _yaml():
    import yaml
    return yaml


def read_structure(run_dir, structure=None):
    """(times [F], positions [F, N, 3], grid_shape, name, status, solver max stretch ratio or
    None, config yaml text or None) of RUN_DIR/structure.h5."""
    import h5py
    path = os.path.join(run_dir, "structure.h5")
    if not os.path.isfile(path):
        raise MetricsError("%s: no such file (the rag's positions; RUN_DIR must be the output folder of a run "
                           "with a structure)" % path)
    with h5py.File(path, "r") as f:
        if "time_s" not in f or "structures" not in f:
            raise MetricsError("%s: no /time_s or /structures (docs/results.md describes the layout)" % path)
        names = sorted(f["structures"].keys())
        if not names:
            raise MetricsError("%s: /structures is empty" % path)
        if structure is None:
            if len(names) > 1 and "rag" not in names:
                raise MetricsError("%s: several structures (%s); say which with --structure" % (path, ", ".join(names)))
            structure = names[0] if len(names) == 1 else "rag"
        if structure not in names:
            raise MetricsError("%s: no structure '%s' (allowed: %s)" % (path, structure, ", ".join(names)))
        g = f["structures"][structure]
        if "position_m" not in g:
            raise MetricsError("%s: /structures/%s/position_m missing" % (path, structure))
        rows = complete_rows(f)
        t = f["time_s"][:rows]
        x = g["position_m"][:rows]
        n = min(len(t), len(x))
        grid = [int(v) for v in g.attrs.get("grid_shape", [x.shape[1], 1])]
        stretch = g["max_stretch_ratio"][:n] if "max_stretch_ratio" in g else None
        status = f.attrs.get("status", "")
        config = f.attrs.get("config_yaml", None)
    decode = (lambda s: s.decode() if isinstance(s, bytes) else s)
    if n < 1:
        raise MetricsError("%s: no saved frame" % path)
    return (t[:n], x[:n], grid, structure, decode(status),
            float(np.max(stretch)) if stretch is not None and len(stretch) else None, decode(config))


def read_config(run_dir, case_dir, h5_config=None):
    """(config dict, where from): RUN_DIR/config.effective.yaml, else structure.h5's
    config_yaml, else CASE_DIR/case.yaml."""
    yaml = _yaml()
    path = os.path.join(run_dir, "config.effective.yaml")
    if os.path.isfile(path):
        with open(path) as f:
            return yaml.safe_load(f) or {}, path
    if h5_config:
        return yaml.safe_load(h5_config) or {}, os.path.join(run_dir, "structure.h5:config_yaml")
    path = os.path.join(case_dir, "case.yaml")
    if not os.path.isfile(path):
        raise MetricsError("%s: no such file (and no %s/config.effective.yaml)" % (path, run_dir))
    with open(path) as f:
        return yaml.safe_load(f) or {}, path


def load_geometry(case_dir, config, source="case.yaml", discharge_radius_m=None):
    """(PumpGeometry, threshold d_c, target d_t, notes) from the collision surfaces of the
    configuration: the impeller is the mesh surface with motion.rotation, the casing the other
    mesh surface (fluid_side inside), else CASE_DIR/geometry/casing.stl."""
    collisions = config.get("collisions") or {}
    surfaces = collisions.get("surfaces") or []
    impeller, static = None, []
    for s in surfaces:
        mesh = (s or {}).get("mesh")
        if not mesh:
            continue
        rot = ((s.get("motion") or {}).get("rotation"))
        if rot and impeller is None:
            impeller = (mesh, rot)
        elif not rot:
            static.append(mesh)
    inside = [m for m in static if m.get("fluid_side", "outside") == "inside"]
    casing = (inside or static or [None])[0]
    if impeller is None:
        found = "; ".join("%s%s" % (", ".join(k for k in (s or {}) if k != "motion"),
                                    " with motion %s" % ", ".join((s.get("motion") or {})) if (s or {}).get("motion") else "")
                          for s in surfaces) or "none"
        raise MetricsError("%s: collisions.surfaces has no mesh surface with motion.rotation (the impeller, an STL "
                           "with named regions; surfaces found: %s)" % (source, found))
    mesh, rot = impeller
    if "file" not in mesh:
        raise MetricsError("%s: the impeller's collisions.surfaces[].mesh has no 'file'" % source)

    def resolve(p):
        """Relative to the case folder. config.effective.yaml names the files as the run was given
        them (relative to where ./fsi ran: cases/rag-in-pump/geometry/casing.stl): the longest
        tail of the path that is a file in the case folder."""
        if os.path.isabs(p):
            return p
        parts = os.path.normpath(p).split(os.sep)
        for k in range(len(parts)):
            candidate = os.path.join(case_dir, *parts[k:])
            if os.path.isfile(candidate):
                return candidate
        return os.path.join(case_dir, p)

    impeller_file = resolve(mesh["file"])
    casing_file = resolve(casing["file"]) if casing and "file" in casing else os.path.join(case_dir, "geometry", "casing.stl")
    if not os.path.isfile(casing_file):
        raise MetricsError("%s: no such file (the casing with its regions: a collisions.surfaces[].mesh with "
                           "fluid_side: inside, or CASE_DIR/geometry/casing.stl)" % casing_file)
    if "rate_rad_per_s" not in rot:
        raise MetricsError("%s: the impeller's motion.rotation has no rate_rad_per_s" % source)
    geometry = PumpGeometry(read_stl_regions(impeller_file), read_stl_regions(casing_file),
                            rot.get("axis_point_m", [0, 0, 0]), rot.get("axis_direction", [0, 0, 1]),
                            float(rot["rate_rad_per_s"]), discharge_radius_m=discharge_radius_m,
                            impeller_file=impeller_file, casing_file=casing_file)
    notes = []
    gpath = os.path.join(os.path.dirname(impeller_file), "geometry.yaml")
    if os.path.isfile(gpath):
        with open(gpath) as f:
            gy = _yaml().safe_load(f) or {}
        rate = gy.get("rotation_rate_rad_per_s")
        if rate is not None and abs(float(rate) - geometry.rate) > 1e-6 * max(1.0, abs(geometry.rate)):
            notes.append("%s: rotation_rate_rad_per_s %s differs from the case's %s (the case's is used)"
                         % (gpath, rate, geometry.rate))
    threshold = float(collisions.get("threshold_m", 0.004))
    target = float(collisions.get("target_distance_m", 0.004))
    return geometry, threshold, target, notes, {"impeller": impeller_file, "casing": casing_file}


def read_loads(run_dir, geometry, config, impeller_index=None):
    """{"torque": (t, shaft torque), "head": (t, head)} with what the run left; missing parts
    are None. Torque: forces.csv (columns <body>.torque_{x,y,z}_n_m or body<k>.t{x,y,z}_n_m),
    else coupling.h5 /rigid_bodies/<body>/torque_n_m; shaft torque = -axis . torque.
    Head: (p_t,out - p_t,in) / (rho g) from openfoam/postProcessing (python/fsi/pump_point.py)."""
    loads, notes = {"torque": None, "head": None}, []
    torque = None
    path = os.path.join(run_dir, "forces.csv")
    if os.path.isfile(path):
        with open(path) as f:
            header = f.readline().strip().split(",")
        data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        bodies = {}
        for k, name in enumerate(header):
            for pattern in (".torque_%s_n_m", ".t%s_n_m"):
                for c in "xyz":
                    if name.endswith(pattern % c):
                        bodies.setdefault(name[:-len(pattern % c)], {})[c] = k
        bodies = {b: cols for b, cols in bodies.items() if len(cols) == 3}
        chosen = _choose_body(bodies, impeller_index)
        if chosen and len(data):
            torque = (data[:, 0], np.stack([data[:, bodies[chosen][c]] for c in "xyz"], axis=1))
            notes.append("torque: %s, body %s" % (path, chosen))
    if torque is None and os.path.isfile(os.path.join(run_dir, "coupling.h5")):
        import h5py
        with h5py.File(os.path.join(run_dir, "coupling.h5"), "r") as f:
            if "rigid_bodies" in f and "time_s" in f:
                bodies = {b: None for b in f["rigid_bodies"]}
                chosen = _choose_body(bodies, impeller_index)
                if chosen:
                    rows = complete_rows(f)
                    tq = f["rigid_bodies"][chosen]["torque_n_m"][:rows]
                    tt = f["time_s"][:rows]
                    n = min(len(tt), len(tq))
                    torque = (tt[:n], tq[:n])
                    notes.append("torque: coupling.h5, body %s" % chosen)
    if torque is not None:
        loads["torque"] = (torque[0], -(torque[1] @ geometry.axis))
    else:
        notes.append("no torque (no forces.csv or coupling.h5 with a rigid body)")
    try:
        from fsi import pump_point
        t_in, p_in = pump_point.read_dat(run_dir, "inletTotalPressure")
        t_out, p_out = pump_point.read_dat(run_dir, "outletTotalPressure")
        rho = float(((config.get("fluid") or {}).get("openfoam") or {}).get("density_kg_per_m3", 1000.0))
        loads["head"] = (t_out, (p_out[:, 0] - np.interp(t_out, t_in, p_in[:, 0])) / (rho * G))
        notes.append("head: openfoam/postProcessing total pressures, rho = %g kg/m^3" % rho)
    except (FileNotFoundError, ValueError, IndexError) as error:
        notes.append("no head (%s)" % error)
    return loads, notes


def _choose_body(bodies, impeller_index):
    if not bodies:
        return None
    if len(bodies) == 1:
        return next(iter(bodies))
    for name in ("surface%d" % (impeller_index or 0), "body0"):
        if name in bodies:
            return name
    return sorted(bodies)[0]


def read_clean(path):
    if not path:
        return None
    if not os.path.isfile(path):
        raise MetricsError("%s: no such file (--clean-operating-point: the clean pump's operating_point.yaml)" % path)
    with open(path) as f:
        point = _yaml().safe_load(f) or {}
    if "shaft_torque_n_m" not in point and "head_m" not in point:
        raise MetricsError("%s: neither shaft_torque_n_m nor head_m (an operating_point.yaml of "
                           "python/fsi/pump_point.py is expected)" % path)
    return {"torque": point.get("shaft_torque_n_m"), "head": point.get("head_m"),
            "flow_rate_m3_per_s": point.get("flow_rate_m3_per_s")}


PRECURSOR_SETTLED = 0.10  # the two halves of a settled precursor's window differ by at most 10 %


def clean_from_precursor(run_dir, geometry, config, impeller_index):
    """({"torque", "head", "flow_rate_m3_per_s": None, "source"} or None, notes): the clean pump
    at the run's operating point, the means over the second half of RUN_DIR/precursor (the flow
    alone that started the run), in whole revolutions (at least two): whole revolutions average
    every impeller angle, so the means are phase-averaged, and several of them the pump's slow
    swings (rag-in-pump's head swings by +/- 6 % over about six revolutions). A quantity whose
    window's two halves differ by more than PRECURSOR_SETTLED was still settling: it is left
    out, and the notes say so."""
    folder = os.path.join(run_dir, "precursor")
    if not os.path.isdir(folder) or not geometry.rate:
        return None, []
    loads, _ = read_loads(folder, geometry, config, impeller_index)
    period = 2 * math.pi / abs(geometry.rate)
    clean = {"torque": None, "head": None, "flow_rate_m3_per_s": None, "source": None}
    notes = []
    for name in ("torque", "head"):
        if loads[name] is None:
            continue
        t, y = loads[name]
        n = int(math.floor((t[-1] - t[0]) / period / 2 + 1e-9)) if len(t) else 0
        if n < 2:
            notes.append("clean %s: the precursor is shorter than four revolutions" % name)
            continue

        def mean(lo, hi):
            inside = (t >= lo - 1e-12) & (t <= hi + 1e-12)
            return float(np.trapz(y[inside], t[inside]) / (t[inside][-1] - t[inside][0]))
        start, middle = t[-1] - n * period, t[-1] - (n // 2) * period
        early, late = mean(start, middle), mean(middle, t[-1])
        if abs(late - early) > PRECURSOR_SETTLED * max(abs(late), abs(early)):
            notes.append("clean %s: not taken from the precursor, still settling (%.4g then %.4g over its last %d "
                         "revolutions; give --clean-operating-point or a longer fluid.openfoam.precursor_time_s)"
                         % (name, early, late, n))
            continue
        clean[name] = mean(start, t[-1])
        clean["source"] = "%s: the last %d revolutions" % (folder, n)
    if clean["torque"] is None and clean["head"] is None:
        return None, notes
    return clean, notes


# --------------------------------------------------------------------------------------------
# Outputs

DEFINITIONS = {
    "outcome": "passed: every point in the discharge (below) at a frame with t * rate / 2 pi <= n_max_revolutions "
               "(the residence rule); passed_late: out later in the run; hung_up: still in the pump at the end of a "
               "run that reached n_max_revolutions; running: the run ended before n_max_revolutions, the rag in. A point is in the discharge when its distance from the axis exceeds the "
               "volute's outer radius (the largest of volute_wall and cut_water vertices) and its nearest casing "
               "region is discharge_wall or outlet.",
    "exit_time_s": "time of the first frame with every point in the discharge (from the release at t = 0)",
    "exit_revolution": "exit_time_s * rate / 2 pi",
    "time_from_release_to_exit_s": "= exit_time_s (the rag is released at t = 0)",
    "chamber_entry_time_s": "first frame with a point above the top of suction_wall (axially, towards the impeller)",
    "chamber_entry_revolution": "chamber_entry_time_s * rate / 2 pi",
    "residence_time_s": "from chamber_entry_time_s to exit_time_s, or to the last frame when the rag has not left "
                        "(residence_until says which)",
    "residence_time_revolutions": "residence_time_s * rate / 2 pi",
    "residence_until": "exit, end_of_run (the run ended first: a lower bound), or empty (never entered)",
    "time_to_cut_water_s": "first frame with a point within cut_water_distance_m of cut_water",
    "time_to_cut_water_revolutions": "time_to_cut_water_s * rate / 2 pi",
    "wrap_time_s": "duration, within the residence, of the wrap frames: a material line of the rag (a row or a "
                   "column of its grid) bends round blade_leading_edge by at least wrap_angle_deg, its turning seen "
                   "along the edge over its points within wrap_reach_m of the edge, one of them within "
                   "contact_distance_m (in the impeller's frame)",
    "max_wrap_angle_deg": "the largest angle by which a material line bent round the leading edge in any frame",
    "max_wrap_angle_time_s": "the first frame with that angle (empty when the rag never bent round the edge)",
    "wrap_fraction_of_residence": "wrap_time_s / residence_time_s",
    "wrap_fraction_of_run": "wrap duration from t = 0 to the exit (or the end) over that time: the paper's measure",
    "longest_wrap_s": "longest run of consecutive wrap frames, e_{last+1} - e_first",
    "longest_wrap_revolutions": "longest_wrap_s * rate / 2 pi",
    "wrap_episodes": "number of runs of consecutive wrap frames",
    "wrap_span_fraction": "duration-weighted mean axial position of the points touching the leading edge in wrap "
                          "frames, 0 at the leading edge's hub end, 1 at its shroud end",
    "trap_contact_time_s.<site>": "sum of the durations of the frames with at least site_min_points points within "
                                  "contact_distance_m of the site (sites: see sites)",
    "torque_wrap_n_m": "mean shaft torque -axis . T over the force samples whose nearest frame wraps; phase-averaged "
                       "over phase_bins impeller-angle bins when every bin has samples (torque_phase_averaged)",
    "torque_rest_n_m": "the same over the other samples of the frames' time span after settle_revolutions",
    "torque_clean_n_m": "shaft_torque_n_m of --clean-operating-point; without it, the mean over the second half of "
                        "the run's precursor (the flow alone at the same operating point; whole revolutions), when it "
                        "had settled (the two halves of that window within 10 %)",
    "torque_wrap_minus_rest_n_m": "torque_wrap_n_m - torque_rest_n_m (and torque_wrap_minus_clean_n_m)",
    "torque_phase_averaged": "true when both the wrap and the rest means are phase-averaged, false when one is a plain "
                             "mean (a phase bin without samples), empty without torque data",
    "head_wrap_m": "as torque_wrap_n_m with the head (p_t,out - p_t,in) / (rho g) of openfoam/postProcessing (and "
                   "head_rest_m, head_clean_m, head_wrap_minus_rest_m, head_wrap_minus_clean_m, head_phase_averaged)",
    "max_strain": "largest |x_j - x_i| / L0_ij - 1 over the grid edges and frames, L0 the edge's length in frame 0 "
                  "(max_strain_time_s: its frame)",
    "strain_over_limit_fraction": "fraction of the frames whose largest edge strain is above the paper's 3 %: a peak "
                                  "in a few frames of contact (the rag draped over the rotating hub) against a rag "
                                  "stretched all along",
    "max_strain_clear": "max_strain over the edges clear of contact: neither end within contact_distance_m of a "
                        "wall region or of a point of the rag that is not its grid neighbour (max_strain_clear_time_s: "
                        "its frame; strain_clear_over_limit_fraction: the fraction of frames over 3 %). The "
                        "membrane's own stretching by the flow, without the collision corrections of Eq. 11, which "
                        "move a point by up to the target distance against its neighbours",
    "min_wall_distance_m": "smallest distance of a point to any wall region (impeller in its frame, casing; not "
                           "inlet or outlet) over the frames (min_wall_distance_time_s, min_wall_distance_region: "
                           "where)",
    "max_self_contacts": "largest number, over the frames, of point pairs closer than self_contact_distance_m that "
                         "are not grid neighbours (|di1| <= 1 and |di2| <= 1) (max_self_contacts_time_s: its frame)",
    "n_frames": "saved frames of structure.h5 (n_points: the rag's grid points)",
    "end_time_s": "time of the last frame (revolutions_run: * rate / 2 pi)",
    "solver_max_stretch_ratio": "the largest max_stretch_ratio the structure solver saved (length over its model's "
                                "rest length, 1 = unstretched); empty when structure.h5 has none",
}


def _plain(v):
    if isinstance(v, (np.floating, float)):
        return None if not math.isfinite(float(v)) else float(v)
    if isinstance(v, np.integer):
        return int(v)
    if isinstance(v, np.bool_):
        return bool(v)
    if isinstance(v, dict):
        return {k: _plain(w) for k, w in v.items()}
    if isinstance(v, (list, tuple)):
        return [_plain(w) for w in v]
    return v


def write_csv(path, metrics):
    def cell(v):
        v = _plain(v)
        if v is None or v == "":
            return ""
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, float):
            return "%.9g" % v
        return str(v)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(list(metrics))
        w.writerow([cell(v) for v in metrics.values()])


def write_yaml(path, metrics, parameters, extra):
    """The metrics at the top level (as in the CSV), then the parameters, the definitions and
    the paper's values (lists of text, which tools that flatten the numbers pass over), the
    sources and notes."""
    yaml = _yaml()
    doc = dict(_plain(metrics))
    doc["parameters"] = _plain(parameters)
    doc["definitions"] = ["%s: %s" % kv for kv in DEFINITIONS.items()] + [
        "site %s: %s" % kv for kv in SITE_DEFINITIONS.items()]
    doc["paper_section_4_2"] = [
        "%s: on the leading edge %.0f %% of the simulated time, %.1f revolutions; at the cut-water %.2f s after "
        "the release" % (q, 100 * v["wrap_fraction_of_run"], v["longest_wrap_revolutions"], v["time_to_cut_water_s"])
        for q, v in PAPER.items() if isinstance(v, dict)] + ["strain kept under %.0f %%" % (100 * PAPER["max_strain"])]
    doc.update(_plain(extra))
    with open(path, "w") as f:
        f.write("# The clogging metrics of the rag (python/fsi/rag_metrics.py; docs/rag-metrics.md), SI units;\n"
                "# null: undefined (never reached, no data).\n")
        yaml.safe_dump(doc, f, sort_keys=False, width=110)


TRAP_SITES_RED = ("eye_and_hub", "leading_edge", "cut_water")  # the paper's trap sites, red in the picture


def picture(path, metrics, series, title=""):
    """rag_summary.png: the outcome in big letters, the numbers a pump designer asks for, this
    run against the paper, the trap sites, strain and leading-edge contact over time."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    m = {k: _plain(v) for k, v in metrics.items()}
    fig = plt.figure(figsize=(11.7, 8.3))
    grid = fig.add_gridspec(4, 3, height_ratios=[1.0, 1.25, 0.85, 0.85], hspace=0.75, wspace=0.45,
                            left=0.1, right=0.93, top=0.97, bottom=0.07)
    colour = {"passed": "#1a7f37", "passed_late": "#b26a00", "hung_up": "#c62828", "running": "#b26a00"}[m["outcome"]]
    _picture_headline(fig.add_subplot(grid[0, :]), m, series, colour, title)
    _picture_trap_sites(fig.add_subplot(grid[1, 0]), m)
    _picture_against_paper(fig, grid[1, 1:], m, colour)
    ax = _picture_strain_and_wrap(fig.add_subplot(grid[2, :]), series)
    _picture_contacts(fig.add_subplot(grid[3, :], sharex=ax), series)
    fig.savefig(path, dpi=100)
    plt.close(fig)


def _fmt(v, spec, unit="", none="—"):
    return none if v is None or v == "" else (spec % v) + unit


def _pct(v):
    return None if v is None else 100.0 * v


def _picture_headline(text, m, series, colour, title):
    """The outcome in big letters and the numbers a pump designer asks for."""
    text.axis("off")
    head = {"passed": "PASSED at %s s (revolution %s)" % (_fmt(m["exit_time_s"], "%.3f"), _fmt(m["exit_revolution"], "%.1f")),
            "passed_late": "PASSED LATE at %s s (revolution %s; rule: out by %g)" % (
                _fmt(m["exit_time_s"], "%.3f"), _fmt(m["exit_revolution"], "%.1f"),
                series["parameters"]["n_max_revolutions"]),
            "hung_up": "HUNG UP: still in the pump at the end, %.1f rev (rule: out by %g)" % (
                m["revolutions_run"], series["parameters"]["n_max_revolutions"]),
            "running": "RUNNING: the run ended at %.3f s (%.1f rev) before an exit (rule: out by %g)" % (
                m["end_time_s"], m["revolutions_run"], series["parameters"]["n_max_revolutions"])}
    text.text(0.0, 1.0, head[m["outcome"]], fontsize=22, weight="bold", color=colour, va="top", transform=text.transAxes)
    left = [
        "residence in the pump: %s s = %s rev%s" % (
            _fmt(m["residence_time_s"], "%.3f"), _fmt(m["residence_time_revolutions"], "%.1f"),
            " (so far: the run ended first)" if m["residence_until"] == "end_of_run" else ""),
        "on the leading edge: %s of the residence, longest %s rev" % (
            _fmt(_pct(m["wrap_fraction_of_residence"]), "%.0f", " %"), _fmt(m["longest_wrap_revolutions"], "%.2f")),
        "    wrap at span %s (0 hub side, 1 shroud side)" % _fmt(m["wrap_span_fraction"], "%.2f", none="— (no wrap)"),
        "first at the cut-water: %s" % _fmt(m["time_to_cut_water_s"], "%.3f", " s", none="not reached"),
    ]
    right = [
        "shaft torque wrapped %s N m, rest %s, clean %s" % (
            _fmt(m["torque_wrap_n_m"], "%.2f"), _fmt(m["torque_rest_n_m"], "%.2f"), _fmt(m["torque_clean_n_m"], "%.2f")),
        "head wrapped %s m, rest %s, clean %s" % (
            _fmt(m["head_wrap_m"], "%.2f"), _fmt(m["head_rest_m"], "%.2f"), _fmt(m["head_clean_m"], "%.2f")),
        "rag: max strain %s (paper: under 3 %%; over it in %s of %d frames)" % (
            _fmt(_pct(m["max_strain"]), "%.1f", " %"), _fmt(_pct(m["strain_over_limit_fraction"]), "%.0f", " %"),
            m["n_frames"]),
        "    clear of contact: max %s, over 3 %% in %s of the frames" % (
            _fmt(_pct(m["max_strain_clear"]), "%.1f", " %"), _fmt(_pct(m["strain_clear_over_limit_fraction"]), "%.0f", " %")),
        "closest to a wall %s mm (%s), up to %d self-contacts" % (
            _fmt(1e3 * m["min_wall_distance_m"], "%.1f"), m["min_wall_distance_region"], m["max_self_contacts"]),
    ]
    for column, lines in ((0.0, left), (0.55, right)):
        for i, line in enumerate(lines):
            text.text(column, 0.58 - 0.15 * i, line, fontsize=10, va="top", transform=text.transAxes)
    if title:
        text.text(1.0, 1.0, title, fontsize=7, color="0.45", ha="right", va="bottom", transform=text.transAxes)


def _picture_trap_sites(ax, m):
    """Contact time per trap site (red: the paper's)."""
    times = [m["trap_contact_time_s." + s] for s in SITES]
    y = np.arange(len(SITES))[::-1]
    ax.barh(y, times, color=["C3" if s in TRAP_SITES_RED else "C0" for s in SITES])
    ax.set_yticks(y)
    ax.set_yticklabels([s.replace("_", " ") for s in SITES], fontsize=8)
    ax.set_xlabel("contact time (s)", fontsize=8)
    ax.tick_params(axis="x", labelsize=7)
    ax.set_title("where the rag touched\n(red: the paper's trap sites)", fontsize=9)


def _picture_against_paper(fig, cell, m, colour):
    """This run against the paper (section 4.2, the 15 cm x 5 cm rag)."""
    cmp_grid = cell.subgridspec(1, 3, wspace=0.5)
    for j, (key, label, scale, unit) in enumerate((("wrap_fraction_of_run", "on the leading edge\n(% of the run)", 100, "%.0f"),
                                                   ("longest_wrap_revolutions", "longest wrap\n(revolutions)", 1, "%.2f"),
                                                   ("time_to_cut_water_s", "release to cut-water\n(s)", 1, "%.3f"))):
        ax = fig.add_subplot(cmp_grid[0, j])
        values = [m[key], PAPER["Q_BEP"][key], PAPER["0.36 Q_BEP"][key]]
        heights = [0 if v is None else scale * v for v in values]
        bars = ax.bar(range(3), heights, color=[colour, "0.55", "0.8"])
        for b, v in zip(bars, values):
            ax.text(b.get_x() + b.get_width() / 2, b.get_height(), "n/a" if v is None else unit % (scale * v),
                    ha="center", va="bottom", fontsize=7)
        ax.set_xticks(range(3))
        ax.set_xticklabels(["this\nrun", "paper\nQ_BEP", "paper\n0.36 Q"], fontsize=7)
        ax.set_title(label, fontsize=8)
        ax.tick_params(axis="y", labelsize=7)
        ax.set_ylim(0, 1.2 * max(heights + [1e-9]))


def _picture_revolutions(series):
    """(the frames' times in revolutions (in s without a rotation), the period or 1)."""
    per = series["period_s"] if math.isfinite(series["period_s"]) else 1.0
    return series["time_s"] / per, per


def _picture_strain_and_wrap(ax, series):
    """Over time: strain and leading-edge contact, the wraps shaded, the chamber entry and the exit.
    Returns ax (the contacts share its time axis)."""
    rev, per = _picture_revolutions(series)
    for a, b in runs_of(series["wrap"]):
        ax.axvspan(rev[a], rev[min(b + 1, len(rev) - 1)], color="C3", alpha=0.12, lw=0)
    ax.plot(rev, 100 * series["strain"], color="C2", lw=1.2, zorder=3)
    if "strain_clear" in series:
        clear = np.where(np.isfinite(series["strain_clear"]), series["strain_clear"], np.nan)
        ax.plot(rev, 100 * clear, color="C2", lw=0.8, ls=":", zorder=3)
    ax.axhline(100 * PAPER["max_strain"], color="C2", ls="--", lw=0.7)
    ax.set_ylabel("max strain (%)", color="C2", fontsize=8)
    ax.tick_params(labelsize=7)
    ax2 = ax.twinx()
    ax2.plot(rev, series["wrap_angle_deg"], color="C3", lw=0.8, alpha=0.8)
    ax2.axhline(series["parameters"]["wrap_angle_deg"], color="C3", ls="--", lw=0.6)
    ax2.set_ylabel("bent round the\nleading edge (deg)", color="C3", fontsize=8)
    ax2.set_ylim(0, max(200.0, 1.05 * float(np.max(series["wrap_angle_deg"]))))
    ax2.tick_params(labelsize=7)
    for key, style in (("entry_time_s", ":"), ("exit_time_s", "-")):
        if series[key] is not None:
            ax.axvline(series[key] / per, color="k", ls=style, lw=0.8)
    ax.set_title("strain (green; dotted: clear of contact; dashed: the paper's 3 %), the rag's bend round the leading edge (red; shaded: wrapped, over the dashed angle), "
                 "chamber entry (dotted), exit (solid)", fontsize=8)
    return ax


def _picture_contacts(ax3, series):
    """Over time: the contacts per trap site."""
    rev, _ = _picture_revolutions(series)
    for i, s in enumerate(SITES):
        for a, b in runs_of(series["sites"][s]):
            ax3.plot([rev[a], rev[min(b + 1, len(rev) - 1)]], [len(SITES) - 1 - i] * 2, lw=4,
                     color="C3" if s in TRAP_SITES_RED else "C0", solid_capstyle="butt")
    ax3.set_yticks(range(len(SITES)))
    ax3.set_yticklabels([s.replace("_", " ") for s in SITES][::-1], fontsize=6)
    ax3.set_ylim(-0.7, len(SITES) - 0.3)
    ax3.tick_params(axis="x", labelsize=7)
    ax3.set_xlabel("revolutions since the release" if math.isfinite(series["period_s"]) else "time (s)", fontsize=8)
    ax3.set_title("contacts over time", fontsize=8)


def write_metrics(run_dir, case_dir, **options):
    """Reads RUN_DIR (structure.h5, forces.csv / coupling.h5, openfoam/postProcessing) and
    CASE_DIR (case.yaml, the collision STL files), writes rag_metrics.csv, rag_metrics.yaml and
    rag_summary.png into RUN_DIR, returns the metrics dict. Options: see DEFAULTS."""
    unknown = set(options) - set(DEFAULTS)
    if unknown:
        raise MetricsError("unknown option(s) %s (allowed: %s)" % (", ".join(sorted(unknown)), ", ".join(DEFAULTS)))
    opt = dict(DEFAULTS)
    opt.update({k: v for k, v in options.items() if v is not None})
    if not os.path.isdir(run_dir):
        raise MetricsError("%s: not a folder (RUN_DIR: the run's output folder)" % run_dir)
    if not os.path.isdir(case_dir):
        raise MetricsError("%s: not a folder (CASE_DIR: the case folder with case.yaml)" % case_dir)
    t, x, grid, name, status, solver_stretch, h5_config = read_structure(run_dir, opt["structure"])
    config, source = read_config(run_dir, case_dir, h5_config)
    geometry, d_c, d_t, notes, files = load_geometry(case_dir, config, source, opt["discharge_radius_m"])
    surfaces = (config.get("collisions") or {}).get("surfaces") or []
    index = next((k for k, s in enumerate(surfaces) if ((s or {}).get("motion") or {}).get("rotation")), 0)
    loads, load_notes = read_loads(run_dir, geometry, config, index)
    clean, clean_notes = read_clean(opt["clean_operating_point"]), []
    if clean is None:
        clean, clean_notes = clean_from_precursor(run_dir, geometry, config, index)
    if opt["settle_revolutions"] is None:
        opt["settle_revolutions"] = 0.0 if os.path.isdir(os.path.join(run_dir, "precursor")) else 1.0
    analysis = {k: opt[k] for k in DEFAULTS if k not in ("clean_operating_point", "structure", "discharge_radius_m",
                                                          "picture")}
    metrics, series = analyse(t, x, grid, geometry, d_c, loads=loads, clean=clean, **analysis)
    metrics["solver_max_stretch_ratio"] = _opt(solver_stretch)
    parameters = dict(series["parameters"], target_distance_m=d_t, structure=name,
                      clean_operating_point=opt["clean_operating_point"], geometry=geometry.describe())
    extra = {"sources": {"run_dir": os.path.abspath(run_dir), "case_dir": os.path.abspath(case_dir),
                         "configuration": source, "structure_status": status, **files},
             "notes": notes + load_notes + clean_notes}
    if clean and clean.get("flow_rate_m3_per_s") is not None:
        extra["sources"]["clean_flow_rate_m3_per_s"] = clean["flow_rate_m3_per_s"]
    if clean and clean.get("source"):
        extra["sources"]["clean_pump"] = clean["source"]
    write_csv(os.path.join(run_dir, "rag_metrics.csv"), metrics)
    write_yaml(os.path.join(run_dir, "rag_metrics.yaml"), metrics, parameters, extra)
    if opt["picture"]:
        picture(os.path.join(run_dir, "rag_summary.png"), metrics, series,
                title="%s  (%s, structure '%s')" % (os.path.abspath(run_dir), status, name))
    return metrics


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run_dir", help="the run's output folder (structure.h5, forces.csv, openfoam/)")
    p.add_argument("case_dir", help="the case folder (case.yaml, geometry/)")
    p.add_argument("--n-max-revolutions", type=float, help="hung up when still in after this many (default 10)")
    p.add_argument("--wrap-angle-deg", type=float,
                   help="a material line bent round the leading edge by this much is a wrap (default 90)")
    p.add_argument("--wrap-reach-m", type=float,
                   help="the points of a line within this distance of the leading edge count in its bend (default 0.02)")
    p.add_argument("--contact-distance-m", type=float, help="contact distance (default 1.5 d_c)")
    p.add_argument("--cut-water-distance-m", type=float, help="distance that reaches the cut-water (default 2 d_c)")
    p.add_argument("--clean-operating-point", help="operating_point.yaml of the clean pump at the same flow rate")
    p.add_argument("--settle-revolutions", type=float,
                   help="force samples before this many revolutions are left out of the cost (default: 0 after "
                        "a precursor, else 1)")
    p.add_argument("--structure", help="the structure's name in structure.h5 (default: the only one, or 'rag')")
    p.add_argument("--no-picture", action="store_true", help="skip rag_summary.png")
    a = p.parse_args(argv)
    try:
        metrics = write_metrics(a.run_dir, a.case_dir, n_max_revolutions=a.n_max_revolutions,
                                wrap_angle_deg=a.wrap_angle_deg, wrap_reach_m=a.wrap_reach_m, contact_distance_m=a.contact_distance_m,
                                cut_water_distance_m=a.cut_water_distance_m,
                                clean_operating_point=a.clean_operating_point, structure=a.structure,
                                settle_revolutions=a.settle_revolutions,
                                picture=not a.no_picture)
    except MetricsError as error:
        sys.stderr.write("rag_metrics.py: %s\n" % error)
        return 2
    m = {k: _plain(v) for k, v in metrics.items()}

    def say(v, spec, none):
        return none if v is None else spec % v
    print("%s; residence %s; wrap %s of the residence (longest %s); cut-water %s; max strain %.2f %%"
          % (m["outcome"] + say(m["exit_time_s"], " at %.3f s", ""), say(m["residence_time_s"], "%.3f s", "-"),
             say(None if m["wrap_fraction_of_residence"] is None else 100 * m["wrap_fraction_of_residence"], "%.0f %%", "-"),
             say(m["longest_wrap_revolutions"], "%.2f rev", "-"), say(m["time_to_cut_water_s"], "at %.3f s", "not reached"),
             100 * m["max_strain"]))
    print("wrote %s/rag_metrics.csv, rag_metrics.yaml%s" % (a.run_dir, "" if a.no_picture else ", rag_summary.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
