#!/usr/bin/python3
"""python/fsi/pump_curve.py without running a case: the best point's duty (n_q, psi_G, the swirl
T / (rho Q) the volute is sized for) against hand-computed values, and the pump.yaml it writes for
that volute (the operation keys set, everything else kept, and the file the design parser reads).

    /usr/bin/python3 tests/cases/test_pump_curve.py -v
"""

import math
import os
import subprocess
import tempfile
import unittest

import yaml

from fsi import pump_curve  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DESIGN = os.path.join(HERE, "..", "..", "pump", "designs", "single-channel.yaml")


class FakePoint:
    def __init__(self, q, h, t, eta):
        self.method, self.flow_rate = "ibm", q
        self.result = {"head_m": h, "shaft_torque_n_m": t, "efficiency": eta}


class BestPoint(unittest.TestCase):
    def test_duty_and_swirl_of_the_most_efficient_point(self):
        with open(DESIGN) as f:
            design = yaml.safe_load(f)
        points = [FakePoint(0.01, 9.0, 8.0, 0.7), FakePoint(0.02, 7.5, 11.0, 0.86), FakePoint(0.03, 4.0, 12.0, 0.6)]
        (q, swirl), lines = pump_curve.best_point_duty(points, "ibm", design)
        self.assertEqual(q, 0.02)
        self.assertAlmostEqual(swirl, 11.0 / (1000.0 * 0.02), places=12)  # T / (rho Q)
        n_q = 1440.0 * math.sqrt(0.02) / 7.5 ** 0.75 * (150.8 * 30 / math.pi / 1440.0)
        self.assertIn("n_q = %.1f" % n_q, lines[0])
        u2 = 150.8 * 0.1
        self.assertIn("psi_G = 2 g H / u2^2 = %.3f" % (2 * 9.81 * 7.5 / u2 ** 2), lines[0])

    def test_the_volute_file_sets_the_operation_keys_and_keeps_the_rest(self):
        with open(DESIGN) as f:
            text = f.read()
        edited = pump_curve.with_operation(text, {"design_flow_rate_m3_per_s": "0.021",
                                                  "design_swirl_m2_per_s": "0.55"})
        before, after = yaml.safe_load(text), yaml.safe_load(edited)
        self.assertEqual(after["operation"]["design_flow_rate_m3_per_s"], 0.021)
        self.assertEqual(after["operation"]["design_swirl_m2_per_s"], 0.55)
        for section in ("impeller", "volute", "inlet"):
            self.assertEqual(after[section], before[section])
        self.assertEqual(after["operation"]["rotation_rate_rad_per_s"], before["operation"]["rotation_rate_rad_per_s"])
        # fsi-pump-design reads it and sizes the volute for that swirl
        tool = os.path.join(os.environ.get("FSI_BIN_DIR", os.path.join(HERE, "..", "..", "build", "bin")),
                            "fsi-pump-design")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "pump.yaml")
            with open(path, "w") as f:
                f.write(edited)
            run = subprocess.run([tool, path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.assertEqual(run.returncode, 0, run.stdout)
        self.assertIn("c_u2 r2 = 0.55 m^2/s, operation.design_swirl_m2_per_s", run.stdout)


if __name__ == "__main__":
    unittest.main()
