#!/usr/bin/python3
"""cases/centrifugal-pump/make_ami_case.py's fine-blade pair without meshing: the blade's STL holds
exactly the impeller's blade_* solids, and the AMI and penalized snappyHexMeshDicts refine the same
band round it to the same level (issue 30's fair comparison: the same cells in both methods); every
committed case whose cells turn, in both methods, integrates the energy flux out of its rotor and
samples its stations every STATION_INTERVAL steps.

    /usr/bin/python3 tests/cases/test_make_ami_case.py -v
"""

import os
import re
import sys
import tempfile
import unittest

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "cases", "centrifugal-pump"))
import make_ami_case  # noqa: E402


def facet(z):
    return ("facet normal 0 0 1\nouter loop\nvertex 0 0 %g\nvertex 1 0 %g\nvertex 0 1 %g\nendloop\nendfacet\n"
            % (z, z, z))


class FineBlade(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.impeller = os.path.join(self.tmp.name, "impeller.stl")
        solids = [("blade_leading_edge", 1), ("hub", 3), ("blade_pressure_side", 2), ("shroud", 1),
                  ("blade_suction_side", 2)]
        with open(self.impeller, "w") as f:
            for k, (name, n) in enumerate(solids):
                f.write("solid %s\n%sendsolid %s\n" % (name, "".join(facet(10 * k + i) for i in range(n)), name))

    def tearDown(self):
        self.tmp.cleanup()

    def test_the_blade_stl_holds_the_blade_solids_whole(self):
        path = make_ami_case.write_blade_stl(self.impeller)
        with open(path) as f:
            text = f.read()
        self.assertEqual(re.findall(r"^solid (\S+)", text, re.M),
                         ["blade_leading_edge", "blade_pressure_side", "blade_suction_side"])
        self.assertEqual(re.findall(r"^endsolid (\S+)", text, re.M),
                         ["blade_leading_edge", "blade_pressure_side", "blade_suction_side"])
        self.assertEqual(text.count("endfacet"), 5)
        zs = sorted({float(z) for z in re.findall(r"vertex 0 0 (\S+)", text)})
        self.assertEqual(zs, [0.0, 20.0, 21.0, 40.0, 41.0])   # the blade's facets, none of the discs'
        mtime = os.stat(path).st_mtime_ns
        make_ami_case.write_blade_stl(self.impeller)           # unchanged: not rewritten (the mesh cache)
        self.assertEqual(os.stat(path).st_mtime_ns, mtime)

    def test_an_impeller_without_a_blade_is_refused(self):
        with open(self.impeller, "w") as f:
            f.write("solid hub\n%sendsolid hub\n" % facet(0))
        with self.assertRaises(SystemExit) as caught:
            make_ami_case.write_blade_stl(self.impeller)
        self.assertIn("no blade_* solid", str(caught.exception))

    def test_both_methods_refine_the_same_band(self):
        _base, cell, _dt = make_ami_case.FINE_BLADE["coarse-fine-blade"]
        self.assertLessEqual(cell, 0.008 / 3)                   # >= 3 cells across the 8 mm blade
        with open(os.path.join(HERE, "..", "..", "pump", "designs", "thin-blade.yaml")) as f:
            design = yaml.safe_load(f)
        casing = os.path.join(self.tmp.name, "casing.stl")
        with open(casing, "w") as f:
            f.write("solid inlet\n%sendsolid inlet\nsolid outlet\n%sendsolid outlet\n" % (facet(-1), facet(1)))
        blade_lines = []
        for penalized in (False, True):
            text, _rotor, _gap = make_ami_case.snappy_dict(design, 0.008, casing, self.impeller, penalized=penalized,
                                                           blade_cell=cell)
            self.assertIn("impeller-blade.stl", text)
            blade_lines.append(re.findall(r"^\s*blade \{.*$", text, re.M))
            plain, _rotor, _gap = make_ami_case.snappy_dict(design, 0.008, casing, self.impeller, penalized=penalized)
            self.assertNotIn("impeller-blade.stl", plain)
        self.assertEqual(len(blade_lines[0]), 1)
        self.assertEqual(blade_lines[0], blade_lines[1])
        self.assertIn("levels ((0.004 2))", blade_lines[0][0])   # 8 mm / 2^2 = 2 mm


class TurningCases(unittest.TestCase):
    def test_cases_whose_cells_turn_integrate_the_rotor_energy_flux_and_sample_the_stations_less_often(self):
        case = os.path.join(HERE, "..", "..", "cases", "centrifugal-pump")
        turning = []
        for name in sorted(os.listdir(case)):
            folder = os.path.join(case, name)
            if not (name.startswith("openfoam-") and os.path.isdir(folder)):
                continue
            with open(os.path.join(folder, "system", "controlDict")) as f:
                control = f.read()
            budget = re.search(r"rotorEnergyFlux\s*\{([^}]*)\}", control)
            moving = os.path.exists(os.path.join(folder, "constant", "dynamicMeshDict"))
            # The stations: sampled (an octree of all cells each time on a moving mesh) and
            # integrated together, every STATION_INTERVAL steps where the cells turn, else every step.
            interval = make_ami_case.STATION_INTERVAL if moving else 1
            sampling = re.search(r"\n    stations\s*\{(.*?)\n    \}", control, re.S).group(1)
            self.assertRegex(sampling, r"executeInterval %d;" % interval, name)
            values = re.findall(r"\n    stationFlowRate_\w+\s*\{([^}]*)\}", control)
            self.assertEqual(len(values), 5, name)
            for v in values:
                self.assertRegex(v, r"executeInterval %d;" % interval, name)
                self.assertRegex(v, r"writeInterval\s+%d;" % interval, name)
            if moving:
                turning.append(name)
                self.assertIsNotNone(budget, name)
                self.assertRegex(budget.group(1), r"name\s+AMI1;")       # the rotor's side of the pair
                self.assertRegex(budget.group(1), r"weightField\s+phi;")
                self.assertRegex(budget.group(1), r"fields\s+\(totalPressure\);")
                self.assertLess(control.index("totalPressure"), budget.start())   # the field exists first
            else:
                self.assertIsNone(budget, name)
        # Both methods on each turning mesh: the AMI references and the penalized impeller turning with its cells.
        self.assertEqual(turning, ["openfoam-ami-coarse", "openfoam-ami-coarse-fine-blade", "openfoam-ami-medium",
                                   "openfoam-coarse-fine-blade-turning-mesh", "openfoam-coarse-turning-mesh"])
        for name in ("coarse-turning-mesh", "coarse-fine-blade-turning-mesh"):
            with open(os.path.join(case, "presets", name + ".yaml")) as f:
                preset = yaml.safe_load(f)
            self.assertEqual(preset["fluid"]["openfoam"]["case_directory"], "openfoam-" + name)


if __name__ == "__main__":
    unittest.main()
