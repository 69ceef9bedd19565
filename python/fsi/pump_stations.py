#!/usr/bin/python3
"""The head budget's stations of a generated pump as surfaces that OpenFOAM samples every step
(every make_ami_case.STATION_INTERVAL steps where the cells turn: function_objects):
closed-form triangulations (binary STL) of the planes and cylinder bands of
python/fsi/pump_head_budget.py, and the controlDict function objects that integrate the flow
rate through each and the flow-weighted total pressure over it, so that the head budget and the
front side space's leak are averaged over the same revolutions as the head and the torque
(python/fsi/pump_point.py), in the penalized runs and in the AMI reference alike.

Stations (SI; the design's keys, pump.yaml; normals give the sign of the flow rate):
  suction_pipe        the plane halfway along the suction pipe, +z (towards the impeller)
  impeller_outlet     the cylinder r = (r2 + r3) / 2 over the volute chamber's width, +r
  volute              the cylinder r = 1.1 r3 over the chamber's width, +r
  discharge_pipe      the plane halfway along the discharge pipe, +x
  front_side_space    the cylinder r = (r_eye + r2) / 2 from the chamber's floor to the shroud's
                      inner plane (z < 0), -r: the leak back to the eye, inward positive
Triangles outside the fluid are dropped by OpenFOAM (sampledTriSurfaceMesh, source insideCells);
each takes the value of the cell that holds its centre. The surfaces are sampled by a
`surfaces` function object that stores them (re-found after every mesh motion: the AMI's rotor
cells move) and integrated by one surfaceFieldValue per station and quantity.

    pump_stations.py CASE_DIR      writes CASE_DIR/geometry/stations/<station>.stl
"""

import math
import os
import shutil
import struct
import sys

import numpy as np
import yaml

from fsi.foam_case import field_value_function

SPACING_M = 0.003   # the triangles' size: under the 4 mm cells round the impeller, so that each cell is seen

STATIONS = ("suction_pipe", "impeller_outlet", "volute", "discharge_pipe", "front_side_space")


def cylinder_band(radius, z0, z1, spacing, inward=False):
    """Triangles of the side of a cylinder about z (no caps), about `spacing` apart."""
    n_t = max(12, int(math.ceil(2 * math.pi * radius / spacing)))
    n_z = max(1, int(math.ceil((z1 - z0) / spacing)))
    t = np.linspace(0.0, 2 * math.pi, n_t + 1)
    z = np.linspace(z0, z1, n_z + 1)
    tris = []
    for i in range(n_t):
        for j in range(n_z):
            a = (radius * math.cos(t[i]), radius * math.sin(t[i]), z[j])
            b = (radius * math.cos(t[i + 1]), radius * math.sin(t[i + 1]), z[j])
            c = (radius * math.cos(t[i + 1]), radius * math.sin(t[i + 1]), z[j + 1])
            d = (radius * math.cos(t[i]), radius * math.sin(t[i]), z[j + 1])
            # Counter-clockwise seen from outside: the normal points out (+r).
            quad = [(a, b, c), (a, c, d)]
            tris += [(p, r, q) for p, q, r in quad] if inward else quad
    return np.array(tris)


def rectangle(origin, u, v, nu, nv):
    """Triangles of the parallelogram origin + s u + t v (s, t in [0, 1]); normal u x v."""
    o, u, v = (np.asarray(x, float) for x in (origin, u, v))
    tris = []
    for i in range(nu):
        for j in range(nv):
            a = o + u * i / nu + v * j / nv
            b = o + u * (i + 1) / nu + v * j / nv
            c = o + u * (i + 1) / nu + v * (j + 1) / nv
            d = o + u * i / nu + v * (j + 1) / nv
            tris += [(a, b, c), (a, c, d)]
    return np.array(tris)


