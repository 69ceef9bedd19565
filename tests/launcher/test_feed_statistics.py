#!/usr/bin/python3
"""Checks of python/fsi/feed_statistics.py (issue 33: which of two pump designs clogs later, with
a confidence statement) on samples whose answers are known: the pair scores of censored and
clogged runs, P(A outlasts B) for separated, equal and interleaved samples (the Mann-Whitney
count worked by hand), the bootstrap intervals (they hold the sample median, and separate for
well-separated designs), the coverage of the median's interval on draws from a known
distribution, and the sentence a designer reads.
    /usr/bin/python3 tests/launcher/test_feed_statistics.py
"""
import os
import random
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from fsi.feed_statistics import RagsToClog, compare, p_outlasts, pair_score, statement  # noqa: E402


def clogged(*counts):
    return [RagsToClog(n, False) for n in counts]


class FeedStatistics(unittest.TestCase):
    def test_pair_scores_order_clogged_runs_and_respect_censoring(self):
        self.assertEqual(pair_score(RagsToClog(12, False), RagsToClog(8, False)), 1.0)
        self.assertEqual(pair_score(RagsToClog(8, False), RagsToClog(12, False)), 0.0)
        self.assertEqual(pair_score(RagsToClog(8, False), RagsToClog(8, False)), 0.5)
        # A coped with 20 rags; B clogged at 12: A outlasts. A coped with 8 (a shorter run), B
        # clogged at 12: unknown.
        self.assertEqual(pair_score(RagsToClog(20, True), RagsToClog(12, False)), 1.0)
        self.assertEqual(pair_score(RagsToClog(8, True), RagsToClog(12, False)), 0.5)
        self.assertEqual(pair_score(RagsToClog(12, False), RagsToClog(20, True)), 0.0)
        self.assertEqual(pair_score(RagsToClog(20, True), RagsToClog(20, True)), 0.5)

    def test_p_outlasts_counts_every_pair(self):
        self.assertEqual(p_outlasts(clogged(15, 16, 17), clogged(5, 6, 7)), 1.0)
        self.assertEqual(p_outlasts(clogged(5, 6, 7), clogged(15, 16, 17)), 0.0)
        self.assertEqual(p_outlasts(clogged(9, 9), clogged(9, 9)), 0.5)
        # Interleaved, by hand: A = 3, 6, 9 against B = 4, 5, 10: 3 wins none, 6 wins two, 9 wins
        # two: 4 of 9 pairs.
        self.assertAlmostEqual(p_outlasts(clogged(3, 6, 9), clogged(4, 5, 10)), 4 / 9, delta=1e-15)

    def test_separated_designs_are_resolved_and_close_ones_are_not(self):
        far = compare(clogged(15, 16, 14, 15, 17), clogged(5, 6, 4, 5, 7))
        self.assertTrue(far.resolved)
        self.assertEqual(far.later, "A")
        self.assertEqual(far.median_a, 15)
        self.assertEqual(far.median_b, 5)
        self.assertEqual(far.p_a_outlasts_b, 1.0)
        self.assertEqual(far.p_a_outlasts_b_95, [1.0, 1.0])
        for m, ci in ((far.median_a, far.median_a_95), (far.median_b, far.median_b_95)):
            self.assertLessEqual(ci[0], m)
            self.assertGreaterEqual(ci[1], m)
        close = compare(clogged(8, 10, 12, 9), clogged(9, 11, 8, 10))
        self.assertFalse(close.resolved)
        self.assertIsNone(close.later)
        self.assertIn("Not resolved", statement(close, "thin blade", "two blades"))
        self.assertIn("thin blade lasts longer", statement(far, "thin blade", "two blades"))

    def test_censored_runs_are_counted_as_lower_bounds_and_said(self):
        c = compare([RagsToClog(20, True)] * 3, clogged(6, 7, 8))
        self.assertTrue(c.resolved)
        self.assertEqual(c.censored_a, 3)
        self.assertEqual(c.p_a_outlasts_b, 1.0)
        self.assertIn("A: no clog in any of its 3 runs (it coped with the 20 rags fed)", statement(c, "A", "B"))
        some = compare([RagsToClog(20, True)] * 2 + clogged(18, 19), clogged(6, 7, 8))
        self.assertIn("a lower bound: 2 runs did not clog", statement(some, "A", "B"))

    def test_the_medians_interval_covers_the_true_median_about_as_often_as_it_says(self):
        # Runs whose rags to clog are uniform on 1..19 (true median 10), 9 seeds a design: the
        # percentile bootstrap of a median from 9 runs is known to cover a little under its
        # nominal 95 %; over 200 designs it must cover at least 85 % of the time.
        rng = random.Random(3)
        covered = 0
        for trial in range(200):
            sample = clogged(*[rng.randint(1, 19) for _ in range(9)])
            c = compare(sample, sample, resamples=400, seed=trial)
            covered += c.median_a_95[0] <= 10 <= c.median_a_95[1]
        self.assertGreaterEqual(covered / 200, 0.85)

    def test_no_runs_is_refused(self):
        with self.assertRaises(ValueError):
            compare([], clogged(3))


if __name__ == "__main__":
    unittest.main()
