#!/usr/bin/python3
"""python/fsi/rag_metrics.py (the clogging metrics of a rag in a pump, docs/rag-metrics.md) on
synthetic pumps and trajectories with known answers. No built binaries, no run: a few seconds.

    /usr/bin/python3 tests/cases/test_rag_metrics.py -v [Class]

The synthetic pump (written as ASCII STL files with named solids, one box or several per
region): axis -z through the origin, 10 revolutions per second (T = 0.1 s); the impeller has a
thin leading edge 20-22 mm from the axis, blade sides, a hub above and a shroud below the
channel 0 < z < 0.05 m; the casing a suction pipe up to z = -0.013 m (the chamber's entry), a
box volute |x|, |y| <= 0.12 m (outer radius 0.12 sqrt 2), a thin cut-water, a discharge box
along +x from x = 0.125 m and the outlet at x = 0.5 m. The rags are 5 x 4 grids, 4 mm apart.
Distances and times are checked against values derived here independently of the module
(box distances, rotations written out, the exit radius), with the tolerances stated at each
assertion (mostly one frame: frames are 2.5 ms apart).
"""

import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from unittest import mock

try:
    import h5py
    import numpy as np
    import yaml
except ImportError as error:  # ctest reports exit code 77 as "skipped", with this line
    print("skipped: a Debian python3 package is missing (%s)" % error)
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
from fsi import impeller_xdmf  # noqa: E402  (python/fsi/impeller_xdmf.py)
from fsi import rag_metrics  # noqa: E402  (python/fsi/rag_metrics.py)
from fsi import surface_engine  # noqa: E402  (python/fsi/surface_engine.py)

RATE = 2 * math.pi * 10.0          # rad/s: T = 0.1 s
PERIOD = 2 * math.pi / RATE
AXIS = [0.0, 0.0, -1.0]
D_C = 0.004
DT = 0.0025                        # s between frames
SQUARE = 0.12 * math.sqrt(2.0)     # the volute's outer radius: the box's corner

# name -> list of boxes (lo, hi)
IMPELLER = {
    "blade_leading_edge": [((0.020, -0.001, 0.002), (0.022, 0.001, 0.048))],
    "blade_pressure_side": [((0.022, 0.001, 0.0), (0.1, 0.002, 0.05))],
    "blade_suction_side": [((0.022, -0.002, 0.0), (0.1, -0.001, 0.05))],
    "blade_trailing_edge": [((0.099, -0.001, 0.0), (0.1, 0.001, 0.05))],
    "hub": [((-0.1, -0.1, 0.05), (0.1, 0.1, 0.058))],
    "shroud": [((0.05, -0.1, -0.008), (0.1, 0.1, 0.0)), ((-0.1, -0.1, -0.008), (-0.05, 0.1, 0.0)),
               ((-0.05, 0.05, -0.008), (0.05, 0.1, 0.0)), ((-0.05, -0.1, -0.008), (0.05, -0.05, 0.0))],
}
CASING = {
    "inlet": [((-0.05, -0.05, -0.302), (0.05, 0.05, -0.3))],
    "suction_wall": [((0.05, -0.052, -0.3), (0.052, 0.052, -0.013)), ((-0.052, -0.052, -0.3), (-0.05, 0.052, -0.013)),
                     ((-0.05, 0.05, -0.3), (0.05, 0.052, -0.013)), ((-0.05, -0.052, -0.3), (0.05, -0.05, -0.013))],
    "volute_wall": [((-0.12, -0.12, -0.013), (0.12, 0.12, 0.063))],
    "cut_water": [((0.115, 0.04, -0.013), (0.12, 0.045, 0.063))],
    "discharge_wall": [((0.125, -0.04, -0.005), (0.5, 0.04, 0.055))],
    "outlet": [((0.5, -0.04, -0.005), (0.502, 0.04, 0.055))],
}


