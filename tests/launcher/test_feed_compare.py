#!/usr/bin/python3
"""./fsi feed-compare's refusals of bad input, before anything runs (python/fsi/feed_compare.py):
a design file that does not exist, the same design twice, flow fractions that are not positive
numbers, no seeds, and a case without a feed; each message names the option or file and what is
allowed. Its runs: tests/cluster/test_slurm.py FeedCompare (as a SLURM array, with OpenFOAM).
    /usr/bin/python3 tests/launcher/test_feed_compare.py
"""
import contextlib
import io
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))
from fsi import feed_compare  # noqa: E402

FEED = os.path.join(ROOT, "cases", "rag-feed")
TWO_BLADE = os.path.join(ROOT, "pump", "designs", "two-blade.yaml")


class StudyEta(unittest.TestCase):
    def members(self, states):
        out = []
        for k, state in enumerate(states):
            m = feed_compare.Member(feed_compare.Design(TWO_BLADE, 0), 1.0, k + 1, "/nowhere")
            m.state = state
            out.append(m)
        return out

    def test_the_remaining_members_at_the_measured_pace(self):
        ms = self.members(["done", "running", "running", "waiting", "waiting", "waiting", "done"])
        ms[0].seconds = 1500.0                       # one ran to its end in 25 min
        ms[6].finished_before = False
        ms[1].progress, ms[2].progress = 0.5, 0.25   # half and a quarter done
        # 3 waiting + 0.5 + 0.75 left = 4.25 members of 1500 s, two at a time
        self.assertAlmostEqual(feed_compare.study_eta_s(ms, 2), 4.25 * 1500 / 2, delta=1e-9)
        ms[3].finished_before = True                 # reused: nothing to run
        self.assertAlmostEqual(feed_compare.study_eta_s(ms, 2), 3.25 * 1500 / 2, delta=1e-9)

    def test_before_any_ended_the_running_ones_pace_and_nothing_in_a_precursor(self):
        ms = self.members(["running", "waiting"])
        ms[0].started, ms[0].progress = 100.0, 0.4   # 40 % after 600 s: 1500 s a member
        self.assertAlmostEqual(feed_compare.study_eta_s(ms, 1, now=700.0), 1.6 * 1500, delta=1e-9)
        ms[0].resumed_at, ms[0].progress = 0.3, 0.4   # resumed at 30 %: 10 % in 600 s
        self.assertAlmostEqual(feed_compare.study_eta_s(ms, 1, now=700.0), 1.6 * 6000, delta=1e-9)
        ms[0].phase = "precursor "
        self.assertIsNone(feed_compare.study_eta_s(ms, 1, now=700.0))


class Interrupt(unittest.TestCase):
    def test_ctrl_c_starts_no_further_member_and_waits_for_the_running_ones(self):
        """Members of 0.3 s, two at a time, six of them; Ctrl-C at 0.45 s (during the second
        pair): the running two end, none of the last two starts, and run_pool raises."""
        import signal
        import threading
        import time
        events = []
        real = feed_compare.run_member

        def fake(args, member, on_done=None):
            if feed_compare.STOP.is_set():
                return
            events.append(("start", member.seed))
            time.sleep(0.3)
            events.append(("end", member.seed))
        members = [feed_compare.Member(feed_compare.Design(TWO_BLADE, 0), 1.0, k, "/nowhere") for k in range(1, 7)]
        feed_compare.run_member = fake
        feed_compare.STOP.clear()
        timer = threading.Timer(0.45, lambda: os.kill(os.getpid(), signal.SIGINT))
        try:
            timer.start()
            with self.assertRaises(KeyboardInterrupt):
                feed_compare.run_pool(None, members[:2], [], 2, None)   # firsts only: no precursor copies
                feed_compare.run_pool(None, members[2:], [], 2, None)
        finally:
            timer.cancel()
            feed_compare.run_member = real
            stopped = feed_compare.STOP.is_set()
            feed_compare.STOP.clear()
        self.assertTrue(stopped)
        started = sorted(seed for what, seed in events if what == "start")
        ended = sorted(seed for what, seed in events if what == "end")
        self.assertEqual(started, [1, 2, 3, 4])
        self.assertEqual(ended, started)   # the running ones were waited for


class Refusals(unittest.TestCase):
    def refused(self, argv, *words):
        stderr = io.StringIO()
        with contextlib.redirect_stderr(stderr), self.assertRaises(SystemExit) as raised:
            feed_compare.parse_args(["--bin-dir", "bin"] + argv + [FEED])
        text = stderr.getvalue() + str(raised.exception.code)
        for word in words:
            self.assertIn(word, text)

    def test_bad_options_are_refused_naming_them(self):
        self.refused(["--designs", "nowhere.yaml," + TWO_BLADE], "--designs", "nowhere.yaml", "no such file")
        self.refused(["--designs", TWO_BLADE + "," + TWO_BLADE], "the same file")
        self.refused(["--designs", TWO_BLADE], "two pump.yaml files")
        self.refused(["--flow-fractions", "1,x"], "--flow-fractions", "1,0.36")
        self.refused(["--flow-fractions", "1,-0.36"], "each above 0")
        self.refused(["--seeds", "0"], "--seeds 0", "at least 1")
        self.refused(["--flow-fractions", "1,1"], "share a folder", "q1.00, q1.00")
        self.refused(["--flow-fractions", "0.356,0.36"], "share a folder", "q0.36, q0.36")
        self.refused(["--rags", "-2"], "--rags -2", "at least 0")
        self.refused(["--jobs", "-1"], "--jobs -1")
        self.refused(["--end-time", "-0.5"], "--end-time -0.5")

    def test_the_defaults_are_the_feed_s_pump_against_the_two_blade_design(self):
        args = feed_compare.parse_args(["--bin-dir", "bin", FEED])
        self.assertEqual([d.name for d in args.designs], ["A-rag-in-pump", "B-two-blade"])
        self.assertEqual(args.fractions, [1.0, 0.36])

    def test_a_case_without_a_feed_is_refused(self):
        with self.assertRaises(SystemExit) as raised:
            feed_compare.case_inputs(os.path.join(ROOT, "cases", "rag-in-pump"))
        self.assertIn("no feed section", str(raised.exception.code))


if __name__ == "__main__":
    unittest.main()
