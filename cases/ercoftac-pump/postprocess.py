#!/usr/bin/python3
"""After a run of ercoftac-pump (./fsi run calls it; the body-fitted reference's
python/fsi/ercoftac_ami_run.py too): our probes over the run's second half against the
measurement (reference.yaml, data/):
- at R/R2 = 1.02: the pitch-averaged c_u/U2 (the work input) and c_r/U2, their errors against
  midspan and the span average, the RMS difference of the profiles across a pitch (ours moved by
  the one shift that fits both, the measurement's origin against the blade being undocumented),
  and the sampling's check (our mean c_r against continuity's);
- the impeller's torque against the angular momentum the flow carries out through that radius
  (they balance: nothing else turns the flow between the blades and the probes), and through
  the budget's circles from inside the blades to the diffuser (where the flow gets it);
- on the casing's tap radii: cp across a pitch against the measured one, with one shift and one
  offset (the reference pressure is not stated), and the rise of the pitch-averaged cp from the
  innermost tap.
Writes impeller_outlet.yaml, impeller_outlet.png and casing_pressure.png in the results folder.
Usage: postprocess.py RESULTS_DIR CASE_DIR"""

import math
import os
import sys

import numpy as np
import yaml

from fsi import ercoftac_compare as ecc
from fsi import ercoftac_pump as ecp


def outlet(foam, measured):
    samples = ecc.read_outlet_samples(foam)
    revolutions = samples[-1][0] * ecp.omega_rad_per_s() / (2 * math.pi)
    ours = ecc.impeller_outlet(foam, 0.5 * revolutions, samples=samples)
    result = {"revolutions_run": round(revolutions, 3), "averaged_from_s": ours["from_s"],
              "averaged_to_s": ours["to_s"], "samples": ours["samples"],
              "cu_over_u2": ours["cu_over_u2"], "cu_over_u2_flux_weighted": ours["cu_over_u2_flux_weighted"],
              "cr_over_u2": ours["cr_over_u2"],
              "cr_over_continuity": ours["cr_over_continuity"],
              "cu_over_u2_vane_phase_min": min(ours["cu_over_u2_by_vane_phase"]),
              "cu_over_u2_vane_phase_max": max(ours["cu_over_u2_by_vane_phase"])}
    for where in ("midspan", "span_average"):
        result["cu_error_against_%s" % where] = ours["cu_over_u2"] / measured["cu_over_u2_" + where] - 1.0
    fraction = np.array(ours["profile"]["pitch_fraction"])
    m_fraction, m_cr, m_cu = ecp.measured_profile(0.5)
    shift, (rms_cu, rms_cr) = ecc.common_shift_rms([
        (fraction, ours["profile"]["cu_over_u2"], m_fraction, m_cu),
        (fraction, ours["profile"]["cr_over_u2"], m_fraction, m_cr)])
    result.update({"cu_profile_rms_midspan": rms_cu, "cr_profile_rms_midspan": rms_cr,
                   "profile_shift_pitch_fraction": shift})
    balance = ecc.angular_momentum_balance(os.path.dirname(foam), 0.5 * revolutions, samples=samples)
    if balance:
        result["angular_momentum"] = balance
    by_radius = ecc.angular_momentum_by_radius(os.path.dirname(foam), 0.5 * revolutions)
    if by_radius:
        result["angular_momentum_by_radius"] = by_radius
    return result, ours, revolutions, (m_fraction, m_cr, m_cu)


def casing(foam, revolutions):
    if not os.path.isdir(os.path.join(foam, "postProcessing", "casing")):
        return None, None
    radii, fraction, cp, used = ecc.casing_pressure(foam, 0.5 * revolutions)
    m_radii, _, m_cp = ecp.measured_casing_pressure(len(fraction))
    if not np.allclose(radii, m_radii, atol=1e-4):
        raise SystemExit("postprocess: the casing probes' radii %s are not the taps' %s: run make_case.py"
                         % (radii.tolist(), m_radii.tolist()))
    fit = ecc.casing_fit(cp, m_cp)
    result = {"samples": used, "radii_over_r2": radii.tolist(), "cp_rms": fit["rms"],
              "cp_shift_pitch_fraction": fit["shift_pitch_fraction"], "cp_offset": fit["offset"],
              "cp_rise_ours": fit["rise_ours"], "cp_rise_measured": fit["rise_measured"],
              "cp_rise_error": fit["rise_ours"][-1] - fit["rise_measured"][-1]}
    return result, (radii, fraction, cp, m_cp, fit)


