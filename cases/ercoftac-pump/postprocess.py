#!/usr/bin/python3
"""After a run of ercoftac-pump (./fsi run calls it): the velocity at the measured radius
(R/R2 = 1.02) over the run's second half, against the measurement (reference.yaml,
data/impeller_outlet_velocity.csv): the pitch-averaged c_u/U2 (the work input) and c_r/U2, their
errors against midspan and the span average, the RMS difference of the profiles across a pitch
(ours moved to the measured phase, whose origin is not documented), and the sampling's check (our
mean c_r against continuity's). Writes impeller_outlet.yaml and impeller_outlet.png in the
results folder. Usage: postprocess.py RESULTS_DIR CASE_DIR"""

import math
import os
import sys

import numpy as np
import yaml

from fsi import ercoftac_pump as ecp


def main(out, case_dir):
    with open(os.path.join(case_dir, "reference.yaml")) as f:
        measured = yaml.safe_load(f)["measured"]
    # the run's length: its last sample (a penalized run's and an AMI run's alike)
    samples = ecp.read_outlet_samples(os.path.join(out, "openfoam"))
    revolutions = samples[-1][0] * ecp.omega_rad_per_s() / (2 * math.pi)
    ours = ecp.impeller_outlet(os.path.join(out, "openfoam"), 0.5 * revolutions, samples=samples)
    fraction = np.array(ours["profile"]["pitch_fraction"])
    result = {"revolutions_run": round(revolutions, 3), "averaged_from_s": ours["from_s"],
              "averaged_to_s": ours["to_s"], "samples": ours["samples"],
              "cu_over_u2": ours["cu_over_u2"], "cr_over_u2": ours["cr_over_u2"],
              "cr_over_continuity": ours["cr_over_continuity"]}
    for where in ("midspan", "span_average"):
        result["cu_error_against_%s" % where] = ours["cu_over_u2"] / measured["cu_over_u2_" + where] - 1.0
    m_fraction, m_cr, m_cu = ecp.measured_profile(0.5)
    for key, values in (("cu", m_cu), ("cr", m_cr)):
        rms, shift = ecp.profile_rms(fraction, np.array(ours["profile"][key + "_over_u2"]), m_fraction, values)
        result["%s_profile_rms_midspan" % key] = rms
        result["%s_profile_shift_pitch_fraction" % key] = shift
    with open(os.path.join(out, "impeller_outlet.yaml"), "w") as f:
        f.write("# The velocity at R/R2 = 1.02 over U2 = 43.98 m/s (the run's second half) against the ERCOFTAC\n"
                "# measurement (reference.yaml); errors are ours / measured - 1; profile RMS over U2.\n")
        yaml.safe_dump(result, f, sort_keys=False)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        for ax, key, values in ((axes[0], "cu", m_cu), (axes[1], "cr", m_cr)):
            shift = result["%s_profile_shift_pitch_fraction" % key]
            ax.plot(m_fraction, values, "k.", label="measured, midspan (4 instants)")
            ax.plot(np.mod(fraction + shift, 1.0), ours["profile"][key + "_over_u2"], "C0.", ms=3,
                    label="penalized impeller (shifted %.2f)" % shift)
            ax.set_xlabel("pitch fraction")
            ax.set_ylabel("c_%s / U2" % key[1])
            ax.legend(fontsize=8)
        fig.suptitle("ERCOFTAC pump, R/R2 = 1.02: c_u/U2 %.3f ours, %.3f midspan, %.3f span average"
                     % (ours["cu_over_u2"], measured["cu_over_u2_midspan"], measured["cu_over_u2_span_average"]))
        fig.tight_layout()
        fig.savefig(os.path.join(out, "impeller_outlet.png"), dpi=110)
    except ImportError:
        pass
    print("impeller_outlet.yaml: c_u/U2 = %.4f (measured %.3f midspan, %.3f span average: %+.1f %%, %+.1f %%), "
          "c_r against continuity %.3f" % (ours["cu_over_u2"], measured["cu_over_u2_midspan"],
                                          measured["cu_over_u2_span_average"],
                                          100 * result["cu_error_against_midspan"],
                                          100 * result["cu_error_against_span_average"], ours["cr_over_continuity"]))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit("usage: postprocess.py RESULTS_DIR CASE_DIR")
    main(sys.argv[1], sys.argv[2])
