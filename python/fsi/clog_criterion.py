"""The clog criterion of a rag feed: when a pump fed rags in sequence stops coping, as the test
rigs judge it (issue 33). A rig calls a pump clogged when its head falls or its shaft power rises
by a set fraction against the clean pump at the same flow and stays so for a number of
revolutions, or when it holds a number of rags; its "degree of saturation" is the most solids the
pump holds before it stops coping.

Here the same on the traces of a run, revolution by revolution:
  - each whole revolution's time mean head H_k (m) and shaft power P_k (W) (each sample weighted
    by the step it stands for, time_means.window_mean) against the clean pump's means at the same
    flow, H_clean and P_clean (a mean over whole revolutions is the phase average over them; the
    once-per-revolution pulsation of a single blade cancels);
  - a rag is retained at time t when it entered the pump at t_p <= t (past the sump, when the
    pump has one; else its release), has not left (its exit time t_e > t, or it never left) and
    has been in the pump for at least the residence rule: t - t_p >= residence_revolutions x
    the period (the rag metrics' rule, 10 revolutions), and is in the pump at t. A rag in the
    sump (before its entry, or fallen back into it) is not retained: it is not in the pump;
  - the criterion is met at the end of the first revolution that completes `held_revolutions`
    consecutive revolutions with H_k <= (1 - head_drop_fraction) H_clean, or with
    P_k >= (1 + power_rise_fraction) P_clean, or at the first instant `retained_rags` rags are
    retained, whichever comes first. The conditions not given are not checked; at least one is.
  - the degree of saturation is the largest mass (kg) and count of retained rags before the
    criterion is met (over the whole run when it is not).

Used on synthetic traces by tests/launcher/test_clog_criterion.py."""

import math
from dataclasses import dataclass, field
from typing import List, Optional, Sequence, Tuple

import numpy as np

from fsi.time_means import window_mean


KEYS = {
    "head_drop_fraction": "clogged when the revolution mean head is this fraction under the clean pump's (0 < f < 1)",
    "power_rise_fraction": "clogged when the revolution mean shaft power is this fraction over the clean pump's (f > 0)",
    "held_revolutions": "for this many consecutive revolutions (an integer >= 1; default 3)",
    "retained_rags": "clogged when this many rags are retained at once (an integer >= 1)",
    "residence_revolutions": "a rag still in the pump after this many revolutions is retained (> 0; default 10)",
}


class CriterionError(ValueError):
    """A clog criterion that cannot be evaluated: names the key, the value and what is allowed."""


@dataclass(frozen=True)
class ClogCriterion:
    head_drop_fraction: Optional[float] = None
    power_rise_fraction: Optional[float] = None
    held_revolutions: int = 3
    retained_rags: Optional[int] = None
    residence_revolutions: float = 10.0

    @classmethod
    def from_mapping(cls, mapping, where="clog_criterion"):
        """From a case's mapping (YAML), strict: an unknown key, a value of the wrong type or out
        of range, or no condition at all is refused naming `where`, the key and what is allowed."""
        if not isinstance(mapping, dict):
            raise CriterionError("%s: a mapping of %s expected, got %r" % (where, ", ".join(KEYS), mapping))
        for key in mapping:
            if key not in KEYS:
                raise CriterionError("%s.%s: unknown key (allowed: %s)" % (where, key, ", ".join(KEYS)))

        def number(key, low, high, integer=False):
            if mapping.get(key) is None:   # absent or null: not given, as the C++ reader takes it
                return None
            value = mapping[key]
            if isinstance(value, bool) or not isinstance(value, (int, float)) or (integer and value != int(value)):
                raise CriterionError("%s.%s: %r is not %s (%s)" % (where, key, value, "an integer" if integer
                                                                   else "a number", KEYS[key]))
            if not (low(value) and high(value)):
                raise CriterionError("%s.%s: %r is out of range (%s)" % (where, key, value, KEYS[key]))
            return int(value) if integer else float(value)

        args = {
            "head_drop_fraction": number("head_drop_fraction", lambda v: v > 0, lambda v: v < 1),
            "power_rise_fraction": number("power_rise_fraction", lambda v: v > 0, lambda v: True),
            "retained_rags": number("retained_rags", lambda v: v >= 1, lambda v: True, integer=True),
        }
        held = number("held_revolutions", lambda v: v >= 1, lambda v: True, integer=True)
        residence = number("residence_revolutions", lambda v: v > 0, lambda v: True)
        if held is not None:
            args["held_revolutions"] = held
        if residence is not None:
            args["residence_revolutions"] = residence
        if all(args[k] is None for k in ("head_drop_fraction", "power_rise_fraction", "retained_rags")):
            raise CriterionError("%s: no condition: give at least one of head_drop_fraction, power_rise_fraction, "
                                 "retained_rags" % where)
        return cls(**args)


@dataclass(frozen=True)
class Rag:
    """One rag of a feed: when it was released and left (None: it never left), its mass, and
    when it entered the pump (past the sump: the residence rule's clock starts then; None: at
    its release, a pump without a sump; NEVER: it never did, and is never retained)."""
    release_time_s: float
    exit_time_s: Optional[float]
    mass_kg: float
    entry_time_s: Optional[float] = None
    # After its entry, the spans [from, to) it spent back in the sump (to = NEVER: to the end).
    sump_intervals: Tuple[Tuple[float, float], ...] = ()

    def start_s(self):
        """When the residence rule's clock starts."""
        return self.release_time_s if self.entry_time_s is None else self.entry_time_s

    def in_sump(self, time_s):
        """Back in the sump at time_s (after its entry)."""
        return any(a - TIME_TOLERANCE_S <= time_s < b - TIME_TOLERANCE_S for a, b in self.sump_intervals)


