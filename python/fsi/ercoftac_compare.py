"""Our ERCOFTAC pump runs against the measurement (issue 31): the probes the case's OpenFOAM
folders write (cases/ercoftac-pump/make_case.py: `impellerOutlet`, the velocity at R/R2 = 1.02;
`casing`, the pressure at the radii of the casing's taps; `budget`, the velocity on the circles of
the angular momentum budget), averaged as the measurement was
(python/fsi/ercoftac_pump.py reads it), and the fits that place a profile measured from an
undocumented origin against ours.

Angles: theta is the absolute angle of the table's frame; the impeller turns toward -theta, so
the impeller-fixed angle is phi = theta + omega t (phi = theta at t = 0, when the mesh's blades
are Table 2's). A folder with a dynamicMeshDict turns its rotor and the probes' cells with it
(fixedLocations false): from the angle of its point at the run's start (the time its
postProcessing folder is named after), a probe in the rotor (r < 0.217 m, the AMI) turns by
-omega (t - start); the stator's stay."""

import glob
import math
import os

import numpy as np
from matplotlib.path import Path

from fsi import ercoftac_pump as ecp
from fsi.ercoftac_mesh import R_INTERFACE_M

UNSET = -1e300          # OpenFOAM's probes write -VGREAT for a point in no cell (a body-fitted blade)


def read_probes(foam_case, name, field):
    """The rows of a probes function object's `field`: (points (n, 3), [(time_s, theta_rad[n], values
    (n, k))]), theta each probe's absolute angle at that time, values NaN where a probe lies in no
    cell. A restart's rows replace the ones it repeats; a line cut short by a stopped run is left
    out."""
    root = os.path.join(foam_case, "postProcessing", name)
    if not os.path.isdir(root):
        raise ValueError("%s: no samples (the %s function object of controlDict)" % (root, name))
    turning = os.path.isfile(os.path.join(foam_case, "constant", "dynamicMeshDict"))
    omega = ecp.omega_rad_per_s()
    rows, points = {}, None
    for folder in sorted(os.listdir(root), key=float):
        path = os.path.join(root, folder, field)
        if not os.path.isfile(path):
            continue
        here, start_angle = [], None
        with open(path) as f:
            for line in f:
                if line.startswith("#"):
                    if line.startswith("# Probe "):
                        here.append([float(v) for v in line[line.index("(") + 1:line.index(")")].split()])
                    continue
                values = line.replace("(", " ").replace(")", " ").split()
                if not here or (len(values) - 1) % len(here) or len(values) < 1 + len(here):
                    continue
                if start_angle is None:   # the folder's probes, once
                    xy = np.array(here)[:, :2]
                    start_angle = np.arctan2(xy[:, 1], xy[:, 0])
                    turns = turning & (np.hypot(xy[:, 0], xy[:, 1]) < R_INTERFACE_M)
                t = float(values[0])
                u = np.array(values[1:], float).reshape(len(here), -1)
                u[u < 0.5 * UNSET] = np.nan
                rows[t] = (t, start_angle - np.where(turns, omega * (t - float(folder)), 0.0), u)
        points = np.array(here) if here else points
    return points, [rows[t] for t in sorted(rows)]


def read_outlet_samples(foam_case):
    """The velocity at the measured radius: [(time_s, theta_rad[n], c_r[n], c_u[n], z_m)], c_u
    positive with the impeller's rotation (-theta), z the probes' height (the slab's mid-plane)."""
    points, rows = read_probes(foam_case, "impellerOutlet", "U")
    out = []
    for t, theta, u in rows:
        c_r = u[:, 0] * np.cos(theta) + u[:, 1] * np.sin(theta)
        c_u = -(-u[:, 0] * np.sin(theta) + u[:, 1] * np.cos(theta))
        out.append((t, theta, c_r, c_u, float(points[0, 2])))
    return out


def after(samples, settle_revolutions, what):
    start = settle_revolutions * 2 * math.pi / ecp.omega_rad_per_s()
    used = [s for s in samples if s[0] >= start - 1e-12]
    if not used:
        raise ValueError("%s: no samples after %g revolutions (the last at t = %.4g s)"
                         % (what, settle_revolutions, samples[-1][0] if samples else 0.0))
    return used


