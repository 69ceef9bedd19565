#!/usr/bin/python3
"""Pictures of a coupled run's flow: |U| on a slice with the sheet drawn on top, one PNG for
each of (at most) four OpenFOAM times after 0, as in Figs. 4 and 12 of the paper.

Usage (ParaView's Python, no display needed):
    pvbatch --force-offscreen-rendering python/fsi/plot_flow.py OUT_DIR
            [--normal x|y|z] [--origin X Y Z] [--count N]
OUT_DIR is a run's output folder: OUT_DIR/openfoam (the OpenFOAM case; a decomposed one,
processor*/, is read as such) and, optional, OUT_DIR/structure.xdmf (+ structure.h5).
Writes OUT_DIR/flow_t<time>.png, <time> being the OpenFOAM time folder's name.
The slice goes through the sheet's centre (the domain's without a sheet); its normal is by
default z, or y when the sheet is thinnest in z, so that it cuts the sheet across the flow.
The colour range is that of |U| on the slices over all the pictured times.
ParaView reads the case (OpenFOAM reader) and the sheet (XDMF reader) and cuts the slice;
matplotlib (Agg) draws, since Debian's ParaView 5.11 renders only with an X server. So
/usr/bin/python3 runs it as well as pvbatch does.
Exits 1 with a message when OUT_DIR holds no OpenFOAM results (no time after 0 with U).
"""
import argparse
import glob
import math
import os
import re
import sys

AXES = {"x": 0, "y": 1, "z": 2}


def fail(message):
    sys.stderr.write("plot_flow.py: %s\n" % message)
    sys.exit(1)


