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
        c = compare([RagsToClog(20, True)] * 4, clogged(6, 7, 8, 12))
        self.assertTrue(c.resolved)
        self.assertEqual(c.censored_a, 4)
        self.assertEqual(c.p_a_outlasts_b, 1.0)
        self.assertIn("A: no clog in any of its 4 runs (it coped with the 20 rags fed)", statement(c, "A", "B"))
        some = compare([RagsToClog(20, True)] * 2 + clogged(18, 19), clogged(6, 7, 8))
        self.assertIn("a lower bound: 2 runs did not clog", statement(some, "A", "B"))

    def test_gehan_test_against_counts_by_hand(self):
        # 4 against 4, all pairs one way: 2 of the C(8, 4) = 70 relabellings are as extreme.
        c = compare(clogged(15, 16, 14, 17), clogged(5, 6, 4, 7))
        self.assertAlmostEqual(c.p_value, 2 / 70, delta=1e-12)
        self.assertTrue(c.exact)
        # 3 against 3, all pairs one way: 2 of 20, not under 0.05, and no outcome of 3 and 3 can be.
        three = compare(clogged(15, 16, 14), clogged(5, 6, 4))
        self.assertAlmostEqual(three.p_value, 0.1, delta=1e-12)
        self.assertFalse(three.resolved)
        self.assertIn("with 3 and 3 runs no outcome can reach it", statement(three, "A", "B"))
        # 4 against 4 with one of A's runs among B's: U = 14 of 16. Of the 70 arrangements of 4
        # and 4 runs, U = 16, 15, 14 in 1, 1 and 2 (the Mann-Whitney table), and as many at 0-2:
        # p = 8 / 70, not resolved, but 4 and 4 runs can be.
        mixed = compare(clogged(15, 16, 14, 5.5), clogged(5, 6, 4, 7))
        self.assertAlmostEqual(mixed.p_value, 8 / 70, delta=1e-12)
        self.assertFalse(mixed.resolved)
        self.assertIn("more seeds may tell.", statement(mixed, "A", "B"))
        # The first comparison's part load: one clog in four runs each; the six runs cut short tie.
        mostly_cut = compare([RagsToClog(20, True)] * 3 + clogged(20), [RagsToClog(20, True)] * 3 + clogged(17))
        self.assertFalse(mostly_cut.resolved)
        self.assertIn("more seeds may tell, and a longer feed: 6 of the 8 runs coped with all their rags.",
                      statement(mostly_cut, "A", "B"))
        # One run each: no outcome can reach 0.05, whatever the intervals look like.
        one = compare(clogged(12), clogged(10))
        self.assertFalse(one.resolved)
        self.assertIn("no outcome can reach it", statement(one, "A", "B"))
        # By hand: A = 3, 6, 9 against B = 4, 5, 10 is U = 4 of 9, |U - 4.5| = 0.5; of the 20
        # relabellings those with U in {4, 5} (|U - 4.5| = 0.5 or more: all of them) -> p = 1.
        self.assertAlmostEqual(compare(clogged(3, 6, 9), clogged(4, 5, 10)).p_value, 1.0, delta=1e-12)

    def test_a_cut_short_run_cannot_win_and_no_clogs_ask_for_rags(self):
        # A's runs cut short at 6 rags (censored) against B clogging at 12: every pair unknown.
        short = compare([RagsToClog(6, True)] * 5, clogged(12, 12, 13, 11, 12))
        self.assertEqual(short.p_a_outlasts_b, 0.5)
        self.assertFalse(short.resolved)
        none = compare([RagsToClog(20, True)] * 4, [RagsToClog(20, True)] * 4)
        self.assertFalse(none.resolved)
        self.assertIn("more rags can", statement(none, "A", "B"))

    def test_random_relabelling_agrees_with_the_exact_test(self):
        # 10 against 10 runs without ties: C(20, 10) = 184756 relabellings, drawn 20000 times.
        # Without ties U is the Mann-Whitney count, whose exact distribution the classic
        # recursion gives: N(m, n, u) = N(m - 1, n, u - n) + N(m, n - 1, u).
        a = clogged(3, 5, 7, 9, 11, 13, 15, 17, 19, 21)
        b = clogged(2, 4, 6, 8, 10, 12, 14, 16, 18, 20)   # U = 55 of 100
        c = compare(a, b, resamples=100)
        self.assertFalse(c.exact)
        counts = {}

        def ways(m, n, u):
            if u < 0:
                return 0
            if m == 0 or n == 0:
                return 1 if u == 0 else 0
            if (m, n, u) not in counts:
                counts[(m, n, u)] = ways(m - 1, n, u - n) + ways(m, n - 1, u)
            return counts[(m, n, u)]
        total = sum(ways(10, 10, u) for u in range(101))
        self.assertEqual(total, 184756)
        exact = sum(ways(10, 10, u) for u in range(101) if abs(u - 50) >= 5) / total
        self.assertAlmostEqual(c.p_value, exact, delta=0.01)

    def test_the_medians_interval_covers_the_true_median_about_as_often_as_it_says(self):
        # Runs whose rags to clog are uniform on 1..19 (true median 10), 9 seeds a design: the
        # percentile bootstrap of a median from 9 runs is known to cover a little under its
        # nominal 95 %; over 200 designs it must cover at least 85 % of the time.
        rng = random.Random(3)
        covered = 0
        for trial in range(200):
            sample = clogged(*[rng.randint(1, 19) for _ in range(9)])
            c = compare(sample, sample, resamples=400, seed=trial, permutations=100)
            covered += c.median_a_95[0] <= 10 <= c.median_a_95[1]
        self.assertGreaterEqual(covered / 200, 0.85)

    def test_no_runs_is_refused(self):
        with self.assertRaises(ValueError):
            compare([], clogged(3))


if __name__ == "__main__":
    unittest.main()
