#!/usr/bin/python3
"""Check of python/fsi/pump_channel_budget.py on a flow with a known answer: in a block of cells
turning at OMEGA about +z, water turning with it plus a relative swirl W0 along +theta, and the
pressure p = (OMEGA r)^2 / 2 + C (kinematic) that keeps its rothalpy uniform. Every half-plane
must carry W0 times its area (r < R2, 0 < z < b2) along +theta and none back, and a rothalpy of
(C + W0^2 / 2) / g. Fields set by setExprFields; needs OpenFOAM and ParaView's Python modules.
    /usr/bin/python3 tests/cases/test_pump_channel_budget.py [-v]
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "python", "fsi", "pump_channel_budget.py")
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from fsi.foam_case import OPENFOAM_ENVIRONMENT  # noqa: E402

OMEGA, W0, C = 20.0, 2.0, 3.0       # rad/s, m/s, m^2/s^2
R2, B2 = 0.09, 0.05                 # m: the channel's radius and width in pump.yaml
HEAD = """FoamFile { version 2.0; format ascii; class %s; object %s; }
"""
BLOCK = HEAD % ("dictionary", "blockMeshDict") + """convertToMeters 1;
vertices ((-0.1 -0.1 0) (0.1 -0.1 0) (0.1 0.1 0) (-0.1 0.1 0) (-0.1 -0.1 0.05) (0.1 -0.1 0.05) (0.1 0.1 0.05) (-0.1 0.1 0.05));
blocks (hex (0 1 2 3 4 5 6 7) (40 40 5) simpleGrading (1 1 1));
boundary ( walls { type wall; faces ((0 3 2 1) (4 5 6 7) (0 1 5 4) (2 3 7 6) (0 4 7 3) (1 2 6 5)); } );
"""
CONTROL = HEAD % ("dictionary", "controlDict") + """application pimpleFoam; startFrom latestTime; startTime 0;
stopAt endTime; endTime 1; deltaT 1; writeControl timeStep; writeInterval 1;
"""
SCHEMES = HEAD % ("dictionary", "fvSchemes") + """ddtSchemes { default Euler; } gradSchemes { default Gauss linear; }
divSchemes { default none; } laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; } snGradSchemes { default corrected; }
"""
SOLUTION = HEAD % ("dictionary", "fvSolution") + "solvers {}\n"
DYNAMIC = HEAD % ("dictionary", "dynamicMeshDict") + """dynamicFvMesh dynamicMotionSolverFvMesh;
motionSolver solidBody; cellZone rotor; solidBodyMotionFunction rotatingMotion;
origin (0 0 0);
axis (0 0 1);
omega %r;   // rad/s
""" % OMEGA
FIELD = HEAD + """dimensions %s;
internalField uniform %s;
boundaryField { walls { type %s; %s } }
"""
EXPRESSIONS = HEAD % ("dictionary", "setExprFieldsDict") + """expressions
(
    U { field U; dimensions [0 1 -1 0 0 0 0];
        expression "vector(-%(om)r*pos().y(), %(om)r*pos().x(), 0) + %(w0)r*vector(-pos().y(), pos().x(), 0)/max(sqrt(sqr(pos().x()) + sqr(pos().y())), 1e-9)"; }
    p { field p; dimensions [0 2 -2 0 0 0 0];
        expression "0.5*sqr(%(om)r)*(sqr(pos().x()) + sqr(pos().y())) + %(c)r"; }
);
""" % {"om": OMEGA, "w0": W0, "c": C}


class ChannelBudget(unittest.TestCase):
    def setUp(self):
        for tool in ("blockMesh", "setExprFields"):
            if shutil.which(tool) is None:
                self.skipTest("OpenFOAM (%s) not installed" % tool)
        try:
            import paraview.simple  # noqa: F401
        except ImportError:
            self.skipTest("ParaView's Python modules not installed")
        self.dir = tempfile.mkdtemp(prefix="channel-budget-test-")
        case = self.case = os.path.join(self.dir, "openfoam")
        files = {"system/blockMeshDict": BLOCK, "system/controlDict": CONTROL, "system/fvSchemes": SCHEMES,
                 "system/fvSolution": SOLUTION, "system/setExprFieldsDict": EXPRESSIONS,
                 "constant/dynamicMeshDict": DYNAMIC,
                 "0/U": FIELD % ("volVectorField", "U", "[0 1 -1 0 0 0 0]", "(0 0 0)", "fixedValue", "value uniform (0 0 0);"),
                 "0/p": FIELD % ("volScalarField", "p", "[0 2 -2 0 0 0 0]", "0", "zeroGradient", ""),
                 "case.foam": ""}
        for name, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(case, name)), exist_ok=True)
            with open(os.path.join(case, name), "w") as f:
                f.write(text)
        env = dict(os.environ, **OPENFOAM_ENVIRONMENT)
        for command in (["blockMesh"], ["setExprFields", "-time", "0"]):
            done = subprocess.run(command + ["-case", case], env=env, stdin=subprocess.DEVNULL,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            self.assertEqual(done.returncode, 0, done.stdout[-3000:])
        shutil.copytree(os.path.join(case, "0"), os.path.join(case, "0.01"))   # a time after 0
        with open(os.path.join(self.dir, "pump.yaml"), "w") as f:
            f.write("impeller: {outer_diameter_m: %r, outlet_width_m: %r}\n" % (2 * R2, B2))

    def tearDown(self):
        if hasattr(self, "dir"):
            shutil.rmtree(self.dir, ignore_errors=True)

    def test_a_uniform_relative_swirl(self):
        out = os.path.join(self.dir, "budget")
        done = subprocess.run([sys.executable, SCRIPT, self.case, os.path.join(self.dir, "pump.yaml"), "--step", "45",
                               "-o", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.assertEqual(done.returncode, 0, done.stdout[-3000:])
        with open(out + ".csv") as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        self.assertEqual([float(r["theta_deg"]) for r in rows], [0, 45, 90, 135, 180, 225, 270, 315])
        area = (R2 - 5e-4) * (B2 - 1e-3)          # the cut: r < R2 - 0.5 mm, 0.5 mm < z < b2 - 0.5 mm
        for row in rows:
            self.assertAlmostEqual(float(row["net_flow_m3_per_s"]) / (W0 * area), 1.0, delta=0.06)   # cells of 5 mm
            self.assertEqual(float(row["backward_flow_m3_per_s"]), 0.0)
            # cell values against the blade speed at the slice's faces: (OMEGA r)^2 errs by
            # OMEGA^2 r dr at most, 0.9e-3 m at r = R2 and dr = 2.5 mm
            self.assertAlmostEqual(float(row["rothalpy_head_m"]), (C + 0.5 * W0 ** 2) / 9.81, delta=0.005)
        self.assertTrue(os.path.isfile(out + ".png"))
        self.assertTrue(os.path.isfile(out + "_midplane.png"))

    def test_the_midplane_in_the_impellers_frame(self):
        """The mid-plane map's cells (all inside R2, turned into the impeller's frame) carry the
        relative swirl W0 along +theta and the uniform rothalpy."""
        import numpy as np
        from fsi import pump_channel_budget
        reader, t = pump_channel_budget.open_case(self.case)
        xy, w, rothalpy = pump_channel_budget.midplane(reader, t, OMEGA, R2, 0.5 * B2)
        radius = np.hypot(xy[:, 0], xy[:, 1])
        self.assertGreater(len(radius), 200)
        self.assertLess(radius.max(), R2)
        theta_hat = np.column_stack([-xy[:, 1], xy[:, 0]]) / radius[:, None]
        along = (w * theta_hat).sum(axis=1)
        # the frame turned back by OMEGA t = 0.2 rad keeps an axisymmetric field axisymmetric; the
        # plane through the cells' centres, untriangulated, gives their own centres: exact but for
        # ParaView's single precision (3e-6 m/s)
        np.testing.assert_allclose(along, W0, atol=1e-5)
        np.testing.assert_allclose(np.hypot(w[:, 0], w[:, 1]), W0, atol=1e-5)
        np.testing.assert_allclose(rothalpy, (C + 0.5 * W0 ** 2) / 9.81, atol=1e-5)


if __name__ == "__main__":
    unittest.main()