def impeller_outlet(foam_case, settle_revolutions, bins=100, samples=None, vane_phases=12):
    """Our velocities at R/R2 = 1.02 as the measurement gives them: averaged over the whole circle
    (all 7 pitches) and over the samples after settle_revolutions; and across one pitch in the
    impeller's frame (phase-averaged over the blades and the samples: bins across the pitch,
    the fraction growing against the rotation from the blade-fixed origin phi = 0). Over U2.
    Also the c_r-weighted c_u (the swirl the flow carries out), the mean c_r against the flow
    rate's (continuity): the sampling's check; and the
    passage-averaged c_u by the vanes' phase against the passage (the position of the nearest vane
    leading edge behind the passage's first blade, in `vane_phases` bins of the vane pitch): the
    measurement holds four such phases (its instants), this average all of them. samples:
    read_outlet_samples(foam_case), when the caller has read them."""
    samples = samples if samples is not None else read_outlet_samples(foam_case)
    omega, u2 = ecp.omega_rad_per_s(), ecp.tip_speed_m_per_s()
    used = after(samples, settle_revolutions, foam_case)
    pitch, vane_pitch = 2 * math.pi / ecp.BLADES, 2 * math.pi / ecp.VANES
    leading_edge = ecp.vane().a[0]
    vane_angle = math.atan2(leading_edge[1], leading_edge[0])
    sums, counts = np.zeros((2, bins)), np.zeros(bins)
    by_phase, in_phase = np.zeros(vane_phases), np.zeros(vane_phases)
    for t, theta, c_r, c_u, _z in used:
        phi = np.mod(theta + omega * t, 2 * math.pi)
        fraction = np.mod(phi, pitch) / pitch
        k = np.minimum((fraction * bins).astype(int), bins - 1)
        np.add.at(sums[0], k, c_r)
        np.add.at(sums[1], k, c_u)
        np.add.at(counts, k, 1.0)
        passage = np.minimum((phi / pitch).astype(int), ecp.BLADES - 1)
        means = np.bincount(passage, c_u, ecp.BLADES) / np.maximum(np.bincount(passage, None, ecp.BLADES), 1)
        first_blade = np.arange(ecp.BLADES) * pitch - omega * t          # absolute angle of each passage's origin
        phase = np.mod(first_blade - vane_angle, vane_pitch) / vane_pitch
        j = np.minimum((phase * vane_phases).astype(int), vane_phases - 1)
        np.add.at(by_phase, j, means)
        np.add.at(in_phase, j, 1.0)
    by_phase = by_phase[in_phase > 0] / in_phase[in_phase > 0] / u2
    continuity = ecp.design_flow_rate_m3_per_s() / (2 * math.pi * ecp.MEASUREMENT_RADIUS_M * ecp.SPAN_M)
    cr_mean = float(np.mean([np.mean(s[2]) for s in used]))
    # The swirl the flow carries out (weighted by c_r): where the plain average, the probes', also
    # counts the near wake's slow fluid at the blade's speed (README: "Where the excess is").
    carried = float(sum(np.sum(s[2] * s[3]) for s in used) / sum(np.sum(s[2]) for s in used)) / u2
    return {"cr_over_u2": cr_mean / u2, "cu_over_u2": float(np.mean([np.mean(s[3]) for s in used])) / u2,
            "cu_over_u2_flux_weighted": carried,
            "cr_over_continuity": cr_mean / continuity, "samples": len(used),
            "from_s": used[0][0], "to_s": used[-1][0],
            "cu_over_u2_by_vane_phase": by_phase.tolist(),
            "profile": {"pitch_fraction": ((np.arange(bins) + 0.5) / bins).tolist(),
                        "cr_over_u2": (sums[0] / np.maximum(counts, 1) / u2).tolist(),
                        "cu_over_u2": (sums[1] / np.maximum(counts, 1) / u2).tolist()}}


def impeller_torque(out, start, end):
    """The impeller's mean torque from start to end (s): the penalized body's (out/forces.csv,
    about its box's centre) or the blades' patch's (the forces function object, about the axis).
    None without either."""
    penalized = os.path.join(out, "forces.csv")
    # the forces function object's folders, one per start (a restart's rows replace those it repeats)
    moments = sorted(glob.glob(os.path.join(out, "openfoam", "postProcessing", "forces", "*", "moment.dat")),
                     key=lambda path: float(os.path.basename(os.path.dirname(path))))
    if os.path.isfile(penalized):
        loads = np.loadtxt(penalized, delimiter=",", skiprows=1, ndmin=2)
        torque = loads[:, [0, 6]]
    elif moments:
        rows = {}
        for moment in moments:
            begin = float(os.path.basename(os.path.dirname(moment)))
            rows = {t: m for t, m in rows.items() if t < begin - 1e-12}
            with open(moment) as f:
                for line in f:
                    values = line.replace("(", " ").replace(")", " ").split()
                    if not line.startswith("#") and len(values) >= 4:
                        rows[float(values[0])] = float(values[3])
        torque = np.array(sorted(rows.items()))
    else:
        return None
    window = (torque[:, 0] >= start - 1e-12) & (torque[:, 0] <= end + 1e-12)
    return float(np.mean(torque[window, 1]))


