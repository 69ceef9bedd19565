"""Copies and fingerprints of a case folder that leave its results behind, wherever a study writes
them: in the case's own output/ (the default), or in any folder the user gives with -o, which
may lie inside the case (`./fsi pump-curve -o CASE/curve CASE`). A copy that took such a folder
along would copy itself into itself, one point inside the last, until the disk is full; a
fingerprint that read it would change with every result and rerun every point."""

import os
import shutil

SKIPPED = ("output", "__pycache__")


def _real(path):
    return os.path.realpath(os.path.abspath(path))


def ignore_results(out_dirs, patterns=SKIPPED):
    """shutil.copytree's ignore: the names matching `patterns`, and every folder of `out_dirs`
    (a study's results) met on the way."""
    outs = {_real(o) for o in out_dirs}
    by_pattern = shutil.ignore_patterns(*patterns)

    def ignore(folder, names):
        skipped = set(by_pattern(folder, names))
        skipped.update(n for n in names if _real(os.path.join(folder, n)) in outs)
        return skipped
    return ignore


def case_files(case_dir, out_dirs=(), patterns=SKIPPED, skipped_files=()):
    """Every file of the case folder, sorted, but those under `patterns`' folders, under
    `out_dirs`, and those named in `skipped_files`."""
    outs = {_real(o) for o in out_dirs}
    paths = []
    for root, dirs, files in os.walk(case_dir, followlinks=False):
        dirs[:] = sorted(d for d in dirs if d not in patterns and _real(os.path.join(root, d)) not in outs)
        paths += [os.path.join(root, name) for name in sorted(files) if name not in skipped_files]
    return paths