NEVER = math.inf   # Rag.entry_time_s of a rag that never entered the pump


@dataclass
class Revolution:
    end_time_s: float
    head_m: float
    power_w: float
    head_change: float   # (H_k - H_clean) / H_clean
    power_change: float  # (P_k - P_clean) / P_clean
    retained: int        # rags retained at the revolution's end


@dataclass
class ClogResult:
    clogged: bool
    time_s: Optional[float]          # when the criterion was met (None: not met)
    reason: Optional[str]            # which condition: "head", "power" or "retained rags"
    rags_released: int               # released by time_s (by the run's end when not met)
    rags_retained: int               # retained at time_s (at the end when not met)
    saturation_kg: float             # the most retained mass before time_s (over the run when not met)
    saturation_rags: int             # the most retained rags before time_s
    revolutions: List[Revolution] = field(default_factory=list)


def revolution_means(t_s, values, period_s):
    """Time means of `values` over each whole revolution [k P, (k + 1) P] the samples t_s cover
    (they start within one sample spacing of its start and reach its end): (end times, means)."""
    t_s, values = np.asarray(t_s, float), np.asarray(values, float)
    spacing = float(np.median(np.diff(t_s))) if len(t_s) > 1 else period_s
    first = max(0, int(np.ceil((t_s[0] - spacing - 1e-9) / period_s)))
    n = max(0, int(np.floor((t_s[-1] + 1e-9) / period_s)) - first)
    ends = np.arange(first + 1, first + n + 1) * period_s
    return ends, np.array([window_mean(t_s, values, e - period_s, e) for e in ends])


TIME_TOLERANCE_S = 1e-9   # release + residence - release is residence only to round-off


def retained_at(rags: Sequence[Rag], time_s, residence_s):
    """The rags retained at time_s: in the pump (entered), not left, in for residence_s or
    longer since they entered (to TIME_TOLERANCE_S: a rag becomes retained at the event entry +
    residence itself). A rag still in the sump is not retained."""
    return [r for r in rags if r.start_s() <= time_s and (r.exit_time_s is None or r.exit_time_s > time_s)
            and time_s - r.start_s() >= residence_s - TIME_TOLERANCE_S and not r.in_sump(time_s)]


def evaluate(criterion: ClogCriterion, period_s, t_s, head_m, power_w, clean_head_m, clean_power_w,
             rags: Sequence[Rag]):
    """The criterion on a run's traces (head and shaft power sampled at t_s, SI) against the
    clean pump's revolution means: a ClogResult with each revolution's means and changes."""
    if not (clean_head_m > 0 and clean_power_w > 0):
        raise CriterionError("the clean pump's head and power must be positive to compare with (got %r m, %r W)"
                             % (clean_head_m, clean_power_w))
    residence_s = criterion.residence_revolutions * period_s
    ends, heads = revolution_means(t_s, head_m, period_s)
    _, powers = revolution_means(t_s, power_w, period_s)
    revolutions = [Revolution(e, h, p, h / clean_head_m - 1.0, p / clean_power_w - 1.0,
                              len(retained_at(rags, e, residence_s))) for e, h, p in zip(ends, heads, powers)]

    met = []  # (time, reason) of each condition's first meeting
    for name, off in (("head", lambda r: criterion.head_drop_fraction is not None
                       and r.head_change <= -criterion.head_drop_fraction),
                      ("power", lambda r: criterion.power_rise_fraction is not None
                       and r.power_change >= criterion.power_rise_fraction)):
        run = 0
        for r in revolutions:
            run = run + 1 if off(r) else 0
            if run >= criterion.held_revolutions:
                met.append((r.end_time_s, name))
                break
    # Retained counts change only when a rag passes its residence limit or leaves.
    events = sorted({r.start_s() + residence_s for r in rags if r.start_s() < NEVER}
                    | {r.exit_time_s for r in rags if r.exit_time_s is not None}
                    | {b for r in rags for _, b in r.sump_intervals if b < NEVER})
    t_end = float(np.asarray(t_s, float)[-1])
    events = [e for e in events if e <= t_end]
    if criterion.retained_rags is not None:
        for e in events:
            if len(retained_at(rags, e, residence_s)) >= criterion.retained_rags:
                met.append((e, "retained rags"))
                break

    time_s, reason = min(met) if met else (None, None)
    horizon = time_s if time_s is not None else t_end
    held = [retained_at(rags, e, residence_s) for e in events if e <= horizon] + [retained_at(rags, horizon, residence_s)]
    return ClogResult(
        clogged=time_s is not None, time_s=time_s, reason=reason,
        rags_released=sum(1 for r in rags if r.release_time_s <= horizon),
        rags_retained=len(retained_at(rags, horizon, residence_s)),
        saturation_kg=max((sum(r.mass_kg for r in h) for h in held), default=0.0),
        saturation_rags=max((len(h) for h in held), default=0),
        revolutions=revolutions)