def angular_momentum_balance(out, settle_revolutions, samples=None):
    """The impeller's torque against the angular momentum the flow carries out through the
    measured radius (nothing else acts between the blades' trailing edge at R2 and that circle, and
    the inflow has no swirl), over the samples after settle_revolutions: rho dz r^2 sum(c_r c_u)
    dtheta, divided by the sampled mass flux over the imposed one (the sampling's error, which
    the product shares). The torque is the penalized body's (out/forces.csv, about its box's
    centre) or the blades' patch's (the forces function object, about the axis), over the same
    time. Returns {torque_n_m, flux_torque_n_m, flux_over_torque} of the slab, or None without
    a torque."""
    foam = os.path.join(out, "openfoam")
    samples = samples if samples is not None else read_outlet_samples(foam)
    used = after(samples, settle_revolutions, foam)
    start, end = used[0][0], used[-1][0]
    mean_torque = impeller_torque(out, start, end)
    if mean_torque is None:
        return None
    dz = 2.0 * samples[0][4]                     # sampled in the one-cell slab's mid-plane
    r = ecp.MEASUREMENT_RADIUS_M
    n = len(used[0][1])
    flux = np.mean([np.sum(s[2] * s[3]) for s in used]) * ecp.AIR_DENSITY_KG_PER_M3 * dz * r * r * 2 * math.pi / n
    sampled = np.mean([np.sum(s[2]) for s in used]) * dz * r * 2 * math.pi / n
    flux /= sampled / (ecp.design_flow_rate_m3_per_s() * dz / ecp.SPAN_M)
    return {"torque_n_m": mean_torque, "flux_torque_n_m": float(flux), "flux_over_torque": float(flux) / mean_torque}


def angular_momentum_by_radius(out, settle_revolutions):
    """Where the flow gets its angular momentum: through each circle of the `budget` probes, the
    flux rho dz r^2 sum(c_r c_u) dtheta over the samples after settle_revolutions, as
    angular_momentum_balance takes it at the measured radius (divided by the sampled mass flux
    over the imposed one), against the impeller's torque. Inside the blades a penalized run's
    probes in the body read its rigid motion (no c_r: no flux), a body-fitted run's find no
    cell. Returns [{radius_m, flux_over_torque, mass_flux_over_imposed}] by radius, or None
    without the probes or a torque."""
    foam = os.path.join(out, "openfoam")
    if not os.path.isdir(os.path.join(foam, "postProcessing", "budget")):
        return None
    points, rows = read_probes(foam, "budget", "U")
    used = after(rows, settle_revolutions, foam)
    torque = impeller_torque(out, used[0][0], used[-1][0])
    if torque is None:
        return None
    dz = 2.0 * float(points[0, 2])
    radius = np.round(np.hypot(points[:, 0], points[:, 1]), 4)   # the probes file prints 6 digits
    imposed = ecp.design_flow_rate_m3_per_s() * dz / ecp.SPAN_M
    result = []
    for r in sorted(set(radius.tolist())):
        on = radius == r
        flux, mass = [], []
        for _t, theta, u in used:
            th, v = theta[on], u[on]
            c_r = v[:, 0] * np.cos(th) + v[:, 1] * np.sin(th)
            c_u = -(-v[:, 0] * np.sin(th) + v[:, 1] * np.cos(th))
            flux.append(np.nanmean(c_r * c_u))
            mass.append(np.nanmean(c_r))
        sampled = np.mean(mass) * dz * r * 2 * math.pi
        moment = np.mean(flux) * ecp.AIR_DENSITY_KG_PER_M3 * dz * r * r * 2 * math.pi * imposed / sampled
        result.append({"radius_m": r, "flux_over_torque": float(moment / torque),
                       "mass_flux_over_imposed": float(sampled / imposed)})
    return result


