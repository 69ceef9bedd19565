#!/usr/bin/python3
"""Checks of python/fsi/snap_quality.py (how closely a body-fitted mesh follows its surface):
- Staircase: an axis-aligned staircase over a cylinder stands half its area more than 30 deg off
  the cylinder (exactly 1/2 for a fine staircase: the faces of normal x are within 30 deg of the
  radius where |theta| < 30 deg, those of normal y where |theta| > 60 deg, and the area of each
  kind grows as |cos| and |sin|); a finer polygon of the same cylinder stands none of it off.
- Report: a blockMesh cube against its own STL (no step) and against a box twice as wide turned
  45 deg about the axis (its four sides off: 4/6 of the area), through surfaceMeshExtract as the AMI
  reference's check runs it; refusals of a missing surface and a patch the mesh lacks.
    /usr/bin/python3 tests/cases/test_snap_quality.py [-v] [Class]
Needs fsi-surface-query (build/bin or FSI_BIN_DIR); Report needs OpenFOAM (skipped without it).
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from fsi import snap_quality  # noqa: E402
from fsi.foam_case import OPENFOAM_ENVIRONMENT  # noqa: E402

R, HEIGHT = 0.1, 0.07


def cylinder(n):
    """The side of a cylinder of radius R as a polygon of n facets (2 triangles each)."""
    t = np.linspace(0, 2 * math.pi, n + 1)
    tri = []
    for a, b in zip(t[:-1], t[1:]):
        p = [R * math.cos(a), R * math.sin(a)]
        q = [R * math.cos(b), R * math.sin(b)]
        tri.append([p + [0], q + [0], q + [HEIGHT]])
        tri.append([p + [0], q + [HEIGHT], p + [HEIGHT]])
    return np.array(tri, float)


def staircase(step):
    """An axis-aligned staircase following the circle of radius R (steps of `step`), extruded
    over HEIGHT: for each step, one face of normal x and one of normal y."""
    n = int(round(2 * math.pi * R / step)) * 4
    t = np.linspace(0, 2 * math.pi, n + 1)
    pts = np.c_[R * np.cos(t), R * np.sin(t)]
    tri = []
    for (x0, y0), (x1, y1) in zip(pts[:-1], pts[1:]):
        corner = (x1, y0) if abs(x1 - x0) > 0 else (x0, y1)   # x first, then y
        for (ax, ay), (bx, by) in (((x0, y0), corner), (corner, (x1, y1))):
            if abs(ax - bx) + abs(ay - by) < 1e-15:
                continue
            tri.append([[ax, ay, 0], [bx, by, 0], [bx, by, HEIGHT]])
            tri.append([[ax, ay, 0], [bx, by, HEIGHT], [ax, ay, HEIGHT]])
    return np.array(tri, float)


class Staircase(unittest.TestCase):
    def test_a_staircase_is_half_stepped(self):
        fraction, distance, area = snap_quality.stepped(staircase(0.0005), cylinder(720))
        self.assertAlmostEqual(fraction, 0.5, delta=0.02)          # 1/2 exactly in the limit
        self.assertLess(distance, 0.0005)                          # within a step of the wall

    def test_a_polygon_of_the_cylinder_is_not_stepped(self):
        fraction, distance, area = snap_quality.stepped(cylinder(90), cylinder(720))
        self.assertEqual(fraction, 0.0)                            # 2 deg facets against 0.5 deg
        self.assertAlmostEqual(area, 2 * math.pi * R * HEIGHT, delta=0.001 * area)


BLOCK_MESH = """FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
convertToMeters 1;
vertices ((-0.5 -0.5 -0.5) (0.5 -0.5 -0.5) (0.5 0.5 -0.5) (-0.5 0.5 -0.5)
          (-0.5 -0.5 0.5) (0.5 -0.5 0.5) (0.5 0.5 0.5) (-0.5 0.5 0.5));
blocks (hex (0 1 2 3 4 5 6 7) (4 4 4) simpleGrading (1 1 1));
boundary ( cube { type wall; faces ((0 3 2 1) (4 5 6 7) (0 1 5 4) (2 3 7 6) (0 4 7 3) (1 2 6 5)); } );
"""
CONTROL = """FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application none; startFrom startTime; startTime 0; stopAt endTime; endTime 1; deltaT 1;
writeControl timeStep; writeInterval 1;
"""


def cube_stl(turn_deg, width=1.0):
    """The unit cube's surface (one solid, `cube`), its sides `width` wide, turned about z."""
    h = 0.5 * width
    corners = np.array([[x, y, z] for z in (-0.5, 0.5) for y in (-h, h) for x in (-h, h)])
    a = math.radians(turn_deg)
    rot = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])
    c = corners @ rot.T
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    lines = ["solid cube"]
    for q in quads:
        for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            lines.append("facet normal 0 0 0\nouter loop")
            lines += ["vertex %r %r %r" % tuple(c[i]) for i in t]
            lines.append("endloop\nendfacet")
    lines.append("endsolid cube")
    return "\n".join(lines) + "\n"


class Report(unittest.TestCase):
    def setUp(self):
        if shutil.which("blockMesh") is None or shutil.which("surfaceMeshExtract") is None:
            self.skipTest("OpenFOAM (blockMesh, surfaceMeshExtract) not installed")
        self.dir = tempfile.mkdtemp(prefix="snap-quality-test-")
        os.makedirs(os.path.join(self.dir, "system"))
        with open(os.path.join(self.dir, "system", "blockMeshDict"), "w") as f:
            f.write(BLOCK_MESH)
        with open(os.path.join(self.dir, "system", "controlDict"), "w") as f:
            f.write(CONTROL)
        done = subprocess.run(["blockMesh", "-case", self.dir], env=dict(os.environ, **OPENFOAM_ENVIRONMENT),
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        self.assertEqual(done.returncode, 0, done.stdout.decode()[-2000:])

    def tearDown(self):
        if hasattr(self, "dir"):
            shutil.rmtree(self.dir, ignore_errors=True)

    def surface(self, turn_deg, width=1.0):
        path = os.path.join(self.dir, "cube%g-%g.stl" % (turn_deg, width))
        with open(path, "w") as f:
            f.write(cube_stl(turn_deg, width))
        return path

    def test_the_cube_against_itself_and_turned(self):
        own = snap_quality.report(self.dir, self.surface(0))
        self.assertEqual(list(own), ["cube"])
        self.assertEqual(own["cube"]["stepped_area_fraction"], 0.0)
        self.assertAlmostEqual(own["cube"]["area_m2"], 6.0, places=6)
        # Turned and twice as wide, so that every face of the mesh's top and bottom lies over the
        # surface's: those match, the four sides (normals x, y against +-45 deg or z) do not.
        turned = snap_quality.report(self.dir, self.surface(45, width=2.0))
        self.assertAlmostEqual(turned["cube"]["stepped_area_fraction"], 4.0 / 6.0, places=3)
        self.assertEqual(len(snap_quality.warnings(turned)), 1)
        self.assertEqual(snap_quality.warnings(own), [])

    def test_refusals_name_what_is_missing(self):
        with self.assertRaisesRegex(snap_quality.SnapError, "no such file"):
            snap_quality.report(self.dir, os.path.join(self.dir, "absent.stl"))
        with self.assertRaisesRegex(snap_quality.SnapError, "patch blade"):
            snap_quality.report(self.dir, self.surface(0), patches=["blade"])
        with self.assertRaisesRegex(snap_quality.SnapError, "not a meshed OpenFOAM case"):
            snap_quality.report(os.path.join(self.dir, "system"), self.surface(0))


if __name__ == "__main__":
    unittest.main()