def station_triangles(design, bounds, spacing):
    """{station: (n, 3, 3) triangles} of a design (pump.yaml) in a casing of bounding box
    `bounds` ((lo xyz), (hi xyz)), triangles about `spacing` apart."""
    imp, vol, inlet = design["impeller"], design["volute"], design["inlet"]
    r2, r3 = 0.5 * imp["outer_diameter_m"], vol["base_radius_m"]
    z_lo, z_hi = 0.5 * (imp["outlet_width_m"] - vol["base_width_m"]), 0.5 * (imp["outlet_width_m"] + vol["base_width_m"])
    lo, hi = (np.asarray(b, float) for b in bounds)
    r_pipe = 0.5 * inlet["suction_pipe_diameter_m"] * 1.02
    z_pipe = z_lo - 0.5 * inlet["suction_pipe_length_m"]
    x_discharge = hi[0] - 0.5 * vol["discharge_length_m"]
    z_mid, d = 0.5 * (z_lo + z_hi), vol["discharge_diameter_m"]
    n = lambda length: max(1, int(math.ceil(length / spacing)))  # noqa: E731
    return {
        "suction_pipe": rectangle((-r_pipe, -r_pipe, z_pipe), (2 * r_pipe, 0, 0), (0, 2 * r_pipe, 0),
                                  n(2 * r_pipe), n(2 * r_pipe)),
        "impeller_outlet": cylinder_band(0.5 * (r2 + r3), z_lo, z_hi, spacing),
        "volute": cylinder_band(1.1 * r3, z_lo, z_hi, spacing),
        "discharge_pipe": rectangle((x_discharge, lo[1], z_mid - 0.6 * d), (0, hi[1] - lo[1], 0), (0, 0, 1.2 * d),
                                    n(hi[1] - lo[1]), n(1.2 * d)),
        "front_side_space": cylinder_band(0.5 * (0.5 * imp["eye_diameter_m"] + r2), z_lo, 0.0, spacing, inward=True),
    }


def write_binary_stl(path, triangles, name):
    tri = np.asarray(triangles, float)
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    with open(path, "wb") as f:
        f.write(("%-80s" % ("station " + name))[:80].encode())
        f.write(struct.pack("<I", len(tri)))
        for nrm, t in zip(normals, tri):
            f.write(struct.pack("<12fH", *nrm, *t.ravel(), 0))


FUNCTIONS = """    // The head budget's stations (python/fsi/pump_stations.py): sampled every %(every)s, re-found
    // after every mesh motion; per station the flow rate (m^3/s, along the station's normal)
    // and the flow-weighted total pressure (Pa).
    stations
    {
        type            surfaces;
        libs            ("libsampling.so");
        surfaceFormat   none;
        fields          (U totalPressure);
        store           true;
        sampleOnExecute true;
        executeControl  timeStep;
        executeInterval %(interval)d;
        writeControl    none;
        surfaces
        {
%(surfaces)s        }
    }
%(values)s"""

SURFACE = """            %(name)s { type sampledTriSurfaceMesh; surface %(name)s; file "stations/%(name)s.stl"; source insideCells; interpolate false; }
"""

VALUES = """%(flow_rate)s    stationTotalPressure_%(name)s
    {
        $stationFlowRate_%(name)s;
        operation       weightedAreaAverage;
        weightField     U;
        fields          (totalPressure);
    }
"""


def function_objects(stations=STATIONS, interval=1):
    """The controlDict entries (inside `functions { }`, after the totalPressure object), sampled
    every `interval` steps. On a moving mesh each sampled surface builds an octree of all the
    mesh's cells every time it samples (sampledTriSurfaceMesh::update, OpenFOAM v1912): every
    step, that was a third of a turning case's step (measured with perf on the pump's coarse
    turning mesh, penalized and AMI alike)."""
    return FUNCTIONS % {"surfaces": "".join(SURFACE % {"name": s} for s in stations),
                        "values": "".join(VALUES % {"name": s, "flow_rate": field_value_function(
                            "stationFlowRate_" + s, "functionObjectSurface", "stations." + s, "areaNormalIntegrate",
                            "U", interval)} for s in stations),
                        "interval": interval, "every": "step" if interval == 1 else "%d steps" % interval}


def write_stations(case_dir):
    """CASE_DIR/geometry/stations/<station>.stl from pump.yaml and geometry/geometry.yaml (the
    casing's bounding box), written next to it and swapped in whole; returns the folder."""
    with open(os.path.join(case_dir, "pump.yaml")) as f:
        design = yaml.safe_load(f)
    with open(os.path.join(case_dir, "geometry", "geometry.yaml")) as f:
        box = yaml.safe_load(f)["casing"]["bounding_box_m"]
    folder = os.path.join(case_dir, "geometry", "stations")
    partial = "%s.partial-%d" % (folder, os.getpid())
    os.makedirs(partial, exist_ok=True)
    for name, triangles in station_triangles(design, (box["min"], box["max"]), SPACING_M).items():
        write_binary_stl(os.path.join(partial, name + ".stl"), triangles, name)
    if os.path.isdir(folder):
        shutil.rmtree(folder)
    os.rename(partial, folder)
    return folder


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: pump_stations.py CASE_DIR")
    print(write_stations(sys.argv[1]))
