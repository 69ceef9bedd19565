# Opens an XDMF index with both ParaView readers and checks what they show against the values
# the test wrote. Run by ParaViewOpenTest.cpp:
#   pvbatch --force-offscreen-rendering paraview_open_check.py INDEX.xdmf EXPECTED.json
# EXPECTED.json: {"times": [t...], "steps": [{"time": t, "blocks": [{"points": [[x, y, z]...],
#                 "velocities": [[vx, vy, vz]...], "n_cells": n}...]}...]}
# Each reader opens the index from an absolute path, a path relative to the working folder and a
# file name in the index's own folder; prints one line per check and exits 1 on any mismatch.
#
# Not checked: Xdmf3 given a bare file name ("run.xdmf"). ParaView 5.11's Xdmf3 appends the HDF5
# reference to the index path up to its last '/', so it opens "run.xdmfrun.h5" and aborts; only
# an absolute reference in the index would avoid that. "./run.xdmf" works and is checked.

import json
import os
import sys

from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

VELOCITY = "velocity_m_per_s"
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def close(a, b, tolerance=1e-12):
    return len(a) == len(b) and all(abs(x - y) <= tolerance * (1.0 + abs(y)) for x, y in zip(a, b))


def leaves(data):
    iterator = data.NewIterator()
    iterator.InitTraversal()
    while not iterator.IsDoneWithTraversal():
        yield iterator.GetCurrentDataObject()
        iterator.GoToNextItem()


def flat(rows):
    return [value for row in rows for value in row]


def expected_bounds(blocks):
    points = [p for block in blocks for p in block["points"]]
    bounds = []
    for c in range(3):
        bounds += [min(p[c] for p in points), max(p[c] for p in points)]
    return bounds


def check_step(reader, label, step):
    reader.UpdatePipeline(step["time"])
    label = "%s t=%g" % (label, step["time"])
    blocks = step["blocks"]
    info = reader.GetDataInformation()
    n_points = sum(len(b["points"]) for b in blocks)
    n_cells = sum(b["n_cells"] for b in blocks)
    check(info.GetNumberOfPoints() == n_points,
          "%s: %d points (expected %d)" % (label, info.GetNumberOfPoints(), n_points))
    check(info.GetNumberOfCells() == n_cells,
          "%s: %d cells (expected %d)" % (label, info.GetNumberOfCells(), n_cells))
    check(close(info.GetBounds(), expected_bounds(blocks)),
          "%s: bounds %s" % (label, list(info.GetBounds())))
    check(VELOCITY in reader.PointData.keys(),
          "%s: point arrays %s" % (label, list(reader.PointData.keys())))
    shown = list(leaves(reader.GetClientSideObject().GetOutputDataObject(0)))
    check(len(shown) == len(blocks), "%s: %d blocks" % (label, len(shown)))
    for index, (data, block) in enumerate(zip(shown, blocks)):
        points = data.GetPoints()
        points = vtk_to_numpy(points.GetData()).ravel().tolist() if points else []
        check(close(points, flat(block["points"])), "%s: block %d positions" % (label, index))
        velocities = data.GetPointData().GetArray(VELOCITY)
        velocities = vtk_to_numpy(velocities).ravel().tolist() if velocities else []
        check(close(velocities, flat(block["velocities"])),
              "%s: block %d velocities" % (label, index))


def check_reader(kind, how, working_folder, path, expected):
    os.chdir(working_folder)  # the readers read lazily: stay here until the checks are done
    label = "%s, %s path %r" % (kind, how, path if how != "absolute" else os.path.basename(path))
    if kind == "Xdmf3":
        reader = simple.OpenDataFile(path)
        check(reader.GetXMLName().startswith("Xdmf3"),
              "%s: OpenDataFile picked %s" % (label, reader.GetXMLName()))
    else:
        reader = simple.XDMFReader(FileNames=[path])
    check(close(list(reader.TimestepValues), expected["times"]),
          "%s: times %s" % (label, list(reader.TimestepValues)))
    for step in expected["steps"]:
        check_step(reader, label, step)
    simple.Delete(reader)


def main():
    index = os.path.abspath(sys.argv[1])
    with open(sys.argv[2]) as file:
        expected = json.load(file)
    folder, name = os.path.split(index)
    parent, folder_name = os.path.split(folder)
    for kind in ("Xdmf3", "legacy"):
        check_reader(kind, "absolute", "/", index, expected)
        check_reader(kind, "relative", parent, os.path.join(folder_name, name), expected)
        check_reader(kind, "own folder", folder, "./" + name, expected)
    check_reader("legacy", "own folder", folder, name, expected)
    print("%d failed checks" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