def blade_mask(radii_m, bins):
    """[radius, bin] True where the bin's centre (phi = (bin + 0.5) / bins of the pitch) lies in a
    blade: no fluid there, in neither method."""
    outlines = [Path(ecp.blade().rotated(k * 2 * math.pi / ecp.BLADES).outline()) for k in range(ecp.BLADES)]
    phi = (np.arange(bins) + 0.5) / bins * 2 * math.pi / ecp.BLADES
    mask = np.zeros((len(radii_m), bins), bool)
    for i, r in enumerate(radii_m):
        xy = np.column_stack([r * np.cos(phi), r * np.sin(phi)])
        for path in outlines:
            mask[i] |= path.contains_points(xy)
    return mask


def casing_pressure(foam_case, settle_revolutions, bins=100):
    """Our pressure coefficient cp = p / (rho U2^2 / 2) at the casing taps' radii across one pitch
    in the impeller's frame (phi = theta + omega t folded onto the pitch, phase-averaged over the
    blades and the samples after settle_revolutions), NaN in the blades (blade_mask) and where no
    sample fell. Returns (radii over R2, bin centres as pitch fractions, cp[radius, bin],
    samples used)."""
    points, rows = read_probes(foam_case, "casing", "p")
    used = after(rows, settle_revolutions, foam_case)
    omega, u2 = ecp.omega_rad_per_s(), ecp.tip_speed_m_per_s()
    radius = np.round(np.hypot(points[:, 0], points[:, 1]) / ecp.R2_M, 5)
    radii = np.array(sorted(set(radius.tolist())))
    which = np.searchsorted(radii, radius)
    pitch = 2 * math.pi / ecp.BLADES
    sums, counts = np.zeros((len(radii), bins)), np.zeros((len(radii), bins))
    for t, theta, p in used:
        k = np.minimum((np.mod(theta + omega * t, pitch) / pitch * bins).astype(int), bins - 1)
        good = np.isfinite(p[:, 0])
        np.add.at(sums, (which[good], k[good]), p[good, 0] / (0.5 * u2 ** 2))      # p kinematic
        np.add.at(counts, (which[good], k[good]), 1.0)
    cp = np.where(counts > 0, sums / np.maximum(counts, 1), np.nan)
    cp[blade_mask(radii * ecp.R2_M, bins)] = np.nan
    return radii, (np.arange(bins) + 0.5) / bins, cp, len(used)


def common_shift_rms(pairs, shifts=200):
    """Profiles across a pitch measured from an undocumented blade-fixed origin against ours: the
    one periodic shift of ours (a fraction of the pitch) that minimises the sum of the profiles'
    mean squared differences, and each profile's RMS difference at it. pairs: [(ours_fraction,
    ours, measured_fraction, measured)]. Returns (shift, [rms])."""
    best = (math.inf, 0.0, [])
    for shift in np.linspace(0.0, 1.0, shifts, endpoint=False):
        rms = []
        for of, ov, mf, mv in pairs:
            moved = np.interp(np.mod(np.asarray(mf) - shift, 1.0), of, ov, period=1.0)
            rms.append(float(np.sqrt(np.mean((moved - np.asarray(mv)) ** 2))))
        best = min(best, (sum(r * r for r in rms), float(shift), rms))
    return best[1], best[2]


def casing_fit(ours, measured):
    """Our cp[radius, bin] against the measured one on the same radii and bins: the one shift of
    the pitch (whole bins) and the one offset (the unstated reference pressure) that minimise the
    RMS difference over every bin both have. Also the rise of the pitch-averaged cp from the
    innermost tap to each radius (reference-free) in both, each averaged over the bins both have
    at the fitted shift (ours has none in the blades). Returns a dict."""
    bins = ours.shape[1]
    best = None
    for k in range(bins):
        moved = np.roll(ours, k, axis=1)
        both = np.isfinite(moved) & np.isfinite(measured)
        offset = float(np.mean(measured[both] - moved[both]))
        rms = float(np.sqrt(np.mean((measured[both] - moved[both] - offset) ** 2)))
        if best is None or rms < best[0]:
            best = (rms, k, offset)
    rms, k, offset = best
    moved = np.roll(ours, k, axis=1)
    both = np.isfinite(moved) & np.isfinite(measured)
    ours_mean = np.array([np.mean(m[b]) for m, b in zip(moved, both)])
    measured_mean = np.array([np.mean(m[b]) for m, b in zip(measured, both)])
    return {"rms": rms, "shift_pitch_fraction": k / bins, "offset": offset,
            "rise_ours": (ours_mean - ours_mean[0]).tolist(),
            "rise_measured": (measured_mean - measured_mean[0]).tolist()}
