#!/usr/bin/python3
"""Checks of python/fsi/feed_report.py's parts that need no run (issue 33): each rag's outcome
by the residence rule, the rags in the scene and retained at given times, a grid's area (the
rag's mass), a fed rag's kind from its name, and the refusal of a name that is not the feed's.
The whole report on a real run: tests/cases/test_cases.py RagFeed.
    /usr/bin/python3 tests/launcher/test_feed_report.py
"""
import os
import sys
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from fsi.feed_report import (FeedError, grid_area, in_scene_counts, kind_of, outcomes,  # noqa: E402
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


if __name__ == "__main__":
    unittest.main()
