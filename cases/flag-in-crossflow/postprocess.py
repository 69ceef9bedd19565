#!/usr/bin/python3
"""After a run of flag-in-crossflow (./fsi run calls it): the flapping frequency, St_L and
amplitude of the trailing edge (flapping.py), printed and written to flapping.txt in the
results folder. Usage: postprocess.py RESULTS_DIR CASE_DIR"""

import os
import subprocess
import sys


def main(out, case_dir):
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "flapping.py")
    result = subprocess.run([sys.executable, script, out], capture_output=True, text=True)
    text = (result.stdout or result.stderr).strip()
    with open(os.path.join(out, "flapping.txt"), "w") as f:
        f.write(text + "\n")
    print("flapping.txt: %s" % text.splitlines()[-1] if text else "flapping.txt")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
