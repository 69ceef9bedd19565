#!/usr/bin/python3
"""Checks of python/fsi/feed_report.py's parts that need no run (issue 33): each rag's outcome
by the residence rule, the rags in the scene and retained at given times, a grid's area (the
rag's mass), a fed rag's kind from its name, and the refusal of a name that is not the feed's.
The whole report on a real run: tests/cases/test_cases.py RagFeed.
    /usr/bin/python3 tests/launcher/test_feed_report.py
"""
import math
import os
import sys
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from fsi.feed_report import (FeedError, entries, grid_area, in_scene_counts, kind_of, outcomes, sump_top_axial,  # noqa: E402
                             suction_pipe_radius, sump_or_suction)

P = 0.04      # s, a revolution
RULE = 10 * P  # the residence rule


def rag(release, exit_=None):
    return {"name": "rag", "release_time_s": release, "exit_time_s": exit_}


class FeedReport(unittest.TestCase):
    def test_outcomes_follow_the_residence_rule(self):
        rags = outcomes([rag(0.0, 0.2), rag(0.1, 0.9), rag(0.2), rag(1.0), rag(2.5)], end_time_s=1.2,
                        residence_s=RULE)
        self.assertEqual([r["outcome"] for r in rags], ["passed", "passed_late", "retained", "in_pump", "waiting"])
        self.assertEqual([round(r["time_in_scene_s"], 12) for r in rags], [0.2, 0.8, 1.0, 0.2, 0.0])
        # Exactly at the rule: passed when it left then, retained when still in then.
        torn = outcomes([dict(rag(0.0, 0.1), exit_reason="torn")], end_time_s=1.2, residence_s=RULE)
        self.assertEqual(torn[0]["outcome"], "torn")
        edge = outcomes([rag(0.0, RULE), rag(0.8)], end_time_s=0.8 + RULE, residence_s=RULE)
        self.assertEqual([r["outcome"] for r in edge], ["passed", "retained"])

    def test_rags_in_the_scene_and_retained_at_given_times(self):
        rags = [rag(0.0, 0.2), rag(0.1), rag(0.3)]
        inside, held = in_scene_counts(rags, [0.05, 0.15, 0.25, 0.35, 0.55, 0.75], RULE)
        self.assertEqual(list(inside), [1, 2, 1, 2, 2, 2])
        self.assertEqual(list(held), [0, 0, 0, 0, 1, 2])   # rag 2 from 0.5 s, rag 3 from 0.7 s
        # A rag is retained from the instant release + rule itself, as the criterion counts it.
        _, at_rule = in_scene_counts([rag(0.0)], [RULE - 1e-6, RULE], RULE)
        self.assertEqual(list(at_rule), [0, 1])
        # A torn rag leaves the scene at its tear but stays caught for the retained count.
        torn = dict(rag(0.0, 0.1), exit_reason="torn")
        inside, held = in_scene_counts([torn], [0.05, 0.15, RULE + 0.01], RULE)
        self.assertEqual(list(inside), [1, 0, 0])
        self.assertEqual(list(held), [0, 0, 1])

    def test_a_grid_s_area_is_its_rectangle_s(self):
        s1, s2 = np.meshgrid(np.linspace(0, 0.15, 16), np.linspace(0, 0.05, 6), indexing="ij")
        flat = np.stack([s1, s2, np.zeros_like(s1)], axis=-1)
        self.assertAlmostEqual(grid_area(flat), 0.0075, delta=1e-15)
        turned = flat @ np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]], float)   # upright, anywhere
        self.assertAlmostEqual(grid_area(turned + 0.3), 0.0075, delta=1e-15)

    def test_a_fed_rag_s_kind_is_its_name_without_the_index(self):
        kinds = [{"name": "rag", "size_m": [0.15, 0.05]}, {"name": "square"}, {"model": "membrane"}]
        self.assertIs(kind_of("rag07", kinds), kinds[0])
        self.assertIs(kind_of("square12", kinds), kinds[1])
        with self.assertRaises(FeedError):
            kind_of("wipe01", kinds[:2])


class AxialGeometry:
    """The parts of rag_metrics.PumpGeometry the sump rule reads: the axis z, the casing's regions."""

    def __init__(self, suction_wall):
        self.casing = {"suction_wall": suction_wall}

    @staticmethod
    def radius(x):
        x = np.asarray(x, float)
        return np.hypot(x[..., 0], x[..., 1])

    @staticmethod
    def axial(x):   # up: toward the impeller, +z
        return np.asarray(x, float)[..., 2]


