"""The operating point of a pump run (a case without structures whose rigid body rotates): the
head, the shaft torque, the efficiency and the once-per-revolution pulsation, averaged over the
last whole revolutions after a settling period. Used by cases/centrifugal-pump/postprocess.py
and python/fsi/pump_curve.py. Inputs, all in the run's output folder:
  forces.csv            the fluid's force (N) and torque (N m, about the body's box centre, which
                        the generated impeller has on the axis) on each rigid body, every step
  openfoam/postProcessing/{inlet,outlet}TotalPressure/*/surfaceFieldValue.dat
                        the mass-flow-averaged total pressure p + rho |U|^2 / 2 (Pa) of the patches
  openfoam/postProcessing/outletFlowRate/*/surfaceFieldValue.dat   sum(phi) on the outlet (m^3/s)
  parts.csv             (optional) the torque of each part of the impeller (its STL's regions:
                        hub, shroud, blade sides, eye), columns body0.<part>.t{x,y,z}_n_m; the
                        penalized runs count each cell for the part closest to it, the AMI
                        runs integrate each patch: torque_by_part_n_m, the shaft's share of each
  parts_pressure.csv    (optional, the AMI runs) the same, the pressure's share alone:
                        pressure_torque_by_part_n_m
  parts_staircase.csv   (optional, the penalized runs) the same, the share the pressure on the
                        staircase's steps takes off the surface (the steps' form drag):
                        staircase_torque_by_part_n_m
  penalization.csv      (penalized runs) the kinetic energy per second the moving impeller
                        destroys in the cells it newly covers (W): switching_power_w, its mean;
                        and the water its cells swallow through their faces with free cells
                        (m^3/s) with the energy destroyed there (W): transpiration_*; and the
                        power of the inertia of the water the impeller's cells hold, left out of
                        its torque (W; divided by omega, the torque it would add): held_fluid_power_w
  openfoam/postProcessing/rotorEnergyFlux/*/surfaceFieldValue.dat   (optional, the runs whose
                        rotor turns behind an AMI) the total-pressure energy flux out of the
                        rotor's water, sum(phi p_t) over its AMI face (W): rotor.energy_flux_out_w,
                        and the shaft power less it, the power the rotor's water dissipates (it
                        stores none over whole revolutions): rotor.loss_w
Definitions (SI): H = (p_t,out - p_t,in) / (rho g) (m); T = -a . T_fluid (N m, the torque the
shaft supplies, a the rotation axis); eta = rho g Q H / (T omega); psi = g H / (omega R2)^2 and
phi = Q / (omega R2^3) (the issue's coefficients); the pulsation is the amplitude of the Fourier
component at the rotation frequency (the blade passing frequency of a single blade), as a
fraction of the mean."""

import glob
import math
import os

import numpy as np
import yaml

from fsi.front_seal import LEAK_FUNCTION_NAME
from fsi.pump_stations import STATIONS
from fsi.time_means import window_mean

G = 9.81  # m/s^2


def rotation(case_dir, who="pump"):
    """(omega rad/s, axis direction) of the rotating surface of CASE_DIR/case.yaml (the impeller);
    refused, naming the file and the key, when the case has none."""
    with open(os.path.join(case_dir, "case.yaml")) as f:
        case = yaml.safe_load(f) or {}
    for surface in (case.get("collisions") or {}).get("surfaces") or []:
        rot = (surface.get("motion") or {}).get("rotation")
        if rot:
            return float(rot["rate_rad_per_s"]), rot.get("axis_direction", [0, 0, 1])
    raise SystemExit("%s: %s: no rotating surface (collisions.surfaces[].motion.rotation)"
                     % (who, os.path.join(case_dir, "case.yaml")))


