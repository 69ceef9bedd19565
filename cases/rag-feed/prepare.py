#!/usr/bin/python3
"""Generates this case's pump: the pump of cases/rag-in-pump (its pump.yaml, copied here so that
the feed always runs in the rag study's pump), then geometry/ and the openfoam-* folders with the
centrifugal-pump case's prepare.py (the same generator, cache and stamps). A pump.yaml of your
own in the case folder (one without the first line this script writes) is kept: the feed then
runs in that pump (./fsi feed-compare writes one per design).

    prepare.py CASE_DIR BIN_DIR     (python/fsi/fsi_launch.py runs it before every run of the case,
                                     with python/ on PYTHONPATH: also from a copy of the case)
"""

import os
import sys

from fsi import ROOT, case_module

# The repository's cases/centrifugal-pump/prepare.py (also for a copy of this case elsewhere).
prepare = case_module("centrifugal-pump", "prepare")
MARK = b"# Copied from cases/rag-in-pump/pump.yaml by prepare.py before every run (your own pump.yaml: without this line)\n"


def main(argv):
    if len(argv) != 3:
        sys.exit("usage: prepare.py CASE_DIR BIN_DIR")
    source = os.path.join(ROOT, "cases", "rag-in-pump", "pump.yaml")
    target = os.path.join(argv[1], "pump.yaml")
    if not os.path.isfile(source):
        sys.exit("prepare.py: %s: no such file (the rag study's pump, which the feed runs in)" % source)
    with open(source, "rb") as f:
        design = MARK + f.read()
    own = os.path.isfile(target) and not open(target, "rb").read().startswith(MARK)
    if not own and (not os.path.isfile(target) or open(target, "rb").read() != design):
        with open(target + ".partial", "wb") as f:
            f.write(design)
        os.replace(target + ".partial", target)
    status = prepare.main(argv, pump_curve_variants=False)
    # The OpenFOAM folders are generated with the geometry; written again when one is missing.
    if not status and not all(os.path.isdir(os.path.join(argv[1], "openfoam-" + r)) for r in ("coarse", "medium", "fine")):
        import subprocess
        made = subprocess.run([sys.executable, os.path.join(ROOT, "cases", "centrifugal-pump", "make_case.py"),
                               argv[1], "--resolutions-only"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        if made.returncode != 0:
            sys.exit("prepare.py: make_case.py failed:\n%s" % made.stdout.decode(errors="replace").strip())
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