def box_triangles(lo, hi):
    """The 12 triangles of an axis-aligned box, outward."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                  [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]])
    faces = [(0, 3, 2), (0, 2, 1), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
             (2, 3, 7), (2, 7, 6), (1, 2, 6), (1, 6, 5), (0, 4, 7), (0, 7, 3)]
    return v[np.array(faces)]


def write_stl(path, regions):
    """regions: {name: list of boxes (lo, hi)} as an ASCII STL with named solids."""
    write_stl_triangles(path, {name: box_regions_triangles(boxes) for name, boxes in regions.items()})


def box_regions_triangles(boxes):
    return np.concatenate([box_triangles(lo, hi) for lo, hi in boxes])


def write_stl_triangles(path, regions):
    """regions: {name: triangles [n, 3, 3]} as an ASCII STL with named solids."""
    with open(path, "w") as f:
        for name, tris in regions.items():
            f.write("solid %s\n" % name)
            for tri in tris:
                n = np.cross(tri[1] - tri[0], tri[2] - tri[0])
                f.write("facet normal %g %g %g\nouter loop\n" % tuple(n / np.linalg.norm(n)))
                for q in tri:
                    f.write("vertex %.9g %.9g %.9g\n" % tuple(q))
                f.write("endloop\nendfacet\n")
            f.write("endsolid %s\n" % name)


def box_distance(p, boxes):
    """Distance of points [m, 3] to the surfaces of boxes (the STL of a region is the surfaces
    of its boxes): from outside the norm of the gap, from inside the nearest face."""
    d = np.full(len(p), np.inf)
    for lo, hi in boxes:
        lo, hi = np.asarray(lo), np.asarray(hi)
        gap = np.maximum(np.maximum(lo - p, p - hi), 0.0)
        outside = np.linalg.norm(gap, axis=1)
        inside = np.min(np.minimum(p - lo, hi - p), axis=1)
        d = np.minimum(d, np.where(np.any(gap > 0, axis=1), outside, inside))
    return d


def to_lab(points_impeller, t):
    """Impeller-frame points into the lab frame at time t: rotation by RATE t about -z, i.e. by
    -RATE t about +z (right-hand rule), written out."""
    a = -RATE * t
    c, s = math.cos(a), math.sin(a)
    x, y, z = points_impeller[:, 0], points_impeller[:, 1], points_impeller[:, 2]
    return np.stack([c * x - s * y, s * x + c * y, z], axis=1)


def grid(n1=5, n2=4, spacing=0.004):
    """(local offsets [n1 n2, 3] of a flat grid along s1 = x, s2 = y, centred; grid shape)."""
    i1, i2 = np.meshgrid(np.arange(n1), np.arange(n2), indexing="ij")
    local = np.stack([(i1.ravel() - (n1 - 1) / 2) * spacing, (i2.ravel() - (n2 - 1) / 2) * spacing,
                      np.zeros(n1 * n2)], axis=1)
    return local, (n1, n2)


_GEOMETRY = {}


def geometry(impeller=None, key=(), **kwargs):
    """The synthetic pump as a PumpGeometry (cached): IMPELLER's boxes, or the impeller's
    triangles by region given as `impeller` (then `key` names it), and CASING."""
    key = (key, tuple(sorted(kwargs.items())))
    if key not in _GEOMETRY:
        tmp = tempfile.mkdtemp(prefix="rag-metrics-geometry-")
        try:
            write_stl_triangles(os.path.join(tmp, "impeller.stl"), impeller or {
                name: box_regions_triangles(boxes) for name, boxes in IMPELLER.items()})
            write_stl(os.path.join(tmp, "casing.stl"), CASING)
            _GEOMETRY[key] = rag_metrics.PumpGeometry(
                rag_metrics.read_stl_regions(os.path.join(tmp, "impeller.stl")),
                rag_metrics.read_stl_regions(os.path.join(tmp, "casing.stl")), [0, 0, 0], AXIS, RATE, **kwargs)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    return _GEOMETRY[key]


# Places a rag can sit without touching anything (lab frame): the suction pipe's centre, and
# the chamber at radius 0.07 m mid-channel (the blade sides sweep past it: irrelevant here).
IN_SUCTION = np.array([0.0, 0.0, -0.15])
def folded_grid():
    """grid() flat (local) and folded: rows 0-2 flat, rows 3-4 folded back 2 mm above, row 3 over
    row 1 and row 4 over row 0. Returns (local, grid shape, row index per point, folded)."""
    local, shape = grid()
    rows = np.arange(len(local)) // shape[1]
    folded = local.copy()
    folded[:, 0] = 0.004 * np.where(rows <= 2, rows, 4 - rows)
    folded[:, 2] = np.where(rows <= 2, 0.0, 0.002)
    return local, shape, rows, folded


IN_CHAMBER = np.array([0.07, 0.0, 0.025])


def bent_line(centre, rho, theta_deg, spacing, n, grow=0.0):
    """n points [n, 2], spacing apart along a path that comes in along -x at y = centre_y + rho,
    bends theta_deg counterclockwise round centre (its radius growing from rho by grow over the
    bend: a spiral, so that a 360 deg loop does not cross itself) and leaves straight along its
    tangent; sampled by arc length, centred on the bend's middle. The path's tangent turns by
    exactly theta_deg; so does the polyline when its first and last segments lie on the straight
    arms."""
    th = math.radians(theta_deg)
    u = np.linspace(0.0, th, 2001)
    rho_u = rho + grow * u / th if th > 0 else np.full_like(u, rho)
    arc = np.stack([centre[0] + rho_u * np.cos(math.pi / 2 + u), centre[1] + rho_u * np.sin(math.pi / 2 + u)], axis=1)
    arm = n * spacing
    tangent_out = np.array([-math.sin(math.pi / 2 + th), math.cos(math.pi / 2 + th)])
    arm_in = arc[0] + np.outer(np.linspace(arm, 0.0, 2001)[:-1], [1.0, 0.0])
    arm_out = arc[-1] + np.outer(np.linspace(0.0, arm, 2001)[1:], tangent_out)
    path = np.concatenate([arm_in, arc, arm_out])
    length = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(path, axis=0), axis=1))])
    middle = length[len(arm_in) + len(arc) // 2]
    s = middle + spacing * (np.arange(n) - (n - 1) / 2.0)
    return np.stack([np.interp(s, length, path[:, 0]), np.interp(s, length, path[:, 1])], axis=1)


def wrap_trajectory():
    """Suction pipe until 0.05 s, then held draped over the leading edge (turning with the
    impeller) for exactly 1.5 revolutions (0.05 <= t < 0.2 s), then in the chamber until 0.3 s.
    Draped: each row of the grid (s1, 5 points 4 mm apart) bends 180 deg round the edge's centre
    line (x, y) = (0.021, 0) at 3 mm from it, opening towards +x (the blade); the columns (s2)
    run along the edge at z = 0.032 .. 0.044 m."""
    local, shape = grid()
    row = bent_line((0.021, 0.0), 0.003, 180.0, 0.004, shape[0])
    i1, i2 = np.arange(len(local)) // shape[1], np.arange(len(local)) % shape[1]
    on_edge = np.stack([row[i1, 0], row[i1, 1], 0.032 + 0.004 * i2], axis=1)
    t = np.arange(0, 121) * DT
    x = []
    for tk in t:
        if tk < 0.05 - 1e-12:
            x.append(IN_SUCTION + local)
        elif tk < 0.05 + 1.5 * PERIOD - 1e-12:
            x.append(to_lab(on_edge, tk))
        else:
            x.append(IN_CHAMBER + local)
    return t, np.array(x), shape, on_edge


def discharge_trajectory(y_offset=0.0):
    """Suction pipe until 0.05 s, the chamber at (0.05, y_offset, 0.025) until 0.1 s, then along
    +x at 1 m/s into the discharge box, to 0.4 s."""
    local, shape = grid()
    t = np.arange(0, 161) * DT
    x = []
    for tk in t:
        if tk < 0.05 - 1e-12:
            x.append(IN_SUCTION + local)
        else:
            xc = 0.05 + max(0.0, tk - 0.1) * 1.0
            x.append(np.array([xc, y_offset, 0.025]) + local)
    return t, np.array(x), shape


class Distance(unittest.TestCase):
    """(6) TriangleSet.distance against brute force: every triangle, by an independent method
    (projection onto the plane with barycentric inside test, else the nearest of the three
    edges)."""

    @staticmethod
    def brute(p, tris):
        a, b, c = tris[:, 0], tris[:, 1], tris[:, 2]
        n = np.cross(b - a, c - a)
        n = n / np.linalg.norm(n, axis=1)[:, None]
        out = np.empty(len(p))
        for i, q in enumerate(p):
            h = np.einsum("ij,ij->i", q - a, n)
            proj = q - h[:, None] * n
            # barycentric coordinates of the projection
            v0, v1, v2 = b - a, c - a, proj - a
            d00, d01, d11 = (v0 * v0).sum(1), (v0 * v1).sum(1), (v1 * v1).sum(1)
            d20, d21 = (v2 * v0).sum(1), (v2 * v1).sum(1)
            den = d00 * d11 - d01 * d01
            v = (d11 * d20 - d01 * d21) / den
            w = (d00 * d21 - d01 * d20) / den
            inside = (v >= 0) & (w >= 0) & (v + w <= 1)
            best = np.where(inside, np.abs(h), np.inf)
            for s, e in ((a, b), (b, c), (c, a)):
                seg = e - s
                u = np.clip(np.einsum("ij,ij->i", q - s, seg) / (seg * seg).sum(1), 0, 1)
                best = np.minimum(best, np.linalg.norm(q - (s + u[:, None] * seg), axis=1))
            out[i] = best.min()
        return out

    def test_random_soup_against_brute_force(self):
        rng = np.random.default_rng(7)
        centres = rng.uniform(0, 0.1, (300, 1, 3))
        tris = centres + rng.normal(0, 0.006, (300, 3, 3))
        tris[:20, 2] = tris[:20, 0] + 1e-3 * (tris[:20, 1] - tris[:20, 0]) + 1e-5  # slivers
        tris[20:23] *= [1, 1, 1]
        tris[20] = [[0, 0, 0.05], [0.1, 0, 0.05], [0, 0.1, 0.05]]  # one large triangle: R large
        points = rng.uniform(-0.03, 0.13, (400, 3))
        tset = rag_metrics.TriangleSet(tris)
        exact = self.brute(points, tris)
        fast = tset.distance(points)
        # exact arithmetic, different formulas: 1e-12 m
        self.assertLess(np.max(np.abs(fast - exact)), 1e-12)
        for cap in (0.002, 0.01):
            capped = tset.distance(points, cap=cap)
            near = exact <= cap
            self.assertTrue(np.any(near) and np.any(~near))
            self.assertLess(np.max(np.abs(capped[near] - exact[near])), 1e-12)  # exact within the cap
            self.assertTrue(np.all(capped[~near] > cap))                        # beyond it: reported beyond

    def test_engine_refusals_are_said(self):
        # The geometry engine (fsi-surface-query): its refusals become the metrics' errors.
        with self.assertRaisesRegex(rag_metrics.MetricsError, "no triangle of non-zero area"):
            rag_metrics.TriangleSet(np.zeros((2, 3, 3)))
        with mock.patch.dict(os.environ, {"FSI_BIN_DIR": "/nonexistent"}):
            with self.assertRaisesRegex(surface_engine.EngineError,
                                        "fsi-surface-query not found in /nonexistent .*\\./fsi build"):
                surface_engine.SurfaceEngine()

    def test_boxes_from_stl_against_box_distance(self):
        g = geometry()
        rng = np.random.default_rng(3)
        points = rng.uniform([0.0, -0.03, 0.0], [0.05, 0.03, 0.05], (500, 3))
        le = IMPELLER["blade_leading_edge"][0]
        outside = np.any((points < le[0]) | (points > le[1]), axis=1)
        points = points[outside]
        d = g.sets[("impeller", "blade_leading_edge")].distance(points)
        # the STL round trip writes 9 digits: 1e-9 m
        self.assertLess(np.max(np.abs(d - box_distance(points, IMPELLER["blade_leading_edge"]))), 1e-9)

    def test_stl_regions_and_derived_geometry(self):
        g = geometry()
        self.assertEqual(sorted(g.impeller), sorted(IMPELLER))
        self.assertEqual(len(g.impeller["shroud"]), 4 * 12)
        self.assertAlmostEqual(g.entry_axial, -0.013, delta=1e-9)   # top of suction_wall
        self.assertAlmostEqual(g.volute_radius, SQUARE, delta=1e-9)
        self.assertAlmostEqual(g.blade_outlet_radius, math.hypot(0.1, 0.002), delta=1e-9)
        self.assertEqual(g.channel, (0.0, 0.05))
        self.assertEqual((g.le_hub_axial, g.le_shroud_axial), (0.048, 0.002))  # hub above the channel
        self.assertEqual(list(g.up), [0.0, 0.0, 1.0])  # from the suction towards the impeller, against the axis


class Wrap(unittest.TestCase):
    """(1) A rag held draped over the leading edge, turning with the impeller, for exactly 1.5
    revolutions."""

    def test_longest_wrap_and_fraction(self):
        t, x, shape, on_edge = wrap_trajectory()
        g = geometry()
        # every point of the held rag is within 1.5 d_c of the edge (at most 3.1 mm) by construction
        self.assertLess(np.max(box_distance(on_edge, IMPELLER["blade_leading_edge"])), 1.5 * D_C)
        m = rag_metrics.compute_metrics(t, x, shape, g, D_C)
        self.assertEqual(m["outcome"], "running")
        self.assertAlmostEqual(m["chamber_entry_time_s"], 0.05, delta=1e-12)
        self.assertAlmostEqual(m["residence_time_s"], 0.25, delta=1e-12)  # to the end of the run
        self.assertEqual(m["residence_until"], "end_of_run")
        self.assertEqual(m["wrap_episodes"], 1)
        # longest wrap 1.5 revolutions within one frame's duration (DT = 0.025 rev)
        self.assertAlmostEqual(m["longest_wrap_revolutions"], 1.5, delta=DT / PERIOD)
        self.assertAlmostEqual(m["longest_wrap_s"], 0.15, delta=DT)
        # designed: 0.15 s of the 0.25 s residence = 0.6, within one frame (0.01)
        self.assertAlmostEqual(m["wrap_fraction_of_residence"], 0.6, delta=DT / 0.25)
        self.assertAlmostEqual(m["wrap_fraction_of_run"], 0.15 / 0.3, delta=DT / 0.3)
        # the held rag spans z = 0.032..0.044 (mean 0.038) of the edge's 0.048 (hub) .. 0.002
        self.assertAlmostEqual(m["wrap_span_fraction"], (0.038 - 0.048) / (0.002 - 0.048), delta=1e-9)
        self.assertAlmostEqual(m["trap_contact_time_s.leading_edge"], 0.15, delta=DT)
        self.assertEqual(m["trap_contact_time_s.cut_water"], 0.0)
        # the drape's rows: the heading of their last segment less that of their first (their
        # turning; every row alike), the bend of the 5 points 4 mm apart round a 180 deg arc of
        # 9.4 mm, both end segments partly on the arc: 177.6 deg
        row = on_edge[::shape[1], :2]
        heading = [math.atan2(*(row[j + 1] - row[j])[::-1]) for j in (0, len(row) - 2)]
        turning = math.degrees(heading[1] - heading[0]) % 360.0
        self.assertAlmostEqual(m["max_wrap_angle_deg"], turning, delta=1e-6)
        self.assertGreater(turning, 170.0)

    def test_rag_fixed_in_the_lab_frame_does_not_wrap(self):
        # the same points held still in the lab frame: the edge sweeps through the drape once a
        # revolution (inside it for a few degrees), never for 1.5 revolutions; this fails if the
        # module rotated the points the wrong way or not at all
        t, x, shape, on_edge = wrap_trajectory()
        held = (t >= 0.05 - 1e-12) & (t < 0.2 - 1e-12)
        x[held] = to_lab(on_edge, 0.05)
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertLess(m["longest_wrap_revolutions"], 0.3)
        self.assertGreaterEqual(m["wrap_episodes"], 2)
        # and the mirror image (turning the other way) does not stay on the edge either
        t, x, shape, on_edge = wrap_trajectory()
        for k in np.nonzero(held)[0]:
            x[k] = to_lab(on_edge, -t[k])
        self.assertLess(rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)["longest_wrap_revolutions"], 0.3)

    def test_wrap_angle_threshold(self):
        # the drape bends by max_wrap_angle_deg: a wrap at a threshold just under it, none just over
        t, x, shape, on_edge = wrap_trajectory()
        angle = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)["max_wrap_angle_deg"]
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, wrap_angle_deg=angle - 1.0)
        self.assertAlmostEqual(m["longest_wrap_revolutions"], 1.5, delta=DT / PERIOD)
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, wrap_angle_deg=angle + 1.0)
        self.assertEqual(m["longest_wrap_revolutions"], 0.0)
        self.assertIsNone(m["wrap_span_fraction"])  # empty: no wrap
        with self.assertRaises(rag_metrics.MetricsError):
            rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, wrap_angle_deg=0.0)

    def test_a_rag_lying_flat_along_the_edge_does_not_wrap(self):
        # the former criterion's case: the flat grid 3 mm beside the edge, every point touching it
        t, x, shape, on_edge = wrap_trajectory()
        local, _ = grid()
        flat = np.stack([np.full(len(local), 0.017), local[:, 1], 0.038 + local[:, 0]], axis=1)
        self.assertLess(np.max(box_distance(flat, IMPELLER["blade_leading_edge"])), 1.5 * D_C)
        held = (t >= 0.05 - 1e-12) & (t < 0.2 - 1e-12)
        for k in np.nonzero(held)[0]:
            x[k] = to_lab(flat, t[k])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertAlmostEqual(m["trap_contact_time_s.leading_edge"], 0.15, delta=DT)  # it touches
        self.assertLess(m["max_wrap_angle_deg"], 1e-6)
        self.assertEqual(m["wrap_episodes"], 0)


def cylinder_triangles(start, axis, radius, length, n=24):
    """A closed cylinder (n-gon prism with its two caps) from start along the unit axis."""
    axis = np.asarray(axis, float)
    e1 = np.cross(axis, [0.0, 0.0, 1.0] if abs(axis[2]) < 0.9 else [1.0, 0.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    a = 2 * math.pi * np.arange(n) / n
    ring = np.asarray(start, float) + radius * (np.outer(np.cos(a), e1) + np.outer(np.sin(a), e2))
    top, c0, c1 = ring + length * axis, np.asarray(start, float), np.asarray(start, float) + length * axis
    tris = []
    for i in range(n):
        j = (i + 1) % n
        tris += [[ring[i], ring[j], top[j]], [ring[i], top[j], top[i]], [c0, ring[j], ring[i]], [c1, top[i], top[j]]]
    return np.array(tris)


# Round noses for the leading edge: (start, axis, radius, length). Axial as the thin blade's
# (4 mm, along the axis at 24 mm from it), radial as the single channel's (8 mm, across the eye
# below the channel).
NOSES = {"axial": ((0.024, 0.0, 0.002), (0.0, 0.0, 1.0), 0.004, 0.046),
         "radial": ((0.012, 0.0, -0.010), (1.0, 0.0, 0.0), 0.008, 0.040)}


def nose_geometry(kind):
    start, axis, radius, length = NOSES[kind]
    regions = {name: box_regions_triangles(boxes) for name, boxes in IMPELLER.items()}
    regions["blade_leading_edge"] = cylinder_triangles(start, axis, radius, length)
    return geometry(impeller=regions, key=("nose", kind))


class WrapAngle(unittest.TestCase):
    """A wrap is seen from the rag's shape round the edge, at the coarse rag's spacing (1 cm, the
    15 x 5 cm rag's 16 x 6 points) and the medium one's (5 mm): each row of a rag bent theta
    round a round nose at the collision distance d_t = 4 mm from its surface (rows along the
    bend, columns along the edge), turning with the impeller. The rows' straight arms hold the
    first and last segments, so each row turns by exactly theta. Two frames."""

    def angle(self, kind, theta, spacing, grow=0.0, columns_bend=False, centre_offset=(0.0, 0.0), full=False,
              **options):
        start, axis, radius, length = NOSES[kind]
        axis = np.asarray(axis, float)
        e1 = np.cross(axis, [0.0, 0.0, 1.0] if abs(axis[2]) < 0.9 else [1.0, 0.0, 0.0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(axis, e1)
        n_bend = int(math.ceil((2 * math.pi * (radius + D_C + grow) * theta / 360.0) / spacing)) + 5
        row = bent_line(centre_offset, radius + D_C, theta, spacing, n_bend, grow=grow)
        along = 0.5 * length + spacing * (np.arange(4) - 1.5)
        pts = np.array([np.asarray(start) + u * e1 + v * e2 + w * axis for (u, v) in row for w in along])
        shape = (len(row), len(along))
        if columns_bend:   # the same rag with its grid's indices swapped: the columns bend
            pts = pts.reshape(shape[0], shape[1], 3).transpose(1, 0, 2).reshape(-1, 3)
            shape = shape[::-1]
        t = np.array([0.0, DT])
        x = np.array([to_lab(pts, tk) for tk in t])
        m = rag_metrics.compute_metrics(t, x, shape, nose_geometry(kind), D_C, **options)
        return (m, row) if full else (m["max_wrap_angle_deg"], m["wrap_episodes"])

    def test_draped_and_looped_rags_are_seen_at_both_spacings(self):
        for kind in NOSES:
            for spacing in (0.01, 0.005):
                with self.subTest(nose=kind, spacing=spacing):
                    angle, episodes = self.angle(kind, 180.0, spacing)
                    self.assertAlmostEqual(angle, 180.0, delta=1e-6)
                    self.assertEqual(episodes, 1)
                    # a full loop, its radius growing by 6 mm so that it passes outside its start
                    angle, episodes = self.angle(kind, 360.0, spacing, grow=0.006)
                    self.assertAlmostEqual(angle, 360.0, delta=1e-6)
                    self.assertEqual(episodes, 1)

    def test_a_partial_wrap_is_measured(self):
        for spacing in (0.01, 0.005):
            self.assertAlmostEqual(self.angle("axial", 90.0, spacing)[0], 90.0, delta=1e-6)
            self.assertAlmostEqual(self.angle("radial", 45.0, spacing)[0], 45.0, delta=1e-6)
            self.assertEqual(self.angle("axial", 45.0, spacing)[1], 0)   # under the 90 deg of a wrap

    def test_the_columns_bending_count_as_well(self):
        self.assertAlmostEqual(self.angle("axial", 180.0, 0.01, columns_bend=True)[0], 180.0, delta=1e-6)

    def test_a_rag_touching_the_nose_straight_does_not_wrap(self):
        # a straight rag tangent to the nose at d_t: touching, not bent
        for kind in NOSES:
            angle, episodes = self.angle(kind, 0.0, 0.01)
            self.assertLess(angle, 1e-6)
            self.assertEqual(episodes, 0)

    def test_a_fold_beside_the_nose_is_not_a_wrap(self):
        # a 180 deg fold of 6 mm radius whose bend is 16 mm beside the nose, not round it: its
        # lower arm passes the nose at d_t (touching it), its upper arm 12 mm further out; the
        # whole fold within the reach (5 cm). It turns 180 deg but winds round the nose by little.
        _, _, radius, _ = NOSES["axial"]
        m, row = self.angle("axial", 180.0, 0.005, centre_offset=(-0.016, radius + D_C + 0.006), full=True,
                            wrap_reach_m=0.05)
        self.assertGreater(m["trap_contact_time_s.leading_edge"], 0.0)
        self.assertAlmostEqual(rag_metrics.turning_angle_deg(np.c_[row, np.zeros(len(row))], np.array([0, 0, 1.0])),
                               180.0, delta=1e-6)
        self.assertLess(m["max_wrap_angle_deg"], 60.0)
        self.assertEqual(m["wrap_episodes"], 0)


class Outcome(unittest.TestCase):
    """(2) exit into the discharge at a known time; (4) hung up after N_max revolutions."""

    def expected_exit(self, t, x):
        radius = np.hypot(x[:, :, 0], x[:, :, 1])
        return t[np.argmax(np.all(radius > SQUARE, axis=1))]

    def test_passed(self):
        t, x, shape = discharge_trajectory()
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertEqual(m["outcome"], "passed")
        # all points beyond the volute's radius: the trailing column (x_c - 8 mm, |y| = 2 mm)
        # passes 0.12 sqrt 2 at x_c = 0.177699 m, t = 0.227699 s; the next frame: 0.23 s
        analytic = 0.1 + math.sqrt(SQUARE ** 2 - 0.002 ** 2) + 0.008 - 0.05
        self.assertAlmostEqual(m["exit_time_s"], self.expected_exit(t, x), delta=1e-12)
        self.assertGreaterEqual(m["exit_time_s"], analytic)
        self.assertLessEqual(m["exit_time_s"], analytic + DT)  # within one frame
        self.assertAlmostEqual(m["exit_revolution"], m["exit_time_s"] / PERIOD, delta=1e-12)
        self.assertEqual(m["time_from_release_to_exit_s"], m["exit_time_s"])
        self.assertAlmostEqual(m["chamber_entry_time_s"], 0.05, delta=1e-12)
        self.assertAlmostEqual(m["residence_time_s"], m["exit_time_s"] - 0.05, delta=1e-12)
        self.assertAlmostEqual(m["residence_time_revolutions"], (m["exit_time_s"] - 0.05) / PERIOD, delta=1e-9)
        self.assertEqual(m["residence_until"], "exit")
        self.assertGreater(m["trap_contact_time_s.discharge"], 0.0)

    def test_nearest_region_must_be_the_discharge(self):
        # with a discharge radius of 0.05 m the radius alone would let the rag out while it is
        # still in the volute box (x_c > 0.058 m); the nearest casing region must be the
        # discharge's too: derived here from the boxes
        t, x, shape = discharge_trajectory()
        g = geometry(discharge_radius_m=0.05)
        m = rag_metrics.compute_metrics(t, x, shape, g, D_C)
        p = x.reshape(-1, 3)
        d_out = np.minimum(box_distance(p, CASING["discharge_wall"]), box_distance(p, CASING["outlet"]))
        d_other = np.min([box_distance(p, CASING[k]) for k in CASING if k not in ("discharge_wall", "outlet")], axis=0)
        radius = np.hypot(p[:, 0], p[:, 1])
        out = np.all(((d_out < d_other) & (radius > 0.05)).reshape(len(t), -1), axis=1)
        # every point nearer the discharge once x > 0.1225 m (halfway across the 5 mm between
        # the boxes): x_c > 0.1305 m, the frame at 0.1825 s
        self.assertAlmostEqual(t[np.argmax(out)], 0.1825, delta=1e-12)
        self.assertAlmostEqual(m["exit_time_s"], 0.1825, delta=1e-12)
        self.assertEqual(m["outcome"], "passed")

    def test_hung_up(self):
        local, shape = grid()
        t = np.arange(0, 121) * DT  # 3 revolutions in the chamber
        x = np.array([IN_CHAMBER + local for _ in t])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, n_max_revolutions=2)
        self.assertEqual(m["outcome"], "hung_up")
        self.assertIsNone(m["exit_time_s"])
        self.assertAlmostEqual(m["residence_time_revolutions"], 3.0, delta=1e-9)
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, n_max_revolutions=5)
        self.assertEqual(m["outcome"], "running")
        # a rag that leaves only after N_max revolutions passed late (its exit is reported)
        t, x, shape = discharge_trajectory()
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, n_max_revolutions=2)
        self.assertEqual(m["outcome"], "passed_late")
        self.assertGreater(m["exit_revolution"], 2.0)
        self.assertEqual(rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)["outcome"], "passed")


class CutWater(unittest.TestCase):
    """(3) a rag that never reaches the cut-water; and one that passes it at a known time."""

    def test_never_touches(self):
        t, x, shape = discharge_trajectory()
        d = box_distance(x.reshape(-1, 3), CASING["cut_water"])
        self.assertGreater(d.min(), 2 * D_C)  # by construction: 34 mm at the closest
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertIsNone(m["time_to_cut_water_s"])  # empty: never reached
        self.assertIsNone(m["time_to_cut_water_revolutions"])
        self.assertEqual(m["trap_contact_time_s.cut_water"], 0.0)

    def test_passes_close(self):
        t, x, shape = discharge_trajectory(y_offset=0.03)  # points up to y = 0.036, the nose at 0.04
        d = box_distance(x.reshape(-1, 3), CASING["cut_water"]).reshape(len(t), -1)
        first = t[np.argmax(np.any(d <= 2 * D_C, axis=1))]
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertAlmostEqual(m["time_to_cut_water_s"], first, delta=1e-12)
        touching = np.any(d <= 1.5 * D_C, axis=1)
        self.assertAlmostEqual(m["trap_contact_time_s.cut_water"], np.sum(np.diff(rag_metrics.frame_edges(t))[touching]),
                               delta=1e-12)
        self.assertGreater(m["trap_contact_time_s.cut_water"], 0.0)
        # a larger reach: an earlier or equal first time
        m2 = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, cut_water_distance_m=0.02)
        self.assertAlmostEqual(m2["time_to_cut_water_s"], t[np.argmax(np.any(d <= 0.02, axis=1))], delta=1e-12)


class Mechanics(unittest.TestCase):
    """(5) strain of a stretched grid; self-contacts of a folded one; frames; closest wall."""

    def test_max_strain_as_built(self):
        local, shape = grid()
        t = np.arange(5) * DT
        base = IN_CHAMBER + local
        stretched = IN_CHAMBER + local * [1.02, 1.0, 1.0]           # s1 edges +2 %
        one_edge = base.copy()
        rows = np.arange(len(local)) // shape[1]
        one_edge[rows >= 3, 0] += 0.05 * 0.004                       # the edge between rows 2 and 3: +5 %
        squeezed = IN_CHAMBER + local * [0.9, 0.9, 1.0]               # all edges -10 %
        x = np.array([base, stretched, one_edge, squeezed, base])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertAlmostEqual(m["max_strain"], 0.05, delta=1e-9)
        self.assertEqual(m["max_strain_time_s"], t[2])
        self.assertAlmostEqual(m["strain_over_limit_fraction"], 1 / 5, delta=1e-12)  # only the 5 % frame
        self.assertEqual(m["n_frames"], 5)
        self.assertEqual(m["n_points"], 20)
        self.assertEqual(m["max_self_contacts"], 0)
        _, series = rag_metrics.analyse(t, x, shape, geometry(), D_C)
        np.testing.assert_allclose(series["strain"], [0, 0.02, 0.05, -0.1, 0], atol=1e-9)

    def test_self_contacts_of_a_fold(self):
        # rows 0-2 flat, rows 3-4 folded back 2 mm above: row 3 over row 1, row 4 over row 0:
        # 2 x 4 pairs 2 mm apart that are not grid neighbours (row 3 over row 2's neighbour is)
        local, shape, rows, folded = folded_grid()
        t = np.array([0.0, DT])
        x = np.array([IN_CHAMBER + local, IN_CHAMBER + folded])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertEqual(m["max_self_contacts"], 8)
        self.assertEqual(m["max_self_contacts_time_s"], DT)

    def test_strain_clear_of_contact(self):
        # frame 1: the fold of test_self_contacts_of_a_fold with its folded rows 3-4 stretched
        # 10 % along s2: in contact (rows 0, 1, 3, 4 within the contact distance 1.5 d_c = 6 mm
        # of a point that is not a grid neighbour). max_strain is the fold's edge from row 2 to
        # row 3 at the rag's side (4 mm along s1, 2 mm up, 0.6 mm along s2); the clear strain
        # sees only row 2's s2 edges (0 %). Frame 2: flat, one edge +5 %, clear
        local, shape, rows, folded = folded_grid()
        folded[rows >= 3, 1] *= 1.1
        one_edge = local.copy()
        one_edge[rows >= 3, 0] += 0.05 * 0.004
        t = (1 + np.arange(3)) * DT  # at t = 0 the blade crosses IN_CHAMBER: every edge in contact
        x = np.array([IN_CHAMBER + local, IN_CHAMBER + folded, IN_CHAMBER + one_edge])
        m, series = rag_metrics.analyse(t, x, shape, geometry(), D_C)
        self.assertAlmostEqual(m["max_strain"], math.sqrt(4.0**2 + 2.0**2 + 0.6**2) / 4.0 - 1, delta=1e-9)
        self.assertEqual(m["max_strain_time_s"], t[1])
        self.assertAlmostEqual(m["max_strain_clear"], 0.05, delta=1e-9)
        self.assertEqual(m["max_strain_clear_time_s"], t[2])
        self.assertAlmostEqual(m["strain_clear_over_limit_fraction"], 1 / 3, delta=1e-12)
        np.testing.assert_allclose(series["strain_clear"], [0, 0, 0.05], atol=1e-9)
        # a rag 3 mm under the hub, every edge stretched 10 %: no edge is clear of contact
        t = np.arange(0, 5) * DT
        held = np.array([-0.06, 0.03, 0.047]) + local * [1.1, 1.1, 1.0]
        x = np.array([to_lab(np.array([-0.06, 0.03, 0.047]) + local, t[0])] +
                     [to_lab(held, tk) for tk in t[1:]])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertAlmostEqual(m["max_strain"], 0.10, delta=1e-9)
        self.assertIsNone(m["max_strain_clear"])
        self.assertIsNone(m["max_strain_clear_time_s"])
        self.assertEqual(m["strain_clear_over_limit_fraction"], 0.0)

    def test_min_wall_distance(self):
        # a rag 3 mm under the hub, held in the impeller's frame away from the blade
        local, shape = grid()
        t = np.arange(0, 41) * DT
        held = np.array([-0.06, 0.03, 0.047]) + local
        x = np.array([to_lab(held, tk) for tk in t])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertAlmostEqual(m["min_wall_distance_m"], 0.003, delta=1e-9)
        self.assertEqual(m["min_wall_distance_region"], "hub")
        # the hub inside the channel: eye_and_hub for the whole run
        self.assertAlmostEqual(m["trap_contact_time_s.eye_and_hub"], t[-1], delta=1e-12)
        self.assertEqual(m["trap_contact_time_s.side_gap"], 0.0)
        # far from every wall (no contact anywhere): the exact minimum by the fallback
        x = np.array([IN_SUCTION + local for _ in t])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        expected = 0.05 - 0.008  # the suction pipe's walls at |x|, |y| = 0.05, the rag's corners at |x| = 8 mm
        self.assertAlmostEqual(m["min_wall_distance_m"], expected, delta=1e-9)
        self.assertEqual(m["min_wall_distance_region"], "suction_wall")

    def test_side_gap(self):
        # a rag 3 mm above the hub's back face (outside the channel), turning with the impeller
        local, shape = grid()
        t = np.arange(0, 21) * DT
        held = np.array([-0.06, 0.03, 0.061]) + local
        x = np.array([to_lab(held, tk) for tk in t])
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        self.assertAlmostEqual(m["trap_contact_time_s.side_gap"], t[-1], delta=1e-12)
        self.assertEqual(m["trap_contact_time_s.eye_and_hub"], 0.0)


class Cost(unittest.TestCase):
    """Torque and head while wrapped against the rest and a clean pump, phase-averaged."""

    def test_phase_averaged_rise(self):
        t, x, shape, _ = wrap_trajectory()
        ts = np.arange(0, 3000) * 1e-4  # every 0.1 ms to 0.3 s
        edges = rag_metrics.frame_edges(t)
        wrapped = (ts >= edges[20]) & (ts < edges[80])  # the frames 0.05 .. 0.1975 s
        torque = 10 + 3 * np.cos(RATE * ts + 0.3) + 2 * wrapped
        head = 5 + 0.5 * np.sin(RATE * ts) - 1 * wrapped
        loads = {"torque": (ts, torque), "head": (ts, head)}
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C, loads=loads,
                                        clean={"torque": 9.5, "head": 5.2})
        # phase-averaged over 12 bins: the pulsation (+-3 N m, +-0.5 m) drops out to under 1 %
        # of its amplitude (measured 0.002 N m and 0.004 m; the plain means are 0.28 and 0.21 off)
        self.assertAlmostEqual(m["torque_wrap_minus_rest_n_m"], 2.0, delta=0.02)
        self.assertAlmostEqual(m["head_wrap_minus_rest_m"], -1.0, delta=0.01)
        self.assertAlmostEqual(m["torque_wrap_n_m"], 12.0, delta=0.02)
        self.assertAlmostEqual(m["torque_wrap_minus_clean_n_m"], 2.5, delta=0.02)
        self.assertAlmostEqual(m["head_wrap_minus_clean_m"], -1.2, delta=0.01)
        self.assertIs(m["torque_phase_averaged"], True)
        # the plain means are further off (1.5 revolutions of wrap): phase averaging matters here
        plain = np.mean(torque[wrapped]) - np.mean(torque[~wrapped])
        self.assertGreater(abs(plain - 2.0), 3 * abs(m["torque_wrap_minus_rest_n_m"] - 2.0))

    def test_missing_data_leave_fields_empty(self):
        t, x, shape, _ = wrap_trajectory()
        m = rag_metrics.compute_metrics(t, x, shape, geometry(), D_C)
        for key in rag_metrics.COST_KEYS:
            self.assertIsNone(m[key], key)


class Files(unittest.TestCase):
    """write_metrics and the CLI on a synthetic run folder and case folder; clear errors."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="rag-metrics-")
        self.case = os.path.join(self.tmp, "case")
        self.run_dir = os.path.join(self.tmp, "run")
        os.makedirs(os.path.join(self.case, "geometry"))
        os.makedirs(self.run_dir)
        write_stl(os.path.join(self.case, "geometry", "impeller.stl"), IMPELLER)
        write_stl(os.path.join(self.case, "geometry", "casing.stl"), CASING)
        with open(os.path.join(self.case, "geometry", "geometry.yaml"), "w") as f:
            yaml.safe_dump({"rotation_axis": AXIS, "rotation_rate_rad_per_s": RATE}, f)
        self.case_yaml = {
            "run": {"end_time_s": 0.3, "time_step_s": DT, "output_interval_s": DT},
            "collisions": {"threshold_m": D_C, "target_distance_m": D_C, "surfaces": [
                {"mesh": {"file": "geometry/impeller.stl"},
                 "motion": {"rotation": {"axis_point_m": [0, 0, 0], "axis_direction": AXIS, "rate_rad_per_s": RATE}}},
                {"mesh": {"file": "geometry/casing.stl", "fluid_side": "inside"}}]},
            "structures": [{"name": "rag", "model": "membrane"}]}
        self.write_case()
        self.write_structure()
        ts = np.arange(0, 3000) * 1e-4
        with open(os.path.join(self.run_dir, "forces.csv"), "w") as f:
            f.write("time_s,total_force_on_fluid.x_n,total_force_on_fluid.y_n,total_force_on_fluid.z_n,"
                    "surface0.force_x_n,surface0.force_y_n,surface0.force_z_n,"
                    "surface0.torque_x_n_m,surface0.torque_y_n_m,surface0.torque_z_n_m\n")
            for tk in ts:
                wrapped = 0.04875 <= tk < 0.19875
                # shaft torque = -axis . T = T_z (axis -z): 10 N m, 12 while wrapped
                f.write("%g,0,0,0,0,0,0,0,0,%g\n" % (tk, 10 + 2 * wrapped))
        with open(os.path.join(self.tmp, "clean.yaml"), "w") as f:
            yaml.safe_dump({"flow_rate_m3_per_s": 0.02, "head_m": 5.0, "shaft_torque_n_m": 9.0}, f)

    def write_structure(self):
        t, x, shape, _ = wrap_trajectory()
        with h5py.File(os.path.join(self.run_dir, "structure.h5"), "w") as f:
            f.attrs["status"] = "completed"
            f["time_s"] = t
            g = f.create_group("structures/rag")
            g.attrs["grid_shape"] = np.array(shape)
            g["position_m"] = x
            g["max_stretch_ratio"] = np.full(len(t), 1.001)

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def write_case(self):
        with open(os.path.join(self.case, "case.yaml"), "w") as f:
            yaml.safe_dump(self.case_yaml, f)

    def test_outputs(self):
        m = rag_metrics.write_metrics(self.run_dir, self.case,
                                      clean_operating_point=os.path.join(self.tmp, "clean.yaml"))
        self.assertEqual(m["outcome"], "running")
        self.assertAlmostEqual(m["longest_wrap_revolutions"], 1.5, delta=DT / PERIOD)
        # settle_revolutions defaults to 1 without a precursor: the rest is t >= 0.1 s
        self.assertAlmostEqual(m["torque_wrap_n_m"], 12.0, delta=1e-9)
        self.assertAlmostEqual(m["torque_rest_n_m"], 10.0, delta=1e-9)
        self.assertAlmostEqual(m["torque_wrap_minus_clean_n_m"], 3.0, delta=1e-9)
        self.assertAlmostEqual(m["head_clean_m"], 5.0, delta=1e-12)
        self.assertIsNone(m["head_wrap_m"])  # no openfoam/postProcessing: empty
        self.assertAlmostEqual(m["solver_max_stretch_ratio"], 1.001, delta=1e-12)
        with open(os.path.join(self.run_dir, "rag_metrics.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 1)
        row = rows[0]
        for key in ("residence_time_s", "wrap_fraction_of_residence", "longest_wrap_revolutions",
                    "trap_contact_time_s.leading_edge", "max_strain", "min_wall_distance_m", "max_self_contacts"):
            self.assertIn(key, row)
        self.assertAlmostEqual(float(row["longest_wrap_revolutions"]), m["longest_wrap_revolutions"], delta=1e-6)
        self.assertEqual(row["exit_time_s"], "")     # not passed: empty
        self.assertEqual(row["head_wrap_m"], "")     # no head data: empty
        with open(os.path.join(self.run_dir, "rag_metrics.yaml")) as f:
            doc = yaml.safe_load(f)
        self.assertEqual(list(doc)[:len(m)], list(m))  # the metrics at the top level, in order
        self.assertIsNone(doc["exit_time_s"])
        self.assertAlmostEqual(doc["parameters"]["contact_distance_m"], 1.5 * D_C, delta=1e-12)
        self.assertEqual(doc["parameters"]["n_max_revolutions"], 10.0)
        self.assertTrue(any(d.startswith("wrap_fraction_of_residence: ") for d in doc["definitions"]))
        self.assertTrue(any(d.startswith("site side_gap: ") for d in doc["definitions"]))
        png = os.path.join(self.run_dir, "rag_summary.png")
        self.assertGreater(os.path.getsize(png), 10000)

    def test_clean_pump_from_the_precursor(self):
        """Without --clean-operating-point, the clean pump is the second half of the precursor, in
        whole revolutions: over 4.5 revolutions, a torque of 9 + 3 sin(rate t) N m averages to 9
        over the last 2, whatever came before (50 N m); a precursor still settling (9 then 12 N m
        over those 2) gives none."""
        folder = os.path.join(self.run_dir, "precursor")
        os.makedirs(folder)
        ts = np.arange(0, 4501) * 1e-4

        def write(torque):
            with open(os.path.join(folder, "forces.csv"), "w") as f:
                f.write("time_s,body0.fx_n,body0.fy_n,body0.fz_n,body0.tx_n_m,body0.ty_n_m,body0.tz_n_m\n")
                for tk in ts:  # shaft torque = -axis . T = T_z (axis -z)
                    f.write("%.10g,0,0,0,0,0,%.17g\n" % (tk, torque(tk)))
        write(lambda tk: 50.0 if tk < 0.25 else 9 + 3 * math.sin(RATE * tk))
        m = rag_metrics.write_metrics(self.run_dir, self.case)
        self.assertAlmostEqual(m["torque_clean_n_m"], 9.0, delta=1e-9)
        self.assertAlmostEqual(m["torque_rest_n_m"] - m["torque_clean_n_m"], 1.0, delta=0.05)
        with open(os.path.join(self.run_dir, "rag_metrics.yaml")) as f:
            self.assertIn("precursor: the last 2 revolutions", f.read())
        write(lambda tk: 9.0 if tk < 0.35 else 12.0)
        m = rag_metrics.write_metrics(self.run_dir, self.case)
        self.assertIsNone(m["torque_clean_n_m"])
        with open(os.path.join(self.run_dir, "rag_metrics.yaml")) as f:
            self.assertIn("still settling", f.read())

    def test_impeller_for_paraview(self):
        """impeller.h5 holds the impeller's STL at its pose of every saved frame (against to_lab,
        the rotation written out), and both ParaView readers show that frame's points."""
        xdmf = impeller_xdmf.write(self.run_dir, self.case)
        with h5py.File(os.path.join(self.run_dir, "impeller.h5"), "r") as f:
            t, x = f["time_s"][:], f["position_m"][:]
            triangles, region, names = f["connectivity"][:], f["region"][:], list(f["region_names"].asstr()[:])
        with h5py.File(os.path.join(self.run_dir, "structure.h5"), "r") as f:
            np.testing.assert_array_equal(t, f["time_s"][:])
        self.assertEqual(names, sorted(IMPELLER))
        self.assertEqual(len(triangles), 12 * sum(len(v) for v in IMPELLER.values()))
        corners = np.concatenate([box_triangles(lo, hi) for k in names for lo, hi in IMPELLER[k]])
        # frame 0 rebuilds every STL triangle, each with its region
        np.testing.assert_allclose(x[0][triangles], corners, atol=1e-7)
        np.testing.assert_array_equal(region, np.repeat(np.arange(len(names)),
                                                        [12 * len(IMPELLER[k]) for k in names]))
        for k in (1, len(t) // 3, len(t) - 1):
            np.testing.assert_allclose(x[k], to_lab(x[0].astype(float), t[k]), atol=1e-6)
        if shutil.which("pvbatch") is None:
            self.skipTest("no pvbatch (Debian's paraview): the readers were not checked")
        frame = len(t) // 3
        script = os.path.join(self.tmp, "open.py")
        with open(script, "w") as f:
            f.write("import sys\nfrom paraview import simple\n"
                    "from vtkmodules.util.numpy_support import vtk_to_numpy\n"
                    "for r in (simple.OpenDataFile(sys.argv[1]), simple.XDMFReader(FileNames=[sys.argv[1]])):\n"
                    "    r.UpdatePipeline(%r)\n"
                    "    d = r.GetClientSideObject().GetOutputDataObject(0)\n"
                    "    print(len(r.TimestepValues), r.GetDataInformation().GetNumberOfCells(), "
                    "' '.join('%%.9g' %% v for v in vtk_to_numpy(d.GetPoints().GetData()).ravel()))\n"
                    % float(t[frame]))
        out = subprocess.run(["pvbatch", "--force-offscreen-rendering", script, xdmf], cwd=self.run_dir,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
        lines = [line for line in out.stdout.splitlines() if line[:1].isdigit()]
        self.assertEqual(len(lines), 2, out.stdout[-2000:])
        for line in lines:
            n_times, n_cells, *points = line.split()
            self.assertEqual((int(n_times), int(n_cells)), (len(t), len(triangles)))
            np.testing.assert_allclose(np.array(points, float).reshape(-1, 3), x[frame], atol=1e-7)

    def test_cli(self):
        code = rag_metrics.main([self.run_dir, self.case, "--n-max-revolutions", "2", "--wrap-angle-deg", "150",
                                 "--wrap-reach-m", "0.03",
                                 "--contact-distance-m", "0.005", "--no-picture"])
        self.assertEqual(code, 0)
        with open(os.path.join(self.run_dir, "rag_metrics.yaml")) as f:
            doc = yaml.safe_load(f)
        self.assertEqual(doc["outcome"], "hung_up")  # 3 revolutions run, N_max = 2
        self.assertEqual(doc["parameters"]["wrap_angle_deg"], 150.0)
        self.assertEqual(doc["parameters"]["wrap_reach_m"], 0.03)
        self.assertEqual(doc["parameters"]["contact_distance_m"], 0.005)
        self.assertFalse(os.path.exists(os.path.join(self.run_dir, "rag_summary.png")))

    def test_errors(self):
        os.remove(os.path.join(self.run_dir, "structure.h5"))
        with self.assertRaisesRegex(rag_metrics.MetricsError, "structure.h5: no such file"):
            rag_metrics.write_metrics(self.run_dir, self.case)
        self.assertEqual(rag_metrics.main([self.run_dir, self.case]), 2)
        self.write_structure()
        with self.assertRaisesRegex(rag_metrics.MetricsError, "no structure 'flag' \\(allowed: rag\\)"):
            rag_metrics.write_metrics(self.run_dir, self.case, structure="flag")
        with self.assertRaisesRegex(rag_metrics.MetricsError, "unknown option"):
            rag_metrics.write_metrics(self.run_dir, self.case, wrap_fractoin=0.2)
        with self.assertRaisesRegex(rag_metrics.MetricsError, "no such file"):
            rag_metrics.write_metrics(self.run_dir, self.case, clean_operating_point=os.path.join(self.tmp, "none.yaml"))
        motion = self.case_yaml["collisions"]["surfaces"][0].pop("motion")
        self.write_case()
        with self.assertRaisesRegex(rag_metrics.MetricsError, "no mesh surface with motion.rotation"):
            rag_metrics.write_metrics(self.run_dir, self.case)
        self.case_yaml["collisions"]["surfaces"][0]["motion"] = motion
        self.write_case()
        regions = dict(CASING)
        del regions["cut_water"]
        write_stl(os.path.join(self.case, "geometry", "casing.stl"), regions)
        with self.assertRaisesRegex(rag_metrics.MetricsError, "casing.stl: no region cut_water"):
            rag_metrics.write_metrics(self.run_dir, self.case)
        with open(os.path.join(self.case, "geometry", "casing.stl"), "wb") as f:
            f.write(b"\0" * 84)  # a binary STL: no regions
        with self.assertRaisesRegex(rag_metrics.MetricsError, "not an ASCII STL with named solids"):
            rag_metrics.write_metrics(self.run_dir, self.case)

if __name__ == "__main__":
    unittest.main()