def read_dat(folder, name):
    """(time, columns) of OpenFOAM's postProcessing/<name>/<start>/<file>.dat (restarts joined)."""
    files = sorted(glob.glob(os.path.join(folder, "openfoam", "postProcessing", name, "*", "*.dat")),
                   key=lambda p: float(os.path.basename(os.path.dirname(p))))
    if not files:
        raise FileNotFoundError("no %s output in %s/openfoam/postProcessing (is the controlDict's "
                                "function object there?)" % (name, folder))
    rows = []
    for path in files:
        with open(path) as f:
            for line in f:
                if line.strip() and not line.startswith("#"):
                    rows.append([float(w) for w in line.split()])
    data = np.array(rows)[::-1]     # a time in two files: the later start's (the continued run's)
    _, unique = np.unique(data[:, 0], return_index=True)
    data = data[unique]
    return data[:, 0], data[:, 1:]


def read_forces(folder, body=0):
    with open(os.path.join(folder, "forces.csv")) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(os.path.join(folder, "forces.csv"), delimiter=",", skiprows=1, ndmin=2)
    column = {name: k for k, name in enumerate(header)}
    torque = np.stack([data[:, column["body%d.t%s_n_m" % (body, c)]] for c in "xyz"], axis=1)
    return data[:, 0], torque


def harmonic(t, y, omega):
    """Amplitude of the component of y at angular frequency omega over the samples t (uniform)."""
    c = np.mean(y * np.cos(omega * t))
    s = np.mean(y * np.sin(omega * t))
    return 2.0 * math.hypot(c, s)


def station_budget(folder, window, rho):
    """The head budget over the averaging window from the stations' function objects
    (python/fsi/pump_stations.py; none when the run has none): per station the mean flow rate
    (m^3/s, along its normal), the flow-weighted total pressure over the window (Pa: the mean of
    p_t Q over the mean of Q, so that the energy fluxes add) and its head above the suction
    pipe's (m)."""
    rows = []
    for name in STATIONS:
        try:
            t_q, q = read_dat(folder, "stationFlowRate_" + name)
            t_p, p = read_dat(folder, "stationTotalPressure_" + name)
        except FileNotFoundError:
            return None
        n = min(len(t_q), len(t_p))
        tw, qw = window(t_q[:n], q[:n, 0])
        _, pw = window(t_p[:n], p[:n, 0])
        if not len(tw):
            return None
        q_mean = float(np.mean(qw))
        rows.append({"station": name, "flow_rate_m3_per_s": q_mean,
                     "total_pressure_pa": float(np.mean(pw * qw) / q_mean) if q_mean else float("nan")})
    for row in rows:
        row["head_above_suction_m"] = (row["total_pressure_pa"] - rows[0]["total_pressure_pa"]) / (rho * G)
    return rows


def seal_leak(folder, window):
    """The mean leak through the front seal's porous ring over the averaging window (m^3/s,
    towards the eye positive: the face flux through its exit, python/fsi/front_seal.py), or None
    for a run without one."""
    try:
        t, leak = read_dat(folder, LEAK_FUNCTION_NAME)
    except FileNotFoundError:
        return None
    _, lw = window(t, leak[:, 0])
    return float(np.mean(lw)) if len(lw) else None


def rotor_budget(folder, window, shaft_power_w):
    """The rotor's energy budget over the averaging window (None when the run has no
    rotorEnergyFlux function object): the mean energy flux out of the rotor's water (W), and the
    shaft power less it, the power lost in that water (W) and as a fraction of the shaft power."""
    try:
        t, flux = read_dat(folder, "rotorEnergyFlux")
    except FileNotFoundError:
        return None
    _, fw = window(t, flux[:, 0])
    if not len(fw):
        return None
    out = float(np.mean(fw))
    loss = shaft_power_w - out
    return {"energy_flux_out_w": out, "loss_w": loss,
            "loss_fraction": loss / shaft_power_w if shaft_power_w else float("nan")}


