#!/usr/bin/python3
"""python/fsi/rag_ensemble.py without running a case: the Wilson interval against its closed
form and known values, the summary's counts by outcome, and the seeded draw of releases (every rag point inside the sump with
two collision distances to spare, upright, reproducible for a seed and different for another).

    /usr/bin/python3 tests/cases/test_rag_ensemble.py -v
"""

import math
import os
import random
import unittest

import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
from fsi import rag_ensemble  # noqa: E402

CASE = os.path.join(HERE, "..", "..", "cases", "rag-in-pump")


class WilsonInterval(unittest.TestCase):
    def test_known_values(self):
        # 0 of 8: [0, z^2 / (n + z^2)] = [0, 0.3244]; 8 of 8 its mirror; 4 of 8 symmetric about 1/2.
        lo, hi = rag_ensemble.wilson_interval(0, 8)
        self.assertEqual(lo, 0.0)
        self.assertAlmostEqual(hi, 1.96 ** 2 / (8 + 1.96 ** 2), places=12)
        lo8, hi8 = rag_ensemble.wilson_interval(8, 8)
        self.assertAlmostEqual(lo8, 1 - hi, places=12)
        self.assertEqual(hi8, 1.0)
        lo4, hi4 = rag_ensemble.wilson_interval(4, 8)
        self.assertAlmostEqual(lo4 + hi4, 1.0, places=12)
        self.assertAlmostEqual(lo4, 0.2152, places=4)

    def test_half_width_at_one_half_and_its_one_over_root_n_limit(self):
        z = 1.96
        for n in (8, 16, 64, 1024):
            lo, hi = rag_ensemble.wilson_interval(n // 2, n)
            half = z * math.sqrt(0.25 / n + z * z / (4 * n * n)) / (1 + z * z / n)
            self.assertAlmostEqual(0.5 * (hi - lo), half, places=12)
        lo, hi = rag_ensemble.wilson_interval(512, 1024)
        self.assertAlmostEqual(0.5 * (hi - lo), z * 0.5 / math.sqrt(1024), delta=0.002)  # the normal limit


class Summary(unittest.TestCase):
    def test_a_rag_out_after_the_rule_is_passed_late_and_decided_not_hung_up(self):
        outcomes = ["passed", "passed", "passed_late", "hung_up", "running"]
        members = []
        for k, outcome in enumerate(outcomes + [None]):
            m = rag_ensemble.Member(k, "/nonexistent", 0.021)
            m.state = "failed" if outcome is None else "done"
            m.metrics = None if outcome is None else {"outcome": outcome}
            members.append(m)
        s = rag_ensemble.summarise(members, 1.0)
        self.assertEqual((s["runs"], s["runs_with_metrics"], s["failed"]), (6, 5, 1))
        self.assertEqual((s["passed"], s["passed_late"], s["hung_up"], s["still_running_at_end"]), (2, 1, 1, 1))
        self.assertEqual(s["runs_decided"], 4)
        self.assertAlmostEqual(s["p_hang_up"], 0.25, delta=1e-15)
        self.assertEqual(s["p_hang_up_95ci"], list(rag_ensemble.wilson_interval(1, 4)))


class Releases(unittest.TestCase):
    def setUp(self):
        with open(os.path.join(CASE, "pump.yaml")) as f:
            self.design = yaml.safe_load(f)
        with open(os.path.join(CASE, "case.yaml")) as f:
            self.rag = yaml.safe_load(f)["structures"][0]
        inlet = self.design["inlet"]
        self.radius = 0.5 * inlet["sump_diameter_m"]
        b2, b3 = self.design["impeller"]["outlet_width_m"], self.design["volute"]["base_width_m"]
        self.floor = 0.5 * (b2 - b3) - inlet["suction_pipe_length_m"] - inlet["sump_height_m"]

    def points(self, rag):
        o, e1, e2 = (np.array(rag[k], float) for k in ("origin_m", "s1_direction", "s2_direction"))
        (a, b), (n1, n2) = rag["size_m"], rag["n_points"]
        return np.array([o + a * i / (n1 - 1) * e1 + b * j / (n2 - 1) * e2 for i in range(n1) for j in range(n2)])

    def test_every_point_is_in_the_sump_with_room_to_spare_and_the_rag_upright(self):
        rng = random.Random(7)
        d_c = 0.004
        reached_pipe = False
        for k in range(200):
            size = (0.1, 0.1) if k % 2 else (0.15, 0.05)
            rag, release = rag_ensemble.draw_release(rng, size, self.rag, self.design, d_c)
            p = self.points(rag)
            self.assertLessEqual(np.hypot(p[:, 0], p[:, 1]).max(), self.radius - 2 * d_c + 1e-12)
            # the part standing in the suction pipe (above the sump's roof) inside the pipe's wall
            in_pipe = p[:, 2] > self.floor + self.design["inlet"]["sump_height_m"] - 2 * d_c
            if np.any(in_pipe):
                pipe = 0.5 * self.design["inlet"]["suction_pipe_diameter_m"]
                self.assertLessEqual(np.hypot(p[in_pipe, 0], p[in_pipe, 1]).max(), pipe - 2 * d_c + 1e-12)
                reached_pipe = True
            self.assertAlmostEqual(p[:, 2].min(), self.floor + 0.01, places=12)
            self.assertEqual(rag["s1_direction"], [0, 0, 1])
            self.assertEqual(rag["size_m"], list(size))
            spacing = self.rag["size_m"][0] / (self.rag["n_points"][0] - 1)
            self.assertAlmostEqual(size[0] / (rag["n_points"][0] - 1), spacing, delta=0.1 * spacing)
            self.assertAlmostEqual(math.hypot(release["centre_x_m"], release["centre_y_m"]),
                                   np.hypot(*p[:, :2].mean(0)), places=9)
        self.assertTrue(reached_pipe, "no draw reached into the suction pipe: the pipe's check was not exercised")

    def test_a_seed_reproduces_its_draw_and_another_seed_does_not(self):
        def draw(seed):
            rng = random.Random(seed)
            return [rag_ensemble.draw_release(rng, (0.15, 0.05), self.rag, self.design, 0.004)[1] for _ in range(4)]
        self.assertEqual(draw(3), draw(3))
        self.assertNotEqual(draw(3), draw(4))

    def test_a_rag_wider_than_the_sump_is_refused(self):
        with self.assertRaises(SystemExit) as e:
            rag_ensemble.draw_release(random.Random(1), (0.1, 0.3), self.rag, self.design, 0.004)
        self.assertIn("does not fit the sump", str(e.exception))


if __name__ == "__main__":
    unittest.main()
