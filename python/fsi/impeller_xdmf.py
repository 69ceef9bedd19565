#!/usr/bin/python3
"""The rotating impeller for ParaView: RUN_DIR/impeller.h5 and RUN_DIR/impeller.xdmf, the
impeller's collision surface (its STL with named regions) at its rotated pose at every frame
saved in structure.h5, so that the impeller turns beside structure.xdmf (open both; the casing
is CASE_DIR/geometry/casing.stl, which does not move). A cell attribute `region` numbers the
STL's regions (the names in the file's Information and in /region_names).

The pose: the STL rotated by rate * t about the rotation's axis (rag_metrics.PumpGeometry, the
structure solver's collision surface and the fluid's penalized body agree on it).
Usage: impeller_xdmf.py RUN_DIR CASE_DIR"""

import os
import sys

import numpy as np

from fsi import rag_metrics


def rotating_surface(run_dir, case_dir):
    """(PumpGeometry, times [F]) of a run: the geometry from its configuration, the times from
    structure.h5 (every structure has the same frames: the first one's, for a feed's many rags)."""
    import h5py
    with h5py.File(os.path.join(run_dir, "structure.h5"), "r") as f:
        first = sorted(f["structures"].keys())[0] if "structures" in f and len(f["structures"]) else None
    times, _, _, _, _, _, h5_config = rag_metrics.read_structure(run_dir, first)
    config, source = rag_metrics.read_config(run_dir, case_dir, h5_config)
    geometry = rag_metrics.load_geometry(case_dir, config, source)[0]
    return geometry, times


def shared_vertices(regions):
    """(vertices [V, 3], triangles [T, 3] indices, region index [T], region names) of
    {name: triangles [n, 3, 3]}: an STL's repeated corners merged."""
    names = sorted(regions)
    corners = np.concatenate([np.asarray(regions[k], float).reshape(-1, 3) for k in names])
    region = np.concatenate([np.full(len(regions[k]), i, dtype=np.int32) for i, k in enumerate(names)])
    vertices, inverse = np.unique(corners, axis=0, return_inverse=True)
    return vertices, inverse.reshape(-1, 3).astype(np.int64), region, names


def write(run_dir, case_dir):
    """Writes impeller.h5 and impeller.xdmf into run_dir; returns the XDMF path."""
    import h5py
    geometry, times = rotating_surface(run_dir, case_dir)
    vertices, triangles, region, names = shared_vertices(geometry.impeller)
    frames = rag_metrics.rotate(np.broadcast_to(vertices, (len(times),) + vertices.shape),
                                geometry.axis, geometry.rate * np.asarray(times, float), geometry.origin)
    h5_path = os.path.join(run_dir, "impeller.h5")
    tmp = h5_path + ".tmp"
    with h5py.File(tmp, "w") as f:
        f["time_s"] = np.asarray(times, float)
        f["connectivity"] = triangles
        f["region"] = region
        f["region_names"] = np.array(names, dtype=h5py.string_dtype())
        f.create_dataset("position_m", data=frames.astype(np.float32), compression="gzip", compression_opts=4,
                         chunks=(1,) + vertices.shape)
        f.attrs["rotation_rate_rad_per_s"] = geometry.rate
        f.attrs["axis_direction"] = geometry.axis
        f.attrs["axis_point_m"] = geometry.origin
    os.replace(tmp, h5_path)
    xdmf_path = os.path.join(run_dir, "impeller.xdmf")
    with open(xdmf_path + ".tmp", "w") as f:
        f.write(xdmf_text(times, len(vertices), len(triangles), names))
    os.replace(xdmf_path + ".tmp", xdmf_path)
    return xdmf_path


def xdmf_text(times, n_vertices, n_triangles, names):
    n_frames = len(times)
    grids = []
    for k, t in enumerate(times):
        grids.append(
            '      <Grid Name="impeller_%d" GridType="Uniform">\n'
            '        <Time Value="%.17g"/>\n'
            '        <Topology TopologyType="Triangle" NumberOfElements="%d">\n'
            '          <DataItem Dimensions="%d 3" NumberType="Int" Precision="8" Format="HDF">impeller.h5:/connectivity</DataItem>\n'
            '        </Topology>\n'
            '        <Geometry GeometryType="XYZ">\n'
            '          <DataItem Type="HyperSlab" Dimensions="1 %d 3" NumberType="Float" Precision="4" Format="HDF">\n'
            '            impeller.h5:/position_m|%d 0 0:1 1 1:1 %d 3:%d %d 3\n'
            '            <DataItem Dimensions="3 3" NumberType="Int" Format="XML">%d 0 0 1 1 1 1 %d 3</DataItem>\n'
            '            <DataItem Dimensions="%d %d 3" NumberType="Float" Precision="4" Format="HDF">impeller.h5:/position_m</DataItem>\n'
            '          </DataItem>\n'
            '        </Geometry>\n'
            '        <Attribute Name="region" AttributeType="Scalar" Center="Cell">\n'
            '          <DataItem Dimensions="%d" NumberType="Int" Precision="4" Format="HDF">impeller.h5:/region</DataItem>\n'
            '        </Attribute>\n'
            '      </Grid>\n'
            % (k, t, n_triangles, n_triangles, n_vertices, k, n_vertices, n_frames, n_vertices, k, n_vertices, n_frames,
               n_vertices, n_triangles))
    legend = ", ".join("%d = %s" % (i, n) for i, n in enumerate(names))
    return ('<?xml version="1.0" encoding="utf-8"?>\n'
            '<Xdmf xmlns:xi="http://www.w3.org/2001/XInclude" Version="3.0">\n'
            '  <Domain>\n'
            '    <Information Name="region" Value="%s"/>\n'
            '    <Grid Name="impeller" GridType="Collection" CollectionType="Temporal">\n'
            '%s'
            '    </Grid>\n'
            '  </Domain>\n'
            '</Xdmf>\n') % (legend, "".join(grids))


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__.splitlines()[-1])
    try:
        print(write(argv[1], argv[2]))
    except rag_metrics.MetricsError as error:
        sys.exit("impeller_xdmf: %s" % error)


if __name__ == "__main__":
    main(sys.argv)
