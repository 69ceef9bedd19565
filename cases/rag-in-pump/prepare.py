#!/usr/bin/python3
"""Generates this case's pump (geometry/ from pump.yaml, then the openfoam-* folders) with the
centrifugal-pump case's prepare.py: the same generator, cache and stamps, without that case's
pump-curve variants (rans, coarse-gaps, the AMI reference).

    prepare.py CASE_DIR BIN_DIR     (scripts/fsi_launch.py runs it before every run of the case,
                                     with scripts/ on PYTHONPATH: also from a copy of the case)
"""

import os
import sys

import fsi_launch  # noqa: E402  (scripts/, on PYTHONPATH)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(fsi_launch.__file__))),
                                "cases", "centrifugal-pump"))
import prepare  # noqa: E402

if __name__ == "__main__":
    sys.exit(prepare.main(sys.argv, pump_curve_variants=False))
