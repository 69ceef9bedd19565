#!/usr/bin/python3
"""The report of a rag feed (issue 33): rags released in sequence into a running pump, as test
rigs feed them. From a run of a case with a `feed` section (cases/rag-feed):

  RUN_DIR/feed_rags.csv         one row per rag: its release, entry (into the pump) and exit
                                times (s), how long it was in the scene and in the pump (s and
                                revolutions), its outcome and where it is held
  RUN_DIR/feed_revolutions.csv  one row per whole revolution: the time mean head (m) and shaft
                                power (W), their change against the clean pump at the same flow,
                                the efficiency rho g Q H / P and its change (a difference), the
                                rags in the scene and retained at its end, and where the rags
                                in the scene are then (at_<site>: how many are at each trap site,
                                each counted once, SITE_PRIORITY; at_free: touching none)
  RUN_DIR/feed_report.yaml      the clog criterion of the case (feed.clog_criterion) and its
                                verdict: met or not, when, at which rag count and why, the degree
                                of saturation (the most rags and mass retained before), with the
                                clean pump it is judged against and the definitions
  RUN_DIR/feed_timeline.png     the feed over time: each rag from release to exit or to the end
                                (coloured by outcome), below it the revolution means of the head
                                and power change with the releases marked and the clog time
  RUN_DIR/feed_retained.png     the rags still in the pump at the end on the impeller at its pose
                                (top and side sections, as plot_rag_in_pump.py's)
  RUN_DIR/feed.mp4              every saved frame of the feed (with --animation)

A rag is in the pump from its entry: the first saved frame with half its points or more above
the sump's top (in the suction pipe; a pump without a sump: from its release), except while it
is back in the sump (half its points below the top again: entries). A rag's outcome (the
residence rule of python/fsi/clog_criterion.py: residence_revolutions of the criterion, 10
without one, counted from its entry):
  passed    left the scene (past feed.remove_when_past, the exit_time_s of structure.h5) within
            the rule after its entry
  passed_late  left later than that
  torn      torn off the scene (structures[].tear_above_stretch_ratio: stretched beyond it, caught
            between the turning impeller and the casing), exit_reason "torn" in structure.h5.
            The clog criterion and the retained counts take a torn rag as caught, not passed:
            held in the pump from its tear to the end (criterion_rags)
  retained  in the pump at the end, entered at least the rule's revolutions before it
  in_pump   in the pump at the end, entered less than that before it
  in_sump   in the sump at the end: never entered the pump, or fell back into the sump (a pump
            at part load can throw rags back out of its eye); not retained
  waiting   not released by the end of the run
Where a rag in the scene at the end is held: the trap site (rag_metrics.SITES) its points
touched longest over the last revolution of the run (python/fsi/rag_metrics.py: the contact
distance 1.5 d_c), or "free" when it touched none; "sump" for the `suction` site when the rag
lies mostly outside the suction pipe's radius (the casing's suction_wall region holds the
sump's walls too).

Usage: feed_report.py RUN_DIR CASE_DIR [--animation]
Python: write_report(run_dir, case_dir, animation=False) -> the report dict.
"""
import argparse
import csv
import dataclasses
import math
import os
import re
import sys

import numpy as np

from fsi import clog_criterion
from fsi import rag_metrics

OUTCOMES = ("passed", "passed_late", "torn", "retained", "in_pump", "in_sump", "waiting")
OUTCOME_COLOURS = {"passed": "tab:green", "passed_late": "tab:olive", "torn": "tab:purple", "retained": "tab:red",
                   "in_pump": "tab:orange", "in_sump": "tab:blue", "waiting": "0.7"}


class FeedError(Exception):
    """A run that is not a feed's, or a file missing from it: says which and what is expected."""


# ---------------------------------------------------------------------------------- reading

