#!/usr/bin/python3
"""Where along an impeller's channel the work is lost: the rothalpy I = p + w^2/2 - u^2/2 (as a
head, m), mass-averaged over the relative flow through half-planes through the axis, every STEP
degrees round the impeller, with that flow (net, forwards and backwards). In a steady relative flow
the rothalpy of the water is constant but for losses; where the relative flow through the planes
is constant (a channel's spiral), its fall is the channel's loss.

Usage (ParaView's Python modules, no display):
    /usr/bin/python3 python/fsi/pump_channel_budget.py FOAM_CASE PUMP_YAML [--step 20] [-o OUT_PREFIX]
FOAM_CASE: a turning-mesh run of the pump (the AMI reference, python/fsi/pump_ami_run.py), read at
its latest time; its constant/dynamicMeshDict gives omega and the axis (z through the origin).
PUMP_YAML: the design (impeller.outer_diameter_m, outlet_width_m): the planes are cut to r < R2
and 0 < z < b2, the channel between the discs. Angles are the impeller's, about +z from its +x
axis (the mesh's turn at that time taken off). Writes OUT_PREFIX.csv and OUT_PREFIX.png (default
FOAM_CASE/../channel_budget), and OUT_PREFIX_midplane.png: the rothalpy and the relative velocity on
the plane z = b2 / 2 inside D2, in the impeller's frame (where the channel loses it, as a map).
Exits 1 with a message for a case without fields or a design
without those keys.
"""
import argparse
import math
import os
import re
import sys

import numpy as np
import yaml

G = 9.81


def fail(message):
    sys.stderr.write("pump_channel_budget.py: %s\n" % message)
    sys.exit(1)


def rotation(foam_case):
    """(omega about +z in rad/s, signed by the axis) from constant/dynamicMeshDict."""
    path = os.path.join(foam_case, "constant", "dynamicMeshDict")
    if not os.path.isfile(path):
        fail("%s: no constant/dynamicMeshDict (not a turning-mesh run)" % foam_case)
    with open(path) as f:
        text = f.read()
    omega = re.search(r"^omega\s+([^;]+);", text, re.M)
    axis = re.search(r"^axis\s+\(([^)]*)\)", text, re.M)
    if not omega or not axis:
        fail("%s: no omega or axis entry" % path)
    a = [float(v) for v in axis.group(1).split()]
    if abs(a[0]) > 1e-9 or abs(a[1]) > 1e-9:
        fail("%s: axis %s is not along z" % (path, a))
    return float(omega.group(1)) * math.copysign(1.0, a[2])


def channel(pump_yaml):
    with open(pump_yaml) as f:
        design = yaml.safe_load(f)
    try:
        return 0.5 * float(design["impeller"]["outer_diameter_m"]), float(design["impeller"]["outlet_width_m"])
    except (KeyError, TypeError) as error:
        fail("%s: no impeller.%s" % (pump_yaml, error))


def open_case(foam_case):
    """ParaView's reader of the case and its latest time after 0."""
    from paraview import simple
    reader = simple.OpenFOAMReader(FileName=os.path.join(foam_case, "case.foam"))
    reader.MeshRegions = ["internalMesh"]
    reader.CellArrays = ["U", "p"]
    reader.UpdatePipelineInformation()
    times = [t for t in reader.TimestepValues if t > 0] if reader.TimestepValues else []
    if not times:
        fail("%s: no time after 0 with fields" % foam_case)
    return reader, times[-1]


def cut_cells(reader, t, origin, normal, triangulate):
    """The cells a plane cuts at time t: the centres of their cut polygons (m), the polygons' areas
    (m^2) and the cells' U and p, or None where the plane cuts none. Untriangulated, a cut hex's
    polygon has the cell's own centre where the plane passes through it."""
    from paraview import servermanager
    from paraview import simple
    from vtk.util.numpy_support import vtk_to_numpy
    cut = simple.Slice(Input=reader)
    cut.Triangulatetheslice = 1 if triangulate else 0
    cut.SliceType.Origin = list(origin)
    cut.SliceType.Normal = list(normal)
    centres = simple.CellCenters(Input=simple.CellSize(Input=simple.MergeBlocks(Input=cut)))
    centres.VertexCells = 1
    centres.UpdatePipeline(t)
    data = servermanager.Fetch(centres)
    simple.Delete(centres)
    if data.GetNumberOfPoints() == 0:
        return None
    arrays = data.GetPointData()
    return (vtk_to_numpy(data.GetPoints().GetData()), vtk_to_numpy(arrays.GetArray("Area")),
            vtk_to_numpy(arrays.GetArray("U")), vtk_to_numpy(arrays.GetArray("p")))


def midplane(reader, t, omega_z, r2, z):
    """The cells cut by the plane at height z inside r2, in the impeller's frame: (x, y) of their
    centres (m), the relative velocity's (w_x, w_y) (m/s) and the rothalpy as a head (m)."""
    cells = cut_cells(reader, t, (0.0, 0.0, z), (0.0, 0.0, 1.0), triangulate=False)
    if cells is None:
        return None
    x, _, u, p = cells
    w = u - omega_z * np.column_stack([-x[:, 1], x[:, 0], np.zeros(len(x))])
    rothalpy = (p + 0.5 * (w ** 2).sum(axis=1) - 0.5 * omega_z ** 2 * (x[:, 0] ** 2 + x[:, 1] ** 2)) / G
    back = -omega_z * t                                       # the impeller's frame: the turn taken off
    c, s = math.cos(back), math.sin(back)
    turn = np.array([[c, -s], [s, c]])
    xy, wxy = x[:, :2] @ turn.T, w[:, :2] @ turn.T
    keep = np.hypot(xy[:, 0], xy[:, 1]) < r2
    return xy[keep], wxy[keep], rothalpy[keep]


