#!/usr/bin/python3
"""Checks of python/fsi/plot_flow.py on a hand-written one-cell OpenFOAM case (ascii, no
structure): a PNG per time after 0, and exit 1 without results. Skipped without pvbatch.
    /usr/bin/python3 tests/launcher/test_plot_flow.py
"""
import os
import shutil
import subprocess
import tempfile
import unittest

from fsi.foam_case import foam_header

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "python", "fsi", "plot_flow.py")
PVBATCH = shutil.which("pvbatch")

MESH = {
    "points": ("vectorField", "8 ((0 0 0) (2 0 0) (2 1 0) (0 1 0)"
                              " (0 0 1) (2 0 1) (2 1 1) (0 1 1))"),
    "faces": ("faceList", "6 (4(0 4 7 3) 4(1 2 6 5) 4(0 1 5 4) 4(3 7 6 2)"
                          " 4(0 3 2 1) 4(4 5 6 7))"),
    "owner": ("labelList", "6 (0 0 0 0 0 0)"),
    "neighbour": ("labelList", "0 ()"),
    "boundary": ("polyBoundaryMesh", "1 (walls { type wall; nFaces 6; startFace 0; })"),
}
U = ("dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0.1 0 0);\n"
     "boundaryField { walls { type slip; } }\n")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


@unittest.skipUnless(PVBATCH, "needs ParaView's pvbatch")
class PlotFlow(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp(prefix="plot_flow_")
        self.case = os.path.join(self.out, "openfoam")

    def tearDown(self):
        shutil.rmtree(self.out)

    def run_script(self, *extra):
        return subprocess.run([PVBATCH, "--force-offscreen-rendering", SCRIPT, self.out,
                               *extra], capture_output=True, text=True, timeout=120)

    def test_no_results_exits_1_with_a_message(self):
        write(os.path.join(self.case, "0", "U"), foam_header("volVectorField", "U") + U)
        result = self.run_script()
        self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
        self.assertIn("no OpenFOAM results", result.stderr)

    def test_one_picture_per_time_after_0(self):
        for name, (cls, body) in MESH.items():
            write(os.path.join(self.case, "constant", "polyMesh", name),
                  foam_header(cls, name) + body + "\n")
        for time in ("0", "0.5", "1"):
            write(os.path.join(self.case, time, "U"), foam_header("volVectorField", "U") + U)
        result = self.run_script("--normal", "z")
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        for name in ("flow_t0.5.png", "flow_t1.png"):
            with open(os.path.join(self.out, name), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertFalse(os.path.exists(os.path.join(self.out, "flow_t0.png")))


if __name__ == "__main__":
    unittest.main()