def read_feed_rags(run_dir):
    """[{name, release_time_s, exit_time_s (None: in to the end), grid_shape, area_m2}] of
    RUN_DIR/structure.h5 in release order, and its frame times [F]."""
    import h5py
    path = os.path.join(run_dir, "structure.h5")
    if not os.path.isfile(path):
        raise FeedError("%s: no such file (RUN_DIR must be the output folder of a feed's run)" % path)
    rags = []
    with h5py.File(path, "r") as f:
        if "time_s" not in f or "structures" not in f:
            raise FeedError("%s: no /time_s or /structures (docs/results.md describes the layout)" % path)
        rows = rag_metrics.complete_rows(f)
        times = np.asarray(f["time_s"][:rows], float)
        for name, g in f["structures"].items():
            if "release_time_s" not in g.attrs:
                raise FeedError("%s: /structures/%s has no release_time_s (written since issue 33: rerun the case)"
                                % (path, name))
            exit_time = float(g.attrs.get("exit_time_s", float("nan")))
            reason = g.attrs.get("exit_reason", "")
            reason = reason.decode() if isinstance(reason, bytes) else str(reason)
            n1, n2 = (int(v) for v in g.attrs["grid_shape"])
            first = np.asarray(g["position_m"][0], float).reshape(n1, n2, 3)
            rags.append({"name": name, "release_time_s": float(g.attrs["release_time_s"]),
                         "exit_time_s": None if math.isnan(exit_time) else exit_time, "exit_reason": reason,
                         "grid_shape": (n1, n2), "area_m2": grid_area(first)})
    if not rags:
        raise FeedError("%s: no structure" % path)
    rags.sort(key=lambda r: (r["release_time_s"], r["name"]))
    return rags, times


def grid_area(points):
    """Area (m^2) of a grid of points [n1, n2, 3], two triangles per cell."""
    a, b, c, d = points[:-1, :-1], points[1:, :-1], points[1:, 1:], points[:-1, 1:]
    return float(0.5 * (np.linalg.norm(np.cross(b - a, c - a), axis=-1)
                        + np.linalg.norm(np.cross(c - a, d - a), axis=-1)).sum())


def kind_of(name, kinds):
    """The feed's kind entry a fed rag's name comes from (its name without the release index)."""
    base = re.sub(r"\d+$", "", name)
    for kind in kinds:
        if (kind.get("name") or "rag") == base:
            return kind
    raise FeedError("structure '%s' is not a rag of the feed (kinds: %s)"
                    % (name, ", ".join(k.get("name") or "rag" for k in kinds)))


def criterion_of(feed):
    """The case's clog criterion (clog_criterion.ClogCriterion), or None when it states none."""
    mapping = feed.get("clog_criterion")
    if not mapping:
        return None
    return clog_criterion.ClogCriterion.from_mapping(mapping, "feed.clog_criterion")


# ---------------------------------------------------------------------------------- analysis

def outcomes(rags, end_time_s, residence_s):
    """Each rag's outcome at the end of the run (the module's definitions), in place, and its
    time in the scene and in the pump (s). A rag's entry_time_s (entries) starts the residence
    rule's clock; a rag without the key entered at its release (a pump without a sump), one whose
    entry_time_s is None never entered."""
    for r in rags:
        entry = r.get("entry_time_s", r["release_time_s"])
        until = r["exit_time_s"] if r["exit_time_s"] is not None else end_time_s
        if r["release_time_s"] > end_time_s + 1e-12:
            r["outcome"] = "waiting"
        elif r["exit_time_s"] is not None and r.get("exit_reason") == "torn":
            r["outcome"] = "torn"
        elif r["exit_time_s"] is not None:
            start = entry if entry is not None else r["release_time_s"]   # seen in the pump by no frame
            r["outcome"] = "passed" if r["exit_time_s"] - start <= residence_s + 1e-12 else "passed_late"
        elif entry is None or any(b == math.inf for _, b in r.get("sump_intervals", ())):
            r["outcome"] = "in_sump"   # never entered the pump, or fell back into the sump for good
        else:
            r["outcome"] = "retained" if end_time_s - entry >= residence_s - 1e-12 else "in_pump"
        waiting = r["outcome"] == "waiting"
        r["time_in_scene_s"] = 0.0 if waiting else max(0.0, until - r["release_time_s"])
        back = sum(min(b, until) - a for a, b in r.get("sump_intervals", ()) if a < until)
        r["time_in_pump_s"] = 0.0 if waiting or entry is None else max(0.0, until - entry - back)
    return rags


def sump_top_axial(geometry, pipe_radius):
    """The sump's top (its walls' highest axial position, toward the impeller; m), or None
    without a sump (suction_pipe_radius)."""
    if pipe_radius is None:
        return None
    walls = np.asarray(geometry.casing["suction_wall"]).reshape(-1, 3)
    outer = walls[geometry.radius(walls) > 1.5 * pipe_radius]
    return float(np.max(geometry.axial(outer))) if len(outer) else None


