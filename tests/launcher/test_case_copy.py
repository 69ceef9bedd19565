#!/usr/bin/python3
"""A study's results folder given inside the case it studies (`./fsi pump-curve -o CASE/curve
CASE`): the points' copies of the case leave it behind (they once copied it into themselves, one
point inside the last, until the disk filled), and the case's fingerprint ignores the results
written there (else every point would rerun on every call). python/fsi/case_copy.py through
python/fsi/pump_curve.py's copy_case and case_fingerprint, which rag-ensemble uses too.
    /usr/bin/python3 tests/launcher/test_case_copy.py
"""
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from fsi import case_copy  # noqa: E402
from fsi import pump_curve  # noqa: E402


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


class StudyInsideTheCase(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.case = os.path.join(self.tmp.name, "case")
        write(os.path.join(self.case, "case.yaml"), "run: {end_time_s: 1}\n")
        write(os.path.join(self.case, "pump.yaml"), "impeller: {}\n")
        write(os.path.join(self.case, "output", "old.csv"), "1\n")
        write(os.path.join(self.case, "geometry", "generate.log"), "took 5 s\n")
        self.out = os.path.join(self.case, "curve")          # the -o of the study

    def tearDown(self):
        self.tmp.cleanup()

    def copied(self, point):
        found = []
        for root, _, files in os.walk(point.case):
            found += [os.path.relpath(os.path.join(root, f), point.case) for f in files]
        return sorted(found)

    def test_copies_leave_the_study_behind(self):
        """Two points in turn: the second's copy holds the case's files only, not the first point."""
        first = pump_curve.Point(0.5, 0.02, self.out, "ibm")
        pump_curve.copy_case(self.case, first)
        write(os.path.join(first.folder, "forces.csv"), "t\n")
        second = pump_curve.Point(1.0, 0.02, self.out, "ibm")
        pump_curve.copy_case(self.case, second)
        self.assertEqual(self.copied(second), ["case.yaml", os.path.join("geometry", "generate.log"), "pump.yaml"])

    def test_fingerprint_ignores_the_results(self):
        """Results written into the study's folder leave the fingerprint; the case's own files move it."""
        before = pump_curve.case_fingerprint(self.case, self.out)
        write(os.path.join(self.out, "q0.50", "operating_point.yaml"), "head_m: 1\n")
        write(os.path.join(self.case, "geometry", "generate.log"), "took 6 s\n")
        self.assertEqual(pump_curve.case_fingerprint(self.case, self.out), before)
        write(os.path.join(self.case, "pump.yaml"), "impeller: {outer_diameter_m: 0.2}\n")
        self.assertNotEqual(pump_curve.case_fingerprint(self.case, self.out), before)

    def test_a_study_outside_the_case_changes_nothing(self):
        """A folder named like the study's elsewhere does not hide the case's own folder of that name."""
        os.makedirs(os.path.join(self.case, "curve"))
        write(os.path.join(self.case, "curve", "notes.txt"), "mine\n")
        outside = os.path.join(self.tmp.name, "curve")
        names = [os.path.relpath(p, self.case) for p in case_copy.case_files(self.case, [outside])]
        self.assertIn(os.path.join("curve", "notes.txt"), names)
        self.assertNotIn(os.path.join("output", "old.csv"), names)


if __name__ == "__main__":
    unittest.main()
