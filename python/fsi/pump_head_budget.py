#!/usr/bin/python3
"""Where a pump's head is made and lost: the mass-flow-averaged total pressure
p_t = p + rho |U|^2 / 2 (absolute frame) at stations along the flow path of one OpenFOAM time
of a pump run: the suction pipe's middle (plane normal to the axis), the impeller's outlet (the
cylinder halfway between D2 / 2 and the volute's base circle), the volute (the cylinder at 1.1
times the base radius) and the discharge pipe's middle (plane normal to x); and the front side
space (the cylinder halfway between the eye's rim and D2 / 2, below the shroud: the leak from
the volute back to the eye, inwards positive). Each is the slab of cells within half their own
size of the section, weighted by u_n V / h (its volume flow, h = V^(1/3)): an estimate,
not an exact surface integral, which the flow rate it finds (beside the imposed one) shows.
It is the budget of one instant, not a time average: where the suction side's pressure swings
from step to step (on the pump with body_normal interfaces by +-31 kPa at the inlet, with the
AMI reference by +-16 kPa) one instant says where the head goes, not how much there is; the
operating point's H (the function objects, every step, averaged) is the measure.
Reads the case with ParaView's OpenFOAM reader (python3-paraview; no display needed).

    pump_head_budget.py FOAM_CASE PUMP_YAML [--time T]     (default: the latest time after 0)

From Python: head_budget(foam_case, design, time=None) -> list of dicts (station, flow rate
m^3/s, total pressure Pa, head above the suction station m).
"""
import argparse
import os
import re
import sys

import numpy as np
import yaml

RHO, G = 1000.0, 9.81


def latest_time(foam_case):
    times = [d for d in os.listdir(foam_case) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0
             and os.path.isfile(os.path.join(foam_case, d, "U"))]
    if not times:
        raise ValueError("%s has no time folder after 0 with U" % foam_case)
    return max(times, key=float)


def cell_fields(foam_case, time):
    """Cell centres (m), velocity (m/s), kinematic pressure (m^2/s^2) and volumes (m^3)."""
    from paraview import simple, servermanager
    from vtk.util.numpy_support import vtk_to_numpy
    marker = os.path.join(foam_case, "case.foam")
    open(marker, "a").close()
    reader = simple.OpenFOAMReader(FileName=marker)
    reader.MeshRegions = ["internalMesh"]
    reader.CellArrays = ["U", "p"]
    reader.UpdatePipeline(float(time))

    def fetch(source):
        data = servermanager.Fetch(source)
        return data.GetBlock(0) if data.IsA("vtkMultiBlockDataSet") else data
    centres = simple.CellCenters(Input=reader)
    centres.UpdatePipeline(float(time))
    c = fetch(centres)
    sizes = simple.CellSize(Input=reader)
    sizes.ComputeVolume = 1
    sizes.UpdatePipeline(float(time))
    v = fetch(sizes)
    return (vtk_to_numpy(c.GetPoints().GetData()), vtk_to_numpy(c.GetPointData().GetArray("U")),
            vtk_to_numpy(c.GetPointData().GetArray("p")), vtk_to_numpy(v.GetCellData().GetArray("Volume")))


def head_budget(foam_case, design, time=None):
    time = time or latest_time(foam_case)
    x, u, p, vol = cell_fields(foam_case, time)
    pt = RHO * (p + 0.5 * (u ** 2).sum(1))
    h = np.cbrt(vol)  # each cell's own size: a graded mesh (the AMI's 2 mm gaps in 8 mm cubes) has several
    r = np.hypot(x[:, 0], x[:, 1])
    u_r = (u[:, 0] * x[:, 0] + u[:, 1] * x[:, 1]) / np.maximum(r, 1e-12)
    imp, vol_, inlet = design["impeller"], design["volute"], design["inlet"]
    r2, r3 = 0.5 * imp["outer_diameter_m"], vol_["base_radius_m"]
    z_lo, z_hi = 0.5 * (imp["outlet_width_m"] - vol_["base_width_m"]), 0.5 * (imp["outlet_width_m"] + vol_["base_width_m"])
    in_chamber = (x[:, 2] > z_lo) & (x[:, 2] < z_hi)
    r_side = 0.5 * (0.5 * imp["eye_diameter_m"] + r2)
    stations = [
        ("suction pipe", np.abs(x[:, 2] - (z_lo - 0.5 * inlet["suction_pipe_length_m"])) < 0.5 * h, u[:, 2]),
        ("impeller outlet", (np.abs(r - 0.5 * (r2 + r3)) < 0.5 * h) & in_chamber, u_r),
        ("volute", (np.abs(r - 1.1 * r3) < 0.5 * h) & in_chamber, u_r),
        ("discharge pipe", np.abs(x[:, 0] - (x[:, 0].max() - 0.5 * vol_["discharge_length_m"])) < 0.5 * h, u[:, 0]),
        # The leak back to the eye between the shroud (z < 0) and the casing: inwards positive.
        ("front side space", (np.abs(r - r_side) < 0.5 * h) & (x[:, 2] < 0) & (x[:, 2] > z_lo - 0.5 * h), -u_r),
    ]
    rows = []
    for name, mask, normal in stations:
        flux = normal[mask] * vol[mask] / h[mask]
        q = float(flux.sum())
        rows.append({"station": name, "flow_rate_m3_per_s": q,
                     "total_pressure_pa": float((pt[mask] * flux).sum() / q) if q else float("nan")})
    for row in rows:
        row["head_above_suction_m"] = (row["total_pressure_pa"] - rows[0]["total_pressure_pa"]) / (RHO * G)
    return rows


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("foam_case")
    parser.add_argument("pump_yaml")
    parser.add_argument("--time", default=None)
    args = parser.parse_args(argv)
    with open(args.pump_yaml) as f:
        design = yaml.safe_load(f)
    for row in head_budget(args.foam_case, design, args.time):
        print("%-16s Q = %.4g m^3/s  p_t = %9.0f Pa  head above the suction: %6.2f m"
              % (row["station"], row["flow_rate_m3_per_s"], row["total_pressure_pa"], row["head_above_suction_m"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