def entries(rags, structure, geometry):
    """Each rag's entry into the pump and its returns to the sump, in place: entry_time_s, the
    first saved frame at or after its release with half its points or more above the sump's top
    (in the suction pipe; the long rag stands as high as the sump), None when there is none; and
    sump_intervals, the spans [from, to) of frames after it with half its points or more back
    below (to: the next frame above, or inf). A pump without a sump: entered at its release,
    never back. `structure(name)`: (t, x, grid)."""
    top = sump_top_axial(geometry, suction_pipe_radius(geometry))
    for r in rags:
        r["sump_intervals"] = []
        if top is None:
            r["entry_time_s"] = r["release_time_s"]
            continue
        t, x, _ = structure(r["name"])
        released = t >= r["release_time_s"] - 1e-12
        above = np.median(geometry.axial(x), axis=1) > top
        if r["exit_time_s"] is not None:
            released &= t < r["exit_time_s"] - 1e-12   # after its exit its frames keep its last place
        first = np.flatnonzero(released & above)
        if not len(first):
            r["entry_time_s"] = None
            continue
        r["entry_time_s"] = float(t[first[0]])
        start = None
        for k in range(first[0], len(t)):
            if not released[k]:
                break
            if not above[k] and start is None:
                start = float(t[k])
            elif above[k] and start is not None:
                r["sump_intervals"].append((start, float(t[k])))
                start = None
        if start is not None:
            r["sump_intervals"].append((start, math.inf))
    return rags


SITES = rag_metrics.SITES + ("sump", "free")


def suction_pipe_radius(geometry):
    """The suction pipe's radius when the casing has a sump wider than it (its suction_wall
    region then holds both: the pipe's wall at the smallest radius, the sump's further out);
    None without a sump."""
    walls = geometry.casing.get("suction_wall")
    if walls is None or not len(walls):
        return None
    r = geometry.radius(np.asarray(walls).reshape(-1, 3))
    return float(r.min()) if r.max() > 1.2 * r.min() else None


def sump_or_suction(site, points, geometry, pipe_radius):
    """`suction` told apart: a rag whose points lie mostly outside the pipe's radius is in the sump."""
    if site == "suction" and pipe_radius is not None and np.median(geometry.radius(points)) > pipe_radius:
        return "sump"
    return site


def held_where(structure, rag, times, geometry, threshold_m, period_s):
    """The trap site a rag in the scene at the end touched longest over the run's last
    revolution, and that time (s); ("free", 0) when it touched none. `structure(name)`: the rag's
    (t, x, grid) as rag_metrics.read_structure gives them."""
    t_end = times[-1]
    keep = (times >= max(rag["release_time_s"], t_end - period_s) - 1e-12)
    if np.count_nonzero(keep) < 1:
        return "free", 0.0
    t, x, grid = structure(rag["name"])
    t, x = t[keep[:len(t)]], x[keep[:len(t)]]
    metrics, _ = rag_metrics.analyse(t, x, grid, geometry, threshold_m)
    contact = {site: metrics["trap_contact_time_s." + site] for site in rag_metrics.SITES}
    site = max(contact, key=contact.get)
    if contact[site] <= 0:
        return "free", 0.0
    return sump_or_suction(site, x[-1], geometry, suction_pipe_radius(geometry)), contact[site]


# A rag touching several sites at once is counted at the first of them in this order: the sites
# that hold a rag (the leading edge, the cut-water) before those it slides along.
SITE_PRIORITY = ("leading_edge", "cut_water", "eye_and_hub", "blade_sides", "shroud", "side_gap", "volute_wall",
                 "discharge", "suction")