def is_number(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def result_times(case_dir):
    """Time folders after 0 holding U, as (value, name), from the case or processor0."""
    roots = [case_dir]
    processors = sorted(d for d in os.listdir(case_dir)
                        if re.match(r"processor\d+$", d)
                        and os.path.isdir(os.path.join(case_dir, d)))
    if processors:
        roots.append(os.path.join(case_dir, processors[0]))
    best, decomposed = [], False
    for root in roots:
        times = sorted((float(d), d) for d in os.listdir(root)
                       if is_number(d) and float(d) > 0
                       and os.path.isfile(os.path.join(root, d, "U")))
        if len(times) > len(best):
            best, decomposed = times, root != case_dir
    return best, decomposed


def pick_evenly(items, count):
    if len(items) <= count:
        return list(items)
    if count == 1:
        return [items[-1]]
    return [items[round(i * (len(items) - 1) / (count - 1))] for i in range(count)]


def nearest(values, t):
    return min(values, key=lambda v: abs(v - t))


def parse_args(argv):
    p = argparse.ArgumentParser(prog="plot_flow.py", description=__doc__.split("\n\n")[0])
    p.add_argument("out_dir")
    p.add_argument("--normal", choices=sorted(AXES), help="slice normal (default z; y for a sheet thinnest in z)")
    p.add_argument("--origin", nargs=3, type=float, metavar=("X", "Y", "Z"),
                   help="a point of the slice (default: the sheet's centre)")
    p.add_argument("--count", type=int, default=4, help="most pictures (default 4)")
    return p.parse_args(argv)


def main(argv):
    args = parse_args(argv)
    out_dir = os.path.abspath(args.out_dir)
    case_dir = os.path.join(out_dir, "openfoam")
    if not os.path.isdir(case_dir):
        fail("%s has no OpenFOAM case (no openfoam/ folder)" % out_dir)
    times, decomposed = result_times(case_dir)
    if not times:
        fail("%s has no OpenFOAM results (no time folder after 0 with U)" % case_dir)
    times = pick_evenly(times, max(1, args.count))

    foam_file = os.path.join(case_dir, "case.foam")
    if not os.path.exists(foam_file):
        open(foam_file, "w").close()

    # Imported here so that --help and the checks above answer quickly. ParaView reads and
    # slices; matplotlib draws, as Debian's ParaView can render only with an X server.
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from matplotlib.ticker import FormatStrFormatter
    import numpy as np
    from paraview import simple as pv
    from vtkmodules.util.numpy_support import vtk_to_numpy

    fluid = pv.OpenFOAMReader(FileName=foam_file)
    fluid.CaseType = "Decomposed Case" if decomposed else "Reconstructed Case"
    fluid.MeshRegions = ["internalMesh"]
    fluid.CellArrays = ["U"]
    fluid.UpdatePipelineInformation()
    fluid_times = [float(v) for v in fluid.TimestepValues]
    if not fluid_times:
        fail("ParaView's OpenFOAM reader sees no time in %s" % case_dir)
    fluid.UpdatePipeline(fluid_times[-1])
    domain = fluid.GetDataInformation().GetBounds()

    sheet, sheet_times = None, []
    xdmf = os.path.join(out_dir, "structure.xdmf")
    if os.path.isfile(xdmf):
        sheet = pv.XDMFReader(FileNames=[xdmf])
        sheet.UpdatePipelineInformation()
        sheet_times = [float(v) for v in sheet.TimestepValues] or [0.0]
    else:
        sys.stderr.write("plot_flow.py: no structure.xdmf in %s; drawing the flow only\n"
                         % out_dir)

    def sheet_bounds(t):
        sheet.UpdatePipeline(t)
        return sheet.GetDataInformation().GetBounds()

    if args.normal:
        axis = AXES[args.normal]
    elif sheet is not None:
        b = sheet_bounds(sheet_times[0])
        thinnest = min(range(3), key=lambda k: b[2 * k + 1] - b[2 * k])
        axis = 1 if thinnest == 2 else 2
    else:
        axis = 2
    normal = [0.0, 0.0, 0.0]
    normal[axis] = 1.0

    def slice_origin(t_sheet):
        if args.origin:
            return list(args.origin)
        b = sheet_bounds(t_sheet) if sheet is not None else domain
        return [0.5 * (b[2 * k] + b[2 * k + 1]) for k in range(3)]

    cut = pv.Slice(Input=fluid)
    cut.SliceType = "Plane"
    cut.SliceType.Normal = normal
    cut.Triangulatetheslice = 0
    cut_at = pv.ForceTime(Input=pv.MergeBlocks(Input=cut))
    cut_at.IgnorePipelineTime = 1
    if sheet is not None:
        sheet_at = pv.ForceTime(Input=pv.MergeBlocks(Input=sheet))
        sheet_at.IgnorePipelineTime = 1

    u_axis, v_axis = {0: (1, 2), 1: (0, 2), 2: (0, 1)}[axis]

    def polygons(source):
        """(list of (n, 2) in-plane polygons, cell data) of a fetched unstructured grid."""
        data = pv.servermanager.Fetch(source)
        if data is None or data.GetNumberOfCells() == 0:
            return [], data
        xyz = vtk_to_numpy(data.GetPoints().GetData())[:, (u_axis, v_axis)]
        cells = data.GetCells()
        offsets = vtk_to_numpy(cells.GetOffsetsArray())
        connectivity = vtk_to_numpy(cells.GetConnectivityArray())
        return [xyz[connectivity[a:b]] for a, b in zip(offsets[:-1], offsets[1:])], data

    frames, low, high = [], math.inf, -math.inf
    for value, name in times:
        t_fluid = nearest(fluid_times, value)
        t_sheet = nearest(sheet_times, value) if sheet is not None else None
        origin = slice_origin(t_sheet)
        cut.SliceType.Origin = origin
        cut_at.ForcedTime = t_fluid
        cells, data = polygons(cut_at)
        u = data.GetCellData().GetArray("U") if cells else None
        if u is None:
            fail("no U on the slice at t = %s s (is the plane inside the domain?)" % name)
        speed = np.linalg.norm(vtk_to_numpy(u), axis=1)
        low, high = min(low, speed.min()), max(high, speed.max())
        sheet_cells = []
        if sheet is not None:
            sheet_at.ForcedTime = t_sheet
            sheet_cells, _ = polygons(sheet_at)
        frames.append((name, origin, cells, speed, sheet_cells))
    if not high > low:
        high = low + 1e-12

    names = "xyz"
    # Plain tick labels with the digits that tell the (often small) differences apart.
    digits = max(0, int(math.ceil(-math.log10(max(high - low, 1e-300)))) + 1)
    tick_format = "%%.%df" % min(digits, 12) if high < 1e4 else "%.4g"
    width_m = domain[2 * u_axis + 1] - domain[2 * u_axis]
    height_m = domain[2 * v_axis + 1] - domain[2 * v_axis]
    fig_w = 10.0
    fig_h = min(12.0, max(3.5, fig_w * 0.85 * height_m / max(width_m, 1e-30) + 1.6))
    for stale in glob.glob(os.path.join(out_dir, "flow_t*.png")):  # an earlier run's pictures
        os.remove(stale)
    for name, origin, cells, speed, sheet_cells in frames:
        fig, ax = plt.subplots(figsize=(fig_w, fig_h), dpi=120)
        flow = PolyCollection(cells, array=speed, cmap="viridis", edgecolors="face",
                              linewidths=0.2)
        flow.set_clim(low, high)
        ax.add_collection(flow)
        if sheet_cells:
            # Seen edge-on the faces are degenerate: the thick edges draw the sheet there.
            ax.add_collection(PolyCollection(sheet_cells, facecolors=(1.0, 0.16, 0.1, 0.6),
                                             edgecolors="#ff2a1a", linewidths=2.5,
                                             zorder=3, label="sheet"))
            ax.legend(loc="upper right", fontsize=9, framealpha=0.8)
        ax.set_xlim(domain[2 * u_axis], domain[2 * u_axis + 1])
        ax.set_ylim(domain[2 * v_axis], domain[2 * v_axis + 1])
        ax.set_aspect("equal")
        ax.set_xlabel("%s (m)" % names[u_axis])
        ax.set_ylabel("%s (m)" % names[v_axis])
        ax.set_title("|U| on the plane %s = %.4g m, t = %s s"
                     % (names[axis], origin[axis], name))
        bar = fig.colorbar(flow, ax=ax, orientation="horizontal", fraction=0.08, pad=0.14,
                           aspect=40, shrink=0.8, format=FormatStrFormatter(tick_format))
        bar.set_label("|U| (m/s)")
        fig.tight_layout()
        png = os.path.join(out_dir, "flow_t%s.png" % name)
        fig.savefig(png)
        plt.close(fig)
        print("picture: %s" % png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
