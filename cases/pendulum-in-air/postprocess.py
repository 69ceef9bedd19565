#!/usr/bin/python3
"""After a run of pendulum-in-air (./fsi run calls it): the free-edge centre relative to the
rigid bar (the paper's Figs. 2-3, normal and longitudinal) and the flag's kinetic energy
relative to the bar, from free_edge.py: free_edge.png and free_edge.txt in the results folder;
and the flow pictures (flow_t*.png) redrawn on the plane of the swing (normal y), as in Fig. 4.
For the comparison with vacuum, run free_edge.py OUT VACUUM_OUT (README.md).
Usage: postprocess.py RESULTS_DIR CASE_DIR"""

import os
import subprocess
import sys


def main(out, case_dir):
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "free_edge.py")
    result = subprocess.run([sys.executable, script, out, "--png", os.path.join(out, "free_edge.png")],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(result.stderr.strip().splitlines()[-1] if result.stderr.strip() else "free_edge.py failed")
    with open(os.path.join(out, "free_edge.txt"), "w") as f:
        f.write(result.stdout)
    made = ["free_edge.png", "free_edge.txt"]
    if os.path.isdir(os.path.join(out, "openfoam")):
        plot_flow = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "fsi", "plot_flow.py")
        if subprocess.run([sys.executable, plot_flow, out, "--normal", "y"], capture_output=True).returncode == 0:
            made.append("flow_t*.png (plane of the swing)")
    print(", ".join(made))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
