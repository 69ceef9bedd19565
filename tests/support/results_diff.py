"""Comparing the results of two runs bit for bit, for the integration tests (restart, security,
network, cluster, soak): every dataset of the HDF5 files but coupling.h5's wall-clock /timings
(measurements, not results), and other files byte for byte."""

import os

import h5py
import numpy


def datasets(h5_path):
    """Every dataset but the wall-clock timings (coupling.h5's /timings: measurements, not results)."""
    found = {}
    with h5py.File(h5_path, "r") as f:
        f.visititems(lambda name, obj: found.__setitem__(name, obj[()])
                     if isinstance(obj, h5py.Dataset) and not name.startswith("timings/") else None)
    return found


def differences(a_dir, b_dir, files=("structure.h5", "probes.csv", "structure.xdmf")):
    """What differs between two results folders, bit for bit (empty: the same)."""
    found = []
    for h5 in (f for f in files if f.endswith(".h5")):
        a, b = datasets(os.path.join(a_dir, h5)), datasets(os.path.join(b_dir, h5))
        if sorted(a) != sorted(b):
            found.append("%s: datasets %s vs %s" % (h5, sorted(a), sorted(b)))
        for name in sorted(set(a) & set(b)):
            x, y = numpy.asarray(a[name]), numpy.asarray(b[name])
            if x.shape != y.shape or x.tobytes() != y.tobytes():
                found.append("%s %s: shapes %s %s, %s" % (h5, name, x.shape, y.shape,
                                                          "max |diff| %.3g" % numpy.max(numpy.abs(x - y))
                                                          if x.shape == y.shape and x.dtype.kind == "f" else "differ"))
    for name in (f for f in files if not f.endswith(".h5")):
        with open(os.path.join(a_dir, name), "rb") as f, open(os.path.join(b_dir, name), "rb") as g:
            if f.read() != g.read():
                found.append(name)
    return found
