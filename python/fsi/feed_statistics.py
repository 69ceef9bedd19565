"""Which of two pump designs clogs later, with a confidence statement (issue 33, section 3):
the statistics of ./fsi feed-compare over the seeds of a rag feed.

Each run of a feed gives its rags to clog: the rags released when the clog criterion was met
(feed_report.yaml: verdict.rags_released), or, when it was not met by the end, a lower bound:
the rags released by then (censored: the pump coped with all of them). Per design:

  - the median of the rags to clog over the seeds, with a 95 % interval: the 2.5th and 97.5th
    percentiles of the median over bootstrap resamples of the seeds (a censored run counts at
    its bound, so a median with censored runs in it is a lower bound, and the summary says so);
  - P(A outlasts B): the chance that a run of design A takes more rags to clog than a run of
    design B, over every pair of their runs (the Mann-Whitney statistic over nA nB): a pair
    counts 1 when A's run took more rags, 0 when fewer, 1/2 for a tie, for two censored runs, or
    when a censored bound leaves the order unknown (A's bound below B's clog); with its 95 %
    bootstrap interval (the seeds of each design resampled).

Which design lasts longer is decided by a test, not by the intervals: Gehan's generalised
Wilcoxon test, the sum of the pair scores above (U = nA nB P) against its distribution when the
design labels are exchanged among the pooled runs (every relabelling when there are at most
20,000, else 20,000 drawn at random), two-sided. A design is named only at p < 0.05; a censored
bound below the other design's clogs scores 1/2, so a cut-short run cannot win. The exact test
needs runs: with 2 seeds a design the smallest p is 0.33, with 3 it is 0.10, with 4 0.029 (all
pairs one way). When no run of either design clogged, more seeds cannot tell them apart: the
statement says to feed more rags; when most runs coped with all their rags, it asks for a longer
feed as well as more seeds.
"""

import dataclasses
import itertools
import math
import random
from typing import List, Optional, Sequence

import numpy as np

BOOTSTRAP_RESAMPLES = 2000
BOOTSTRAP_SEED = 12345   # a fixed seed: the same runs give the same intervals
SIGNIFICANCE = 0.05      # a design is named when the test's two-sided p is under this
PERMUTATIONS = 20000     # the test enumerates relabellings up to this many, else draws this many


@dataclasses.dataclass(frozen=True)
class RagsToClog:
    rags: int            # released when the criterion was met, or by the end (censored)
    censored: bool       # True: not clogged by the end; `rags` is a lower bound


def pair_score(a: RagsToClog, b: RagsToClog) -> float:
    """1 when a took more rags to clog than b, 0 when fewer, 1/2 when tied or unknown."""
    if a.censored and b.censored:
        return 0.5
    if a.censored:
        return 1.0 if a.rags >= b.rags else 0.5     # a coped with at least b's clog count
    if b.censored:
        return 0.0 if b.rags >= a.rags else 0.5
    return 1.0 if a.rags > b.rags else 0.0 if a.rags < b.rags else 0.5


def p_outlasts(a: Sequence[RagsToClog], b: Sequence[RagsToClog]) -> float:
    """P(a run of A takes more rags to clog than a run of B), over every pair."""
    if not a or not b:
        return float("nan")
    return sum(pair_score(x, y) for x in a for y in b) / (len(a) * len(b))