def ring(radius, z):
    a = np.linspace(0, 2 * np.pi, 9)[:-1]
    return np.stack([radius * np.cos(a), radius * np.sin(a), np.full_like(a, z)], axis=1)


class Sump(unittest.TestCase):
    def test_a_rag_at_the_suction_wall_outside_the_pipe_is_in_the_sump(self):
        # A pipe of radius 0.05 m over a sump of 0.1 m (rag-in-pump's): triangles of both walls.
        pipe, sump = ring(0.05, -0.05), ring(0.1, -0.2)
        walls = np.stack([pipe[:3], pipe[3:6], sump[:3], sump[3:6]])
        g = AxialGeometry(walls)
        self.assertAlmostEqual(suction_pipe_radius(g), 0.05, delta=1e-15)
        in_sump = ring(0.08, -0.2)
        in_pipe = ring(0.03, -0.05)
        self.assertEqual(sump_or_suction("suction", in_sump, g, 0.05), "sump")
        self.assertEqual(sump_or_suction("suction", in_pipe, g, 0.05), "suction")
        self.assertEqual(sump_or_suction("leading_edge", in_sump, g, 0.05), "leading_edge")
        # A pipe without a sump: no radius, no sump.
        self.assertIsNone(suction_pipe_radius(AxialGeometry(np.stack([pipe[:3], pipe[3:6]]))))

    def test_a_rag_is_in_the_pump_from_its_entry_and_not_when_back_in_the_sump(self):
        # The sump's walls reach z = -0.11 (its top); the pipe above it. A rag of 4 points whose
        # median rises above -0.11 at 0.2 s, falls back at 0.5 s, rises again at 0.7 s and falls
        # back for good at 0.9 s; one that never rises; one that rises and leaves at 0.6 s.
        pipe, sump = ring(0.05, -0.05), ring(0.1, -0.11)
        g = AxialGeometry(np.stack([pipe[:3], pipe[3:6], sump[:3], sump[3:6], ring(0.1, -0.26)[:3]]))
        self.assertAlmostEqual(sump_top_axial(g, suction_pipe_radius(g)), -0.11, delta=1e-15)
        t = np.arange(0, 1.05, 0.1)

        def rag_at(heights):   # 4 points: two at the height, one 1 cm over, one 20 cm under
            return np.array([[[0, 0, h], [0.01, 0, h], [0, 0, h + 0.01], [0, 0, h - 0.2]] for h in heights])
        up_down = np.where((t >= 0.2 - 1e-9) & (t < 0.5 - 1e-9) | (t >= 0.7 - 1e-9) & (t < 0.9 - 1e-9), -0.05, -0.2)
        positions = {"rag01": rag_at(up_down), "square02": rag_at(np.full_like(t, -0.2)),
                     "rag03": rag_at(np.where(t >= 0.3 - 1e-9, -0.05, -0.2))}
        rags = [dict(rag(0.0), name="rag01"), dict(rag(0.1), name="square02"), dict(rag(0.1, 0.6), name="rag03")]
        entries(rags, lambda name: (t, positions[name], None), g)
        self.assertEqual(rags[0]["entry_time_s"], t[2])
        self.assertEqual(rags[0]["sump_intervals"], [(t[5], t[7]), (t[9], math.inf)])
        self.assertIsNone(rags[1]["entry_time_s"])
        self.assertEqual((rags[2]["entry_time_s"], rags[2]["sump_intervals"]), (t[3], []))
        outcomes(rags, end_time_s=1.0, residence_s=0.25)
        self.assertEqual([r["outcome"] for r in rags], ["in_sump", "in_sump", "passed_late"])   # 0.3 s > 0.25
        self.assertAlmostEqual(rags[0]["time_in_pump_s"], 0.3 + 0.2, delta=1e-12)
        self.assertAlmostEqual(rags[2]["time_in_pump_s"], 0.3, delta=1e-12)
        # Retained (in the pump for 0.25 s since its entry, and there): rag01 at 0.45 s and from
        # 0.7 to 0.9 s, not while back in the sump.
        _, held = in_scene_counts(rags, [0.4, 0.45, 0.6, 0.75, 0.95], 0.25)
        self.assertEqual(list(held), [0, 1, 0, 1, 0])
        # Without a sump every rag is in the pump from its release.
        plain = [dict(rag(0.0), name="rag01")]
        entries(plain, lambda name: (t, positions[name], None), AxialGeometry(np.stack([pipe[:3], pipe[3:6]])))
        self.assertEqual((plain[0]["entry_time_s"], plain[0]["sump_intervals"]), (0.0, []))


if __name__ == "__main__":
    unittest.main()