def sites_over_time(structure, rags, times, ends, geometry, threshold_m):
    """Per revolution end (the saved frame nearest to it): how many rags in the scene are at each
    trap site (rag_metrics' sites and contact distance; a rag touching several counted once, at
    the first in SITE_PRIORITY; `suction` told from `sump`), and how many touch none ("free").
    [{site: count}] in the order of `ends`: the counts of a revolution add up to its rags."""
    frames = np.array([int(np.argmin(np.abs(times - e))) for e in ends], int)
    counts = [dict() for _ in ends]
    pipe_radius = suction_pipe_radius(geometry)
    for r in rags:
        until = r["exit_time_s"] if r["exit_time_s"] is not None else np.inf
        # In the scene at the revolution's end, as in_scene_counts: released before it, not gone.
        inside = [k for k, e in enumerate(ends) if r["release_time_s"] <= e - 1e-9 < until]
        if not inside:
            continue
        t, x, grid = structure(r["name"])
        picked = frames[inside]
        _, series = rag_metrics.analyse(t[picked], x[picked], grid, geometry, threshold_m)
        for j, k in enumerate(inside):
            site = next((sump_or_suction(site, x[picked[j]], geometry, pipe_radius)
                         for site in SITE_PRIORITY if series["sites"][site][j]), "free")
            counts[k][site] = counts[k].get(site, 0) + 1
    return counts


def load_traces(run_dir, geometry, config):
    """(t, head m, t, shaft power W, clean head m, clean power W, notes): the run's head and power
    and the clean pump's (the precursor's whole revolutions, rag_metrics.clean_from_precursor)."""
    surfaces = (config.get("collisions") or {}).get("surfaces") or []
    index = next((k for k, s in enumerate(surfaces) if ((s or {}).get("motion") or {}).get("rotation")), 0)
    loads, notes = rag_metrics.read_loads(run_dir, geometry, config, index)
    clean, clean_notes = rag_metrics.clean_from_precursor(run_dir, geometry, config, index)
    notes += clean_notes
    rate = abs(geometry.rate)
    torque, head = loads["torque"], loads["head"]
    return {"head": head, "power": (torque[0], torque[1] * rate) if torque is not None else None,
            "clean_head_m": (clean or {}).get("head"),
            "clean_power_w": (clean or {}).get("torque") * rate if (clean or {}).get("torque") is not None else None,
            "clean_source": (clean or {}).get("source"), "notes": notes}


def criterion_rags(rags):
    """The rags as the clog criterion sees them: a torn rag was caught (stretched between the
    turning impeller and the casing), not passed: it never left; a rag's clock starts when it
    entered the pump, one that never did is never retained, nor one back in the sump."""
    def entry(r):
        if "entry_time_s" not in r:
            return None
        return clog_criterion.NEVER if r["entry_time_s"] is None else r["entry_time_s"]
    return [clog_criterion.Rag(r["release_time_s"], None if r.get("exit_reason") == "torn" else r["exit_time_s"],
                               r.get("mass_kg", 0.0), entry(r),
                               tuple((a, clog_criterion.NEVER if b == math.inf else b)
                                     for a, b in r.get("sump_intervals", ()))) for r in rags]


def in_scene_counts(rags, t, residence_s):
    """(in the scene, retained) at each time of t: in the scene, released and not gone (torn
    rags gone at their tear); retained as the criterion counts them (clog_criterion.retained_at,
    torn rags held, criterion_rags)."""
    t = np.asarray(t, float)
    inside = np.zeros(len(t), int)
    for r in rags:
        until = r["exit_time_s"] if r["exit_time_s"] is not None else np.inf
        inside += (t >= r["release_time_s"]) & (t < until)
    held_rags = criterion_rags(rags)
    held = np.array([len(clog_criterion.retained_at(held_rags, time, residence_s)) for time in t], int)
    return inside, held


def revolutions_table(rags, traces, period_s, residence_s, flow_rate_m3_per_s=None, density_kg_per_m3=1000.0):
    """Rows per whole revolution of the traces (both head and power needed), or []. With the
    flow rate, the efficiency rho g Q H / P of each revolution's means and the clean pump's."""
    if traces["head"] is None or traces["power"] is None:
        return []
    ends, heads = clog_criterion.revolution_means(traces["head"][0], traces["head"][1], period_s)
    ends_p, powers = clog_criterion.revolution_means(traces["power"][0], traces["power"][1], period_s)
    n = min(len(ends), len(ends_p))
    inside, _ = in_scene_counts(rags, ends[:n] - 1e-9, residence_s)   # in the scene: just before the end
    _, held = in_scene_counts(rags, ends[:n], residence_s)               # retained: at the end, as the criterion
    rows = []
    for k in range(n):
        h, p = float(heads[k]), float(powers[k])
        ch, cp = traces["clean_head_m"], traces["clean_power_w"]
        eta = density_kg_per_m3 * rag_metrics.G * flow_rate_m3_per_s * h / p if flow_rate_m3_per_s and p > 0 else None
        eta_clean = (density_kg_per_m3 * rag_metrics.G * flow_rate_m3_per_s * ch / cp
                     if flow_rate_m3_per_s and ch and cp else None)
        rows.append({"revolution": int(round(ends[k] / period_s)), "end_time_s": float(ends[k]), "head_m": h,
                     "shaft_power_w": p, "head_change": h / ch - 1.0 if ch else None,
                     "power_change": p / cp - 1.0 if cp else None, "efficiency": eta,
                     "efficiency_change": eta - eta_clean if eta is not None and eta_clean is not None else None,
                     "rags_in_scene": int(inside[k]), "rags_retained": int(held[k])})
    return rows


