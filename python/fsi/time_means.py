"""Time means of sampled traces (a load, a head) over windows such as one impeller revolution,
used by the pump's operating point (pump_point) and the feed's clog criterion (clog_criterion)."""

import numpy as np


def window_mean(t_s, values, lo, hi):
    """The time mean of `values` over [lo, hi], each sample standing for its step (the interval
    since the sample before it; the first for a step as long as the second's), weighted by how
    much of that step lies in the window. Not the mean of the samples inside: with a time step
    that does not divide the period (166.67 steps a revolution in the pump), windows hold 166 and
    167 samples in turn, and a once-per-revolution pulsation makes the sample mean swing from one
    revolution to the next (0.036 % for a sinusoidal 30 %, more for a spiky torque)."""
    t_s = np.asarray(t_s, float)
    starts = np.concatenate([[t_s[0] - (t_s[1] - t_s[0]) if len(t_s) > 1 else t_s[0]], t_s[:-1]])
    overlap = np.clip(np.minimum(t_s, hi) - np.maximum(starts, lo), 0.0, None)
    return float(np.sum(overlap * np.asarray(values, float)) / np.sum(overlap))
