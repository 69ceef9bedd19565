#!/usr/bin/python3
"""Generates this case's pump (geometry/ from pump.yaml, then the openfoam-* folders) with the
centrifugal-pump case's prepare.py: the same generator, cache and stamps, without that case's
pump-curve variants (rans, coarse-gaps, the AMI reference).

    prepare.py CASE_DIR BIN_DIR     (python/fsi/fsi_launch.py runs it before every run of the case,
                                     with python/ on PYTHONPATH: also from a copy of the case)
"""

import sys

from fsi import case_module

# The repository's cases/centrifugal-pump/prepare.py (also for a copy of this case elsewhere).
prepare = case_module("centrifugal-pump", "prepare")

if __name__ == "__main__":
    sys.exit(prepare.main(sys.argv, pump_curve_variants=False))
