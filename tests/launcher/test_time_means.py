#!/usr/bin/python3
"""Checks of python/fsi/time_means.py: a revolution's time mean of a trace sampled at a time step
that does not divide the period (166.67 steps a revolution, as in the pump) under a
once-per-revolution pulsation of 30 %, against the exact mean; and the operating point's
per-revolution series built on it (pump_point.revolution_series).
    /usr/bin/python3 tests/launcher/test_time_means.py
"""
import math
import os
import sys
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from fsi.pump_point import revolution_series  # noqa: E402
from fsi.time_means import window_mean  # noqa: E402

P = 2 * math.pi / 150.8        # s, one revolution at 1440 rpm
DT = P / 166.67                # s, the pump's step
MEAN, AMPLITUDE = 10.0, 3.0    # a 30 % pulsation


def trace(phase=0.3):
    t = np.arange(1, 2000) * DT
    return t, MEAN + AMPLITUDE * np.sin(2 * math.pi * t / P + phase)


class WindowMean(unittest.TestCase):
    def test_revolution_means_are_the_exact_mean(self):
        """Each whole revolution's time mean is the trace's mean within 1e-5 relative; the mean
        of the samples inside (166 and 167 in turn) swings 30 times more (3.6e-4 relative)."""
        t, y = trace()
        for k in range(1, 10):
            lo, hi = k * P, (k + 1) * P
            self.assertAlmostEqual(window_mean(t, y, lo, hi) / MEAN, 1.0, delta=1e-5)
        samples = [np.mean(y[(t > k * P) & (t <= (k + 1) * P)]) for k in range(1, 10)]
        self.assertGreater(max(abs(s / MEAN - 1.0) for s in samples), 1e-4)

    def test_constant_and_partial_steps(self):
        """A constant's mean is itself over any window, including windows that cut steps."""
        t = np.arange(1, 50) * DT
        self.assertAlmostEqual(window_mean(t, np.full_like(t, 4.5), 2.3 * DT, 17.8 * DT), 4.5, places=12)
        # a step in the trace: half a step of 1 and the rest 0 over [t0 - dt/2, t0 + 2 dt]
        y = np.where(t <= 10 * DT + 1e-12, 1.0, 0.0)
        self.assertAlmostEqual(window_mean(t, y, 9.5 * DT, 12.0 * DT), 0.5 / 2.5, places=12)

    def test_revolution_series(self):
        """pump_point's per-revolution series holds the time means (the head's drift rule reads it)."""
        t, y = trace(phase=1.1)
        series = revolution_series(t, y, P, P, 8)
        self.assertEqual(len(series), 8)
        self.assertLess(max(abs(s / MEAN - 1.0) for s in series), 1e-5)


if __name__ == "__main__":
    unittest.main()
