#!/usr/bin/python3
"""After a run of rotating-disc (./fsi run calls it): the torque on the whole disc (the wedge's
times 360 / 5), its moment coefficient C_M = 2 |M| / (rho omega^2 R^5) over the last 20 % of
the run, and the references of its regime (python/fsi/rotating_disc.py), printed and written to
torque.yaml in the results folder. Usage: postprocess.py RESULTS_DIR CASE_DIR"""

import os
import sys

import yaml

from fsi import rotating_disc


def main(out, _case_dir):
    disc, config = rotating_disc.disc_of_run(out)
    mean, spread = rotating_disc.window_mean(rotating_disc.penalized_torque(out))
    scale = disc.torque_scale_n_m()
    result = {"torque_n_m": -mean, "torque_std_n_m": spread, "cm": -mean / scale, "reynolds": disc.reynolds,
              "gap_ratio": disc.gap_ratio, "immersed_wall_model": config["fluid"]["openfoam"].get("immersed_wall_model",
                                                                                              "none")}
    result.update(rotating_disc.references(disc))
    ref_key = "cm_faces_and_rim" if "cm_faces_and_rim" in result else "cm_regime_IV"
    result["cm_over_reference"] = result["cm"] / result[ref_key]
    with open(os.path.join(out, "torque.yaml"), "w") as f:
        f.write("# The torque of the fluid on the disc (its magnitude; it brakes the disc) over the last 20 % of the\n"
                "# run, whole disc; C_M = 2 |M| / (rho omega^2 R^5); references: python/fsi/rotating_disc.py.\n")
        yaml.safe_dump(result, f, sort_keys=False)
    print("torque.yaml: |M| = %.4g N m, C_M = %.4g (Re = %.3g, %s; %s = %.4g, ratio %.3f)"
          % (-mean, result["cm"], disc.reynolds, result["regime"], ref_key, result[ref_key], result["cm_over_reference"]))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