def median(values: Sequence[float]) -> float:
    s = sorted(values)
    n = len(s)
    if n == 0:
        return float("nan")
    return float(s[n // 2]) if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def percentile(sorted_values: Sequence[float], q: float) -> float:
    """The q-quantile (0..1) of sorted values, linear between order statistics."""
    n = len(sorted_values)
    if n == 0:
        return float("nan")
    x = q * (n - 1)
    lo = int(math.floor(x))
    hi = min(lo + 1, n - 1)
    return sorted_values[lo] + (x - lo) * (sorted_values[hi] - sorted_values[lo])


@dataclasses.dataclass
class Comparison:
    median_a: float
    median_a_95: List[float]
    median_b: float
    median_b_95: List[float]
    runs_a: int
    runs_b: int
    censored_a: int
    censored_b: int
    p_a_outlasts_b: float
    p_a_outlasts_b_95: List[float]
    p_value: float            # Gehan's test, two-sided (permutation_p_value)
    exact: bool               # every relabelling enumerated (else drawn at random)
    resolved: bool            # p_value < SIGNIFICANCE
    later: Optional[str]      # "A", "B", or None (not resolved)


def permutation_p_value(a: Sequence[RagsToClog], b: Sequence[RagsToClog], seed=BOOTSTRAP_SEED,
                        permutations=PERMUTATIONS):
    """Gehan's test: (two-sided p, exact). The statistic is U - nA nB / 2, U the sum of the pair
    scores of A's runs against B's; p is the share of relabellings of the pooled runs (nA of them
    called A) whose |statistic| is at least the observed one."""
    pooled = list(a) + list(b)
    n, na = len(pooled), len(a)
    score = np.array([[pair_score(x, y) for y in pooled] for x in pooled])
    if math.comb(n, na) <= permutations:
        chosen = np.array(list(itertools.combinations(range(n), na)), int).reshape(-1, na)
        exact = True
    else:
        rng = np.random.default_rng(seed)
        chosen = np.argsort(rng.random((permutations, n)), axis=1)[:, :na]
        exact = False
    labels = np.zeros((len(chosen), n))
    np.put_along_axis(labels, chosen, 1.0, axis=1)
    u = np.sum((labels @ score) * (1.0 - labels), axis=1)
    observed = abs(score[:na, na:].sum() - 0.5 * na * (n - na))
    return float(np.mean(np.abs(u - 0.5 * na * (n - na)) >= observed - 1e-9)), exact


def compare(a: Sequence[RagsToClog], b: Sequence[RagsToClog], resamples=BOOTSTRAP_RESAMPLES,
            seed=BOOTSTRAP_SEED, permutations=PERMUTATIONS) -> Comparison:
    """The comparison of the module's docstring. Needs at least one run of each design."""
    if not a or not b:
        raise ValueError("each design needs at least one finished run (got %d and %d)" % (len(a), len(b)))
    rng = random.Random(seed)
    medians_a, medians_b, ps = [], [], []
    for _ in range(resamples):
        ra = [a[rng.randrange(len(a))] for _ in a]
        rb = [b[rng.randrange(len(b))] for _ in b]
        medians_a.append(median([r.rags for r in ra]))
        medians_b.append(median([r.rags for r in rb]))
        ps.append(p_outlasts(ra, rb))
    medians_a.sort()
    medians_b.sort()
    ps.sort()
    ci_a = [percentile(medians_a, 0.025), percentile(medians_a, 0.975)]
    ci_b = [percentile(medians_b, 0.025), percentile(medians_b, 0.975)]
    m_a, m_b = median([r.rags for r in a]), median([r.rags for r in b])
    p_ab = p_outlasts(a, b)
    p_value, exact = permutation_p_value(a, b, seed, permutations)
    resolved = p_value < SIGNIFICANCE and p_ab != 0.5
    return Comparison(
        median_a=m_a, median_a_95=ci_a, median_b=m_b, median_b_95=ci_b,
        runs_a=len(a), runs_b=len(b), censored_a=sum(r.censored for r in a), censored_b=sum(r.censored for r in b),
        p_a_outlasts_b=p_ab, p_a_outlasts_b_95=[percentile(ps, 0.025), percentile(ps, 0.975)],
        p_value=p_value, exact=exact, resolved=resolved, later=("A" if p_ab > 0.5 else "B") if resolved else None)


def statement(c: Comparison, name_a: str, name_b: str) -> str:
    """The comparison in a sentence a designer reads."""
    def design(median_value, ci, censored, runs):
        if censored == runs:
            return "no clog in %s (it coped with the %g rags fed)" % (
                "its one run" if runs == 1 else "any of its %d runs" % runs, median_value)
        return "clogs after %g rags (95 %% interval %g-%g%s)" % (median_value, ci[0], ci[1],
                                                       ", a lower bound: %d run%s did not clog"
                                                       % (censored, "" if censored == 1 else "s") if censored else "")
    text = "%s: %s; %s: %s. P(%s outlasts %s) = %.2f (95 %% interval %.2f-%.2f). " % (
        name_a, design(c.median_a, c.median_a_95, c.censored_a, c.runs_a), name_b,
        design(c.median_b, c.median_b_95, c.censored_b, c.runs_b),
        name_a, name_b, c.p_a_outlasts_b, c.p_a_outlasts_b_95[0], c.p_a_outlasts_b_95[1])
    test = "Gehan's test, %s p = %.3f" % ("exact" if c.exact else "by random relabelling,", c.p_value)
    if c.resolved:
        text += "%s lasts longer (%s)." % (name_a if c.later == "A" else name_b, test)
    elif c.censored_a == c.runs_a and c.censored_b == c.runs_b:
        text += "Not resolved: neither design clogged in any run; more seeds cannot tell them apart, more rags can."
    else:
        smallest = 1.0 / math.comb(c.runs_a + c.runs_b, c.runs_a) * 2
        cut_short = c.censored_a + c.censored_b
        text += "Not resolved (%s, needs under %.2f)%s%s." % (
            test, SIGNIFICANCE, "; with %d and %d runs no outcome can reach it: more seeds" % (c.runs_a, c.runs_b)
            if smallest >= SIGNIFICANCE else "; more seeds may tell",
            # Runs that coped with every rag are ties with each other: a longer feed breaks them.
            ", and a longer feed: %d of the %d runs coped with all their rags" % (cut_short, c.runs_a + c.runs_b)
            if 2 * cut_short > c.runs_a + c.runs_b else "")
    return text