def verdict(criterion, rags, traces, period_s, end_time_s):
    """The criterion's result as a plain dict, and notes (None without a criterion). Without the
    run's head and power or the clean pump's (a precursor shorter than four revolutions), the
    head and power conditions are left out and the verdict says so (`not_evaluated`)."""
    if criterion is None:
        return None, []
    feed_rags = criterion_rags(rags)
    have_traces = (traces["head"] is not None and traces["power"] is not None and bool(traces["clean_head_m"])
                   and bool(traces["clean_power_w"]))
    skipped, notes = [], []
    if not have_traces:
        skipped = [k for k in ("head_drop_fraction", "power_rise_fraction") if getattr(criterion, k) is not None]
        if skipped:
            notes.append("clog criterion: %s not evaluated (no head and power of the run and of the clean pump: %s)"
                         % (" and ".join(skipped), "; ".join(traces["notes"])))
            criterion = dataclasses.replace(criterion, head_drop_fraction=None, power_rise_fraction=None)
        if criterion.retained_rags is None:
            return {"clogged": None, "not_evaluated": skipped}, notes
    if have_traces:
        t, head = traces["head"]
        power = np.interp(t, *traces["power"])
        clean_h, clean_p = traces["clean_head_m"], traces["clean_power_w"]
    else:  # the retained rags alone: the traces are not read
        t, head, power = np.array([0.0, end_time_s]), np.ones(2), np.ones(2)
        clean_h, clean_p = 1.0, 1.0
    result = clog_criterion.evaluate(criterion, period_s, t, head, power, clean_h, clean_p, feed_rags)
    return {"clogged": result.clogged, "time_s": result.time_s,
            "revolution": result.time_s / period_s if result.time_s is not None else None,
            "reason": result.reason, "rags_released": result.rags_released, "rags_retained": result.rags_retained,
            "saturation_rags": result.saturation_rags, "saturation_kg": result.saturation_kg,
            "not_evaluated": skipped}, notes


# ---------------------------------------------------------------------------------- outputs