def revolution_series(t, y, t0, period, n):
    """The time mean of y (sampled at times t) over each of the n revolutions [t0 + k P, t0 + (k + 1) P]
    (time_means.window_mean: each sample weighted by its step, so that revolutions holding 166 and
    167 samples in turn do not swing with the once-per-revolution pulsation)."""
    return [window_mean(t, y, t0 + k * period, t0 + (k + 1) * period) for k in range(n)]


def revolution_means(t_torque, torque, t_head, head, t0, period, n):
    """The mean of torque and head over each of the n revolutions from t0, the standard error of
    the window's mean that their scatter gives (std / sqrt(n), revolutions taken as independent;
    None for one revolution) and the drift of the last three (max - min of their means over the
    window's mean, the issue's "under 2 %" rule; None for fewer than three)."""
    result = {"revolution_torque_n_m": revolution_series(t_torque, torque, t0, period, n),
              "revolution_head_m": revolution_series(t_head, head, t0, period, n)}
    for key, name in (("revolution_torque_n_m", "torque"), ("revolution_head_m", "head")):
        values = np.asarray(result[key])
        unit = "n_m" if name == "torque" else "m"
        result["%s_standard_error_%s" % (name, unit)] = (float(np.std(values, ddof=1) / math.sqrt(n))
                                                         if n > 1 else None)
        mean = float(np.mean(values))
        result["%s_drift_last_3_revolutions" % name] = (float((values[-3:].max() - values[-3:].min()) / abs(mean))
                                                       if n >= 3 and mean else None)
    return result