def draw_midplane(path, plane, t, r2, z):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    xy, wxy, rothalpy = plane
    fig, ax = plt.subplots(figsize=(8, 7))
    low, high = np.percentile(rothalpy, [2, 98])
    shown = ax.scatter(xy[:, 0], xy[:, 1], c=rothalpy, s=4, cmap="coolwarm", vmin=low, vmax=high)
    fig.colorbar(shown, ax=ax, label="rothalpy p + w^2/2 - u^2/2 as a head (m)")
    every = max(1, len(xy) // 600)
    ax.quiver(xy[::every, 0], xy[::every, 1], wxy[::every, 0], wxy[::every, 1], width=0.002)
    ax.add_patch(matplotlib.patches.Circle((0, 0), r2, fill=False, ls="--"))
    ax.set_aspect("equal")
    ax.set_xlabel("x, the impeller's (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("z = %.3g m at t = %.4g s: relative velocity (arrows) and rothalpy" % (z, t))
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def budget(reader, t, omega_z, r2, b2, step_deg):
    turned = omega_z * t
    rows = []
    for theta in np.arange(0.0, 360.0, step_deg):
        a = math.radians(theta) + turned                     # the impeller's theta in the lab at t
        er, et = np.array([math.cos(a), math.sin(a), 0.0]), np.array([-math.sin(a), math.cos(a), 0.0])
        cells = cut_cells(reader, t, (0.0, 0.0, 0.0), et, triangulate=True)
        if cells is None:
            continue
        x, area, u, p = cells
        radius = x @ er
        keep = (radius > 0) & (radius < r2 - 5e-4) & (x[:, 2] > 5e-4) & (x[:, 2] < b2 - 5e-4)
        x, area, u, p, radius = x[keep], area[keep], u[keep], p[keep], radius[keep]
        blade = omega_z * radius                               # the wall's speed along e_theta
        w = u - np.outer(blade, et)
        flux = (w @ et) * area                                  # m^3/s through the half-plane, +: along +theta
        net = flux.sum()
        rothalpy = (p + 0.5 * (w ** 2).sum(axis=1) - 0.5 * blade ** 2) / G
        rows.append((theta, net, flux[flux > 0].sum(), -flux[flux < 0].sum(),
                     (rothalpy * flux).sum() / net if abs(net) > 1e-5 else float("nan")))
    return np.array(rows)


def main(argv):
    parser = argparse.ArgumentParser(prog="pump_channel_budget.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("foam_case")
    parser.add_argument("pump_yaml")
    parser.add_argument("--step", type=float, default=20.0, help="degrees between the half-planes")
    parser.add_argument("-o", "--output", help="prefix of the .csv and .png (default FOAM_CASE/../channel_budget)")
    args = parser.parse_args(argv)
    if not 0 < args.step <= 90:
        fail("--step %g: between 0 and 90 degrees" % args.step)
    foam_case = os.path.abspath(args.foam_case)
    out = args.output or os.path.join(os.path.dirname(foam_case), "channel_budget")
    omega_z = rotation(foam_case)
    r2, b2 = channel(args.pump_yaml)
    reader, t = open_case(foam_case)
    rows = budget(reader, t, omega_z, r2, b2, args.step)
    with open(out + ".csv", "w") as f:
        f.write("# %s at t = %g s: half-planes through the axis at the impeller's theta (deg, about +z), r < %g m, "
                "0 < z < %g m; relative flow (m^3/s) and its mass-averaged rothalpy p + w^2/2 - u^2/2 as a head (m)\n"
                % (foam_case, t, r2, b2))
        f.write("theta_deg,net_flow_m3_per_s,forward_flow_m3_per_s,backward_flow_m3_per_s,rothalpy_head_m\n")
        for row in rows:
            f.write("%g,%.6g,%.6g,%.6g,%.4f\n" % tuple(row))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    ax[0].plot(rows[:, 0], rows[:, 4], "o-")
    ax[0].set_ylabel("rothalpy, mass-averaged (m)")
    ax[0].set_title("Along the channel at t = %.4g s" % t)
    ax[1].plot(rows[:, 0], 1000 * rows[:, 1], "o-", label="net")
    ax[1].plot(rows[:, 0], 1000 * rows[:, 2], label="along +theta")
    ax[1].plot(rows[:, 0], 1000 * rows[:, 3], label="against")
    ax[1].set_ylabel("relative flow through the half-plane (L/s)")
    ax[1].set_xlabel("theta, the impeller's (deg)")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig(out + ".png", dpi=90)
    plane = midplane(reader, t, omega_z, r2, 0.5 * b2)
    if plane is not None:
        draw_midplane(out + "_midplane.png", plane, t, r2, 0.5 * b2)
    print("pump_channel_budget.py: %s.csv, %s.png, %s_midplane.png (%d half-planes, t = %g s)" % (out, out, out, len(rows), t))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