def plots(out, ours, result, measured_profiles, measured, cp_data):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fraction = np.array(ours["profile"]["pitch_fraction"])
    m_fraction, m_cr, m_cu = measured_profiles
    shift = result["profile_shift_pitch_fraction"]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, values in ((axes[0], "cu", m_cu), (axes[1], "cr", m_cr)):
        ax.plot(m_fraction, values, "k.", label="measured, midspan (4 instants)")
        ax.plot(np.mod(fraction + shift, 1.0), ours["profile"][key + "_over_u2"], "C0.", ms=3,
                label="ours (shifted %.2f)" % shift)
        ax.set_xlabel("pitch fraction")
        ax.set_ylabel("c_%s / U2" % key[1])
        ax.legend(fontsize=8)
    fig.suptitle("ERCOFTAC pump, R/R2 = 1.02: c_u/U2 %.3f ours, %.3f midspan, %.3f span average"
                 % (ours["cu_over_u2"], measured["cu_over_u2_midspan"], measured["cu_over_u2_span_average"]))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "impeller_outlet.png"), dpi=110)
    plt.close(fig)
    if cp_data is None:
        return
    radii, cp_fraction, cp, m_cp, fit = cp_data
    moved = np.roll(cp, int(round(fit["shift_pitch_fraction"] * len(cp_fraction))), axis=1) + fit["offset"]
    fig, axes = plt.subplots(2, (len(radii) + 1) // 2, figsize=(15, 6), sharex=True, sharey=True)
    for ax, r, mine, theirs in zip(axes.flat, radii, moved, m_cp):
        ax.plot(cp_fraction, theirs, "k.", ms=3, label="measured (casing)")
        ax.plot(cp_fraction, mine, "C0-", label="ours (mid-plane)")
        ax.set_title("R/R2 = %.3f" % r, fontsize=9)
    for ax in axes[-1]:
        ax.set_xlabel("pitch fraction")
    axes[0][0].legend(fontsize=7)
    fig.suptitle("ERCOFTAC pump, cp across a pitch: ours shifted %.2f pitch, offset %+.3f; RMS %.3f"
                 % (fit["shift_pitch_fraction"], fit["offset"], fit["rms"]))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "casing_pressure.png"), dpi=100)
    plt.close(fig)


def main(out, case_dir):
    with open(os.path.join(case_dir, "reference.yaml")) as f:
        measured = yaml.safe_load(f)["measured"]
    foam = os.path.join(out, "openfoam")
    result, ours, revolutions, measured_profiles = outlet(foam, measured)
    casing_result, cp_data = casing(foam, revolutions)
    if casing_result:
        result["casing"] = casing_result
    with open(os.path.join(out, "impeller_outlet.yaml"), "w") as f:
        f.write("# The velocity at R/R2 = 1.02 over U2 = 43.98 m/s (the run's second half) against the ERCOFTAC\n"
                "# measurement (reference.yaml); errors are ours / measured - 1; profile RMS over U2 at the\n"
                "# one shift that fits c_u and c_r; casing: cp = p / (rho U2^2 / 2), RMS at the fitted shift\n"
                "# and offset, rise of the pitch-averaged cp from R/R2 = 0.533.\n")
        yaml.safe_dump(result, f, sort_keys=False)
    try:
        plots(out, ours, result, measured_profiles, measured, cp_data)
    except ImportError:
        pass
    line = ("impeller_outlet.yaml: c_u/U2 = %.4f (measured %.3f midspan, %.3f span average: %+.1f %%, %+.1f %%), "
            "c_r against continuity %.3f, profile RMS c_u %.3f c_r %.3f"
            % (ours["cu_over_u2"], measured["cu_over_u2_midspan"], measured["cu_over_u2_span_average"],
               100 * result["cu_error_against_midspan"], 100 * result["cu_error_against_span_average"],
               ours["cr_over_continuity"], result["cu_profile_rms_midspan"], result["cr_profile_rms_midspan"]))
    if "angular_momentum" in result:
        line += "; angular momentum flux / torque %.3f" % result["angular_momentum"]["flux_over_torque"]
    if casing_result:
        line += "; casing cp RMS %.3f, rise %.3f (measured %.3f)" % (
            casing_result["cp_rms"], casing_result["cp_rise_ours"][-1], casing_result["cp_rise_measured"][-1])
    print(line)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit("usage: postprocess.py RESULTS_DIR CASE_DIR")
    main(sys.argv[1], sys.argv[2])