def operating_point(folder, omega, axis, radius_m, flow_rate, rho=1000.0, average_revolutions=4,
                    settle_revolutions=None, end_time_s=None):
    """The operating point of the run in `folder`: a dict of SI values (see the module text).
    Averages over the last `average_revolutions` whole revolutions that follow at least
    `settle_revolutions` (default: the rest of the run, at least 1), of the run up to
    `end_time_s` (default: its end; an earlier time compares runs of different lengths over the
    same window)."""
    period = 2.0 * math.pi / omega
    t_f, torque = read_forces(folder)
    shaft = -(torque @ (np.asarray(axis, float) / np.linalg.norm(axis)))
    t_in, p_in = read_dat(folder, "inletTotalPressure")
    t_out, p_out = read_dat(folder, "outletTotalPressure")
    t_end = min(t_f[-1], t_in[-1], t_out[-1], end_time_s if end_time_s is not None else math.inf)
    n_rev = int(math.floor(t_end / period + 1e-6))
    n_avg = min(average_revolutions, n_rev - (settle_revolutions if settle_revolutions is not None else 1))
    if n_avg < 1:
        raise ValueError("%s: %.3g s is %d revolutions, too short to settle and average one" % (folder, t_end, n_rev))
    t0, t1 = (n_rev - n_avg) * period, n_rev * period

    def window(t, y):
        keep = (t > t0 + 1e-9) & (t <= t1 + 1e-9)
        return t[keep], y[keep]

    tw, tq = window(t_f, shaft)
    head_t = np.interp(t_out, t_in, p_in[:, 0])
    hw, dp = window(t_out, p_out[:, 0] - head_t)
    head = np.mean(dp) / (rho * G)
    torque_mean = float(np.mean(tq))
    q_out = None
    try:
        t_q, q = read_dat(folder, "outletFlowRate")
        q_out = float(np.mean(window(t_q, q[:, 0])[1]))
    except FileNotFoundError:
        pass
    switching = None  # the penalized runs: the energy their moving impeller destroys as it covers cells
    transpiration = [None, None]  # and the water its staircase swallows through its faces
    held_power = None  # and the inertia of the water its cells hold, left out of the torque
    path = os.path.join(folder, "penalization.csv")
    if os.path.isfile(path):
        data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        if len(data):
            switching = float(np.mean(window(data[:, 0], data[:, 3])[1]))
            if data.shape[1] >= 6:
                transpiration = [float(np.mean(window(data[:, 0], data[:, k])[1])) for k in (4, 5)]
            if data.shape[1] >= 7:
                held_power = float(np.nanmean(window(data[:, 0], data[:, 6])[1]))
    def part_torques(name):
        """{part: shaft torque (N m) over the window} of FOLDER/name (parts.csv's format), or None."""
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            return None
        with open(path) as f:
            header = f.readline().strip().split(",")
        data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        a = np.asarray(axis, float) / np.linalg.norm(axis)
        result = {}
        for k, column in enumerate(header):
            if column.startswith("body0.") and column.endswith(".tx_n_m"):
                shaft_part = -(data[:, k:k + 3] @ a)
                result[column[len("body0."):-len(".tx_n_m")]] = float(np.mean(window(data[:, 0], shaft_part)[1]))
        return result

    by_part = part_torques("parts.csv")
    pressure_by_part = part_torques("parts_pressure.csv")   # the body-fitted runs: the pressure's share
    staircase_by_part = part_torques("parts_staircase.csv")   # the penalized runs: the steps' form drag
    power = torque_mean * omega
    u2 = omega * radius_m
    revolutions = revolution_means(tw, tq, hw, dp / (rho * G), t0, period, n_avg)
    point = {
        "flow_rate_m3_per_s": flow_rate,
        "outlet_flow_rate_m3_per_s": q_out,
        "head_m": float(head),
        "head_rms_fluctuation_m": float(np.std(dp) / (rho * G)),
        "shaft_torque_n_m": torque_mean,
        "shaft_power_w": power,
        "hydraulic_power_w": rho * G * flow_rate * head,
        "switching_power_w": switching,
        "transpiration_m3_per_s": transpiration[0],
        "transpiration_power_w": transpiration[1],
        "held_fluid_power_w": held_power,
        "efficiency": rho * G * flow_rate * head / power if power > 0 else float("nan"),
        "head_coefficient_psi": G * head / u2 ** 2,
        "flow_coefficient_phi": flow_rate / (omega * radius_m ** 3),
        "torque_pulsation_1_per_rev": harmonic(tw, tq, omega) / abs(torque_mean) if torque_mean else float("nan"),
        "head_pulsation_1_per_rev": harmonic(hw, dp, omega) / abs(np.mean(dp)) if np.mean(dp) else float("nan"),
        # The same amplitudes in their units: the fractions above mean nothing near zero head.
        "torque_pulsation_amplitude_n_m": harmonic(tw, tq, omega),
        "head_pulsation_amplitude_m": harmonic(hw, dp, omega) / (rho * G),
        "averaged_from_s": t0,
        "averaged_to_s": t1,
        "revolutions_averaged": n_avg,
        "revolutions_run": n_rev,
    }
    point = {k: (None if v is None else int(v) if isinstance(v, int) else float(v)) for k, v in point.items()}
    point.update(revolutions)
    stations = station_budget(folder, window, rho)
    if stations:
        point["stations"] = stations
    leak = seal_leak(folder, window)
    if leak is not None:
        point["front_seal_leak_m3_per_s"] = leak
    rotor = rotor_budget(folder, window, power)
    if rotor:
        point["rotor"] = rotor
    if by_part is not None:
        point["torque_by_part_n_m"] = by_part
    if pressure_by_part is not None:
        point["pressure_torque_by_part_n_m"] = pressure_by_part
    if staircase_by_part is not None:
        point["staircase_torque_by_part_n_m"] = staircase_by_part
    return point


def histories(folder, omega, axis, rho=1000.0):
    """(t, shaft torque N m) and (t, head m) for pictures."""
    t_f, torque = read_forces(folder)
    shaft = -(torque @ (np.asarray(axis, float) / np.linalg.norm(axis)))
    t_in, p_in = read_dat(folder, "inletTotalPressure")
    t_out, p_out = read_dat(folder, "outletTotalPressure")
    head = (p_out[:, 0] - np.interp(t_out, t_in, p_in[:, 0])) / (rho * G)
    return (t_f, shaft), (t_out, head)