def _plain(value):
    """YAML-safe: numpy scalars to Python numbers, tuples to lists, recursively."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def write_csv(path, rows, columns):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for row in rows:
            w.writerow(["" if row.get(c) is None else ("%.9g" % row[c] if isinstance(row[c], float) else row[c])
                        for c in columns])


RAG_COLUMNS = ["name", "release_time_s", "entry_time_s", "exit_time_s", "time_in_scene_s", "time_in_scene_revolutions",
               "time_in_pump_s", "time_in_pump_revolutions", "outcome", "held_at", "held_contact_time_s", "mass_kg"]
REVOLUTION_COLUMNS = ["revolution", "end_time_s", "head_m", "shaft_power_w", "head_change", "power_change",
                      "efficiency", "efficiency_change", "rags_in_scene", "rags_retained"] + [
                          "at_" + site for site in SITES]


def draw_timeline(path, rags, revolutions, result, period_s, end_time_s, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    has_traces = bool(revolutions) and revolutions[0]["head_change"] is not None
    fig, axes = plt.subplots(3 if has_traces else 1, 1, figsize=(9, 8.5 if has_traces else 4.5), sharex=True,
                             squeeze=False, gridspec_kw={"height_ratios": [3, 2, 1.6] if has_traces else [1]})
    ax = axes[0, 0]
    rev = 1.0 / period_s
    for k, r in enumerate(rags):
        if r["outcome"] == "waiting":
            ax.plot([r["release_time_s"] * rev], [k + 1], "o", mfc="none", color=OUTCOME_COLOURS["waiting"], ms=4)
            continue
        until = r["exit_time_s"] if r["exit_time_s"] is not None else end_time_s
        colour = OUTCOME_COLOURS[r["outcome"]]
        # Thin in the sump (before its entry, or back in it), thick in the pump.
        entry = r.get("entry_time_s", r["release_time_s"])
        ax.plot([r["release_time_s"] * rev, (until if entry is None else entry) * rev], [k + 1, k + 1], "-",
                lw=1.2, color=colour)
        if entry is not None:
            edges = [entry] + [v for a, b in r.get("sump_intervals", ()) for v in (a, min(b, until))] + [until]
            for a, b in zip(edges[0::2], edges[1::2]):
                ax.plot([a * rev, b * rev], [k + 1, k + 1], "-", lw=4, solid_capstyle="butt", color=colour)
            for a, b in zip(edges[1::2], edges[2::2]):
                ax.plot([a * rev, b * rev], [k + 1, k + 1], "-", lw=1.2, color=colour)
        if r.get("held_at") and r["held_at"] != "free":
            ax.text(until * rev, k + 1, " " + r["held_at"], va="center", fontsize=7)
    for outcome in OUTCOMES:
        if any(r["outcome"] == outcome for r in rags):
            ax.plot([], [], "-", lw=4, color=OUTCOME_COLOURS[outcome], label=outcome.replace("_", " "))
    ax.plot([], [], "-", lw=1.2, color="0.4", label="in the sump")
    ax.set_ylabel("rag (release order)")
    ax.set_yticks(range(1, len(rags) + 1))
    ax.set_yticklabels([r["name"] for r in rags], fontsize=7 if len(rags) <= 30 else 5)
    ax.set_ylim(len(rags) + 1, 0)
    ax.legend(fontsize=8, loc="lower left", ncol=3)
    ax.grid(alpha=0.3)
    ax.set_title(title, fontsize=9)
    if has_traces:
        ax2 = axes[1, 0]
        x = [r["end_time_s"] * rev - 0.5 for r in revolutions]
        ax2.step(x, [100 * r["head_change"] for r in revolutions], where="mid", label="head")
        ax2.step(x, [100 * r["power_change"] for r in revolutions], where="mid", label="shaft power")
        for r in rags:
            if r["outcome"] != "waiting":
                ax2.axvline(r["release_time_s"] * rev, color="0.8", lw=0.6, zorder=0)
        ax2.axhline(0, color="k", lw=0.6)
        ax2.set_ylabel("revolution mean against\nthe clean pump (%)")
        ax2.legend(fontsize=8)
        ax2.grid(alpha=0.3)
        ax3 = axes[2, 0]
        # Where the rags in the scene are at each revolution's end, stacked (each rag once), and
        # how many of them are retained.
        sites = [site for site in SITES if any(r.get("at_" + site) for r in revolutions)]
        if sites:
            ax3.stackplot([r["end_time_s"] * rev for r in revolutions],
                          *[[r.get("at_" + site, 0) for r in revolutions] for site in sites],
                          labels=[site.replace("_", " ") for site in sites], step="pre", alpha=0.8,
                          colors=[plt.get_cmap("tab20")(SITES.index(site) / 20.0) for site in sites])
        ax3.step(x, [r["rags_retained"] for r in revolutions], where="mid", color="k", lw=1.5, label="retained")
        ax3.set_ylabel("rags in the scene\nby where they are")
        ax3.set_ylim(bottom=0)
        ax3.legend(fontsize=6, ncol=4, loc="upper left")
        ax3.grid(alpha=0.3)
    if result and result.get("clogged"):
        for a in axes[:, 0]:
            a.axvline(result["time_s"] * rev, color="k", ls="--", lw=1.0)
        axes[0, 0].text(result["time_s"] * rev, 0.5, " clogged (%s)" % result["reason"], fontsize=8, va="top")
    axes[-1, 0].set_xlabel("impeller revolutions since the start (releases: grey lines)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def masked_run(run_dir, rags):
    """plot_rag_in_pump.Run of the feed with each rag's points NaN where it is not in the scene
    (before its release, after its exit), and the wall distances of the points in the scene."""
    from fsi import plot_rag_in_pump as plot
    run = plot.Run(run_dir)
    shown = np.ones(run.points.shape[:2], bool)
    timing = {r["name"]: r for r in rags}
    for name, start, n1, n2 in run.structures:
        r = timing[name]
        until = r["exit_time_s"] if r["exit_time_s"] is not None else np.inf
        off = (run.time_s < r["release_time_s"] - 1e-12) | (run.time_s >= until)
        shown[off, start:start + n1 * n2] = False
    return run, shown


def draw_retained(path, run_dir, case_dir, rags, title):
    """The rags in the scene at the last frame, on the impeller at its pose (top and side)."""
    from fsi import plot_rag_in_pump as plot
    run, shown = masked_run(run_dir, rags)
    last = len(run.time_s) - 1
    keep = shown[last]
    if not keep.any():
        return False
    pump = plot.Pump(run_dir, case_dir)
    index = np.flatnonzero(keep)
    remap = -np.ones(run.points.shape[1], int)
    remap[index] = np.arange(len(index))
    pairs = run.pairs[keep[run.pairs].all(axis=1)]
    run.points = run.points[last:last + 1][:, index]
    run.time_s = run.time_s[last:last + 1]
    run.pairs = remap[pairs]
    wall, _ = plot.distances(run, pump)
    plot.draw_sequence(run, pump, wall, [0], path, title)
    return True


def draw_movie(path, run_dir, case_dir, rags, title):
    from fsi import plot_rag_in_pump as plot
    run, shown = masked_run(run_dir, rags)
    pump = plot.Pump(run_dir, case_dir)
    wall, _ = plot.distances(run, pump)
    run.points = np.where(shown[:, :, None], run.points, np.nan)
    return plot.draw_animation(run, pump, wall, path, title)


def describe(criterion, result):
    """The criterion in a few words, with the conditions the run could not evaluate."""
    parts = []
    if criterion.head_drop_fraction is not None:
        parts.append("head -%g %%" % (100 * criterion.head_drop_fraction))
    if criterion.power_rise_fraction is not None:
        parts.append("power +%g %%" % (100 * criterion.power_rise_fraction))
    words = " or ".join(parts)
    if words:
        words += " for %d revolutions" % criterion.held_revolutions
    if criterion.retained_rags is not None:
        words += (" or " if words else "") + "%d rags retained" % criterion.retained_rags
    if result.get("not_evaluated"):
        words += "; head and power not evaluated (no clean pump)"
    return words


def write_report(run_dir, case_dir, animation=False):
    """Reads RUN_DIR and CASE_DIR, writes the files of the module's docstring, returns the report."""
    config, source = rag_metrics.read_config(run_dir, case_dir)
    feed = config.get("feed")
    if not feed:
        raise FeedError("%s: no feed section (a run of a case with `feed`, e.g. cases/rag-feed)" % source)
    criterion = criterion_of(feed)
    residence_rev = criterion.residence_revolutions if criterion else clog_criterion.ClogCriterion.residence_revolutions
    geometry, d_c, _, geometry_notes, _ = rag_metrics.load_geometry(case_dir, config, source)
    period = 2 * math.pi / abs(geometry.rate)
    residence_s = residence_rev * period
    rags, times = read_feed_rags(run_dir)
    end_time = float(times[-1])
    for r in rags:
        kind = kind_of(r["name"], feed.get("kinds") or [])
        rho = float(((kind.get("material") or {}).get("mass_per_area_kg_per_m2", 0.0)))
        r["mass_kg"] = rho * r["area_m2"]
    # Each rag's history read once: for its entry into the pump, where it is held, and last for
    # sites_over_time, which lets it go (tens of MB for a 20-rag feed).
    read_once = {}

    def structure(name):
        if name not in read_once:
            read_once[name] = rag_metrics.read_structure(run_dir, name)[:3]
        return read_once[name]

    def structure_last_use(name):
        return read_once.pop(name, None) or rag_metrics.read_structure(run_dir, name)[:3]

    entries(rags, structure, geometry)
    outcomes(rags, end_time, residence_s)

    for r in rags:
        r["time_in_scene_revolutions"] = r["time_in_scene_s"] / period
        r["time_in_pump_revolutions"] = r["time_in_pump_s"] / period
        if r["outcome"] in ("retained", "in_pump", "in_sump"):
            r["held_at"], r["held_contact_time_s"] = held_where(structure, r, times, geometry, d_c, period)
    traces = load_traces(run_dir, geometry, config)
    foam = (config.get("fluid") or {}).get("openfoam") or {}
    flow_rate = (foam.get("operating_point") or {}).get("flow_rate_m3_per_s")
    density = float(foam.get("density_kg_per_m3", 1000.0))
    revolutions = revolutions_table(rags, traces, period, residence_s, flow_rate, density)
    if revolutions:
        where = sites_over_time(structure_last_use, rags, times, [r["end_time_s"] for r in revolutions], geometry, d_c)
        for row, counts in zip(revolutions, where):
            row.update({"at_" + site: counts.get(site, 0) for site in SITES})
    result, verdict_notes = verdict(criterion, rags, traces, period, end_time)
    write_csv(os.path.join(run_dir, "feed_rags.csv"), rags, RAG_COLUMNS)
    write_csv(os.path.join(run_dir, "feed_revolutions.csv"), revolutions, REVOLUTION_COLUMNS)
    counts = {o: sum(1 for r in rags if r["outcome"] == o) for o in OUTCOMES}
    held = {}
    for r in rags:
        if r.get("held_at"):
            held[r["held_at"]] = held.get(r["held_at"], 0) + 1
    report = {
        "end_time_s": end_time, "end_revolution": end_time / period, "period_s": period,
        "rags": len(rags), "outcomes": counts, "held_at": held,
        "residence_revolutions": residence_rev,
        "clog_criterion": dict(feed.get("clog_criterion") or {}) or None,
        "verdict": result,
        "clean_pump": {"head_m": traces["clean_head_m"], "shaft_power_w": traces["clean_power_w"],
                       "flow_rate_m3_per_s": flow_rate,
                       "efficiency": (density * rag_metrics.G * flow_rate * traces["clean_head_m"] / traces["clean_power_w"]
                                      if flow_rate and traces["clean_head_m"] and traces["clean_power_w"] else None),
                       "source": traces["clean_source"]},
        "sources": {"run_dir": os.path.abspath(run_dir), "case_dir": os.path.abspath(case_dir),
                    "configuration": source},
        "notes": geometry_notes + traces["notes"] + verdict_notes,
    }
    import yaml
    with open(os.path.join(run_dir, "feed_report.yaml"), "w") as f:
        f.write("# The rag feed's report (python/fsi/feed_report.py; per rag feed_rags.csv, per revolution\n"
                "# feed_revolutions.csv). SI units: s, m, W, kg; changes are fractions of the clean pump's.\n")
        yaml.safe_dump(_plain(report), f, sort_keys=False)
    name = os.path.basename(os.path.normpath(case_dir))
    title = "%s: %d rags, %s" % (name, len(rags), ", ".join("%d %s" % (n, o.replace("_", " "))
                                                            for o, n in counts.items() if n))
    if result is not None and result["clogged"] is not None:
        title += "\n" + (("clogged at %.1f revolutions (%s), %d rags released, %d retained"
                          % (result["revolution"], result["reason"], result["rags_released"], result["rags_retained"]))
                         if result["clogged"] else "not clogged by the end (%s)" % describe(criterion, result))
    draw_timeline(os.path.join(run_dir, "feed_timeline.png"), rags, revolutions, result, period, end_time, title)
    draw_retained(os.path.join(run_dir, "feed_retained.png"), run_dir, case_dir, rags,
                  "%s: the rags in the scene at t = %.3g s (%.1f revolutions)" % (name, end_time, end_time / period))
    if animation:
        draw_movie(os.path.join(run_dir, "feed.mp4"), run_dir, case_dir, rags, name)
    return report


def main(argv=None):
    p = argparse.ArgumentParser(prog="feed_report.py", description=__doc__.split("\n\n")[0])
    p.add_argument("run_dir")
    p.add_argument("case_dir")
    p.add_argument("--animation", action="store_true", help="also feed.mp4 (every saved frame)")
    args = p.parse_args(argv)
    try:
        report = write_report(args.run_dir, args.case_dir, animation=args.animation)
    except (FeedError, rag_metrics.MetricsError, clog_criterion.CriterionError) as error:
        sys.exit("feed_report.py: %s" % error)
    v = report["verdict"]
    print("%d rags: %s%s" % (report["rags"], ", ".join("%d %s" % (n, o) for o, n in report["outcomes"].items() if n),
                             "" if v is None or v["clogged"] is None else ("; clogged at %.2f revolutions (%s)" % (v["revolution"], v["reason"])
                                                   if v["clogged"] else "; not clogged")))


if __name__ == "__main__":
    main()
