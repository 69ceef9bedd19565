#!/usr/bin/python3
"""How closely a body-fitted mesh follows the surface it was snapped to: for each patch, the
share of its area whose faces stand more than --angle degrees off the normal of the nearest
triangle of the surface, and the faces' distance to it. Where snappyHexMesh cannot snap (a gap of
about one cell, as between a drum-shaped impeller and a sliding interface 2.5 mm away) it leaves
the background cells' faces: a staircase, whose steps take pressure drag a smooth wall does not
(an axis-aligned staircase over a cylinder stands half its area more than 30 deg off).

Usage:
    /usr/bin/python3 python/fsi/snap_quality.py FOAM_CASE SURFACE.stl [--patches a,b] [--angle 30]
FOAM_CASE: an OpenFOAM case whose constant/polyMesh has patches named as SURFACE.stl's solids
(the pump's AMI reference, python/fsi/pump_ami_run.py); the mesh at constant/, i.e. as it was
snapped, before it turns. The patches are those of SURFACE.stl's solids found in the mesh (or
--patches). Prints a table and, with --yaml FILE, writes it. Faces are read by OpenFOAM's
surfaceMeshExtract; nearest triangles by the solver's exact query (surface_engine).
Exits 1 with a message for a missing case, surface or patch.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from fsi import surface_engine  # noqa: E402
from fsi.foam_case import OPENFOAM_ENVIRONMENT, patch_names  # noqa: E402

STEPPED_ANGLE_DEG = 30.0     # a face more than this off the surface's normal is a step
STEPPED_WARN_FRACTION = 0.05  # a patch with more of its area stepped is not a body-fitted wall


class SnapError(Exception):
    pass


def read_stl(path):
    """{solid name: triangles [n, 3, 3]} (the solver's STL reader, surface_engine)."""
    if not os.path.isfile(path):
        raise SnapError("%s: no such file" % path)
    return surface_engine.engine().regions(path)


def unit_normals_and_areas(triangles):
    cross = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    area = 0.5 * np.linalg.norm(cross, axis=1)
    keep = area > 0
    normals = np.zeros_like(cross)
    normals[keep] = cross[keep] / (2.0 * area[keep, None])
    return normals, area


class Surface:
    """A surface's triangles of non-zero area made into the engine's set once, with their normals."""

    def __init__(self, triangles):
        normals, area = unit_normals_and_areas(triangles)
        self.normals = normals[area > 0]
        self.id, _ = surface_engine.engine().add_set(triangles[area > 0])


def stepped(mesh_triangles, surface, angle_deg=STEPPED_ANGLE_DEG):
    """(area fraction of mesh_triangles whose normal is more than angle_deg off the normal of
    the surface triangle nearest to its centroid, whatever the normals' senses; area-weighted
    mean distance of the centroids to the surface (m); area (m^2)). surface: a Surface, or its
    triangles [n, 3, 3]."""
    if not isinstance(surface, Surface):
        surface = Surface(np.asarray(surface, float))
    mesh_n, mesh_a = unit_normals_and_areas(mesh_triangles)
    distance, nearest = surface_engine.engine().nearest(surface.id, mesh_triangles.mean(axis=1), None)
    cosine = np.abs(np.einsum("ij,ij->i", mesh_n, surface.normals[nearest]))
    off = cosine < np.cos(np.radians(angle_deg))
    area = mesh_a.sum()
    if not area > 0:
        raise SnapError("a patch without area")
    return float(mesh_a[off].sum() / area), float((distance * mesh_a).sum() / area), float(area)


def extract_patch(foam_case, patch, work):
    """The patch's faces (triangulated) as [n, 3, 3], by surfaceMeshExtract at constant/."""
    out = os.path.join(work, patch + ".stl")
    env = dict(os.environ, **OPENFOAM_ENVIRONMENT)
    done = subprocess.run(["surfaceMeshExtract", "-case", foam_case, "-constant", "-time", "constant",
                           "-patches", "(%s)" % patch, out], env=env, stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    written = [os.path.join(work, f) for f in os.listdir(work) if f.startswith(patch) and f.endswith(".stl")]
    if done.returncode != 0 or not written:
        raise SnapError("surfaceMeshExtract found no patch %s in %s: %s" % (
            patch, foam_case, done.stdout.strip().splitlines()[-1] if done.stdout.strip() else "no output"))
    triangles = np.concatenate([t for f in written for t in read_stl(f).values()])
    for f in written:
        os.remove(f)
    return triangles


def report(foam_case, surface_path, patches=None, angle_deg=STEPPED_ANGLE_DEG):
    """{patch: {stepped_area_fraction, mean_distance_m, area_m2}} of the surface's solids in the mesh."""
    surface = read_stl(surface_path)
    try:
        present = patch_names(foam_case)
    except FileNotFoundError as error:
        raise SnapError(str(error))
    if patches is None:
        patches = [name for name in surface if name in present]
        if not patches:
            raise SnapError("%s has no patch named as a solid of %s (%s)" % (
                foam_case, surface_path, ", ".join(sorted(surface))))
    missing = [p for p in patches if p not in present or p not in surface]
    if missing:
        raise SnapError("patch %s: not both a patch of %s and a solid of %s" % (
            ", ".join(missing), foam_case, surface_path))
    whole = Surface(np.concatenate(list(surface.values())))
    work = tempfile.mkdtemp(prefix="snap-quality-")
    try:
        out = {}
        for patch in patches:
            fraction, distance, area = stepped(extract_patch(foam_case, patch, work), whole, angle_deg)
            out[patch] = {"stepped_area_fraction": round(fraction, 4), "mean_distance_m": float("%.3g" % distance),
                          "area_m2": float("%.4g" % area)}
        return out
    finally:
        shutil.rmtree(work, ignore_errors=True)


def warnings(table):
    return ["%s: %.0f %% of its area is stepped (faces more than %g deg off the surface): the body-fitted "
            "wall is a staircase there" % (patch, 100 * row["stepped_area_fraction"], STEPPED_ANGLE_DEG)
            for patch, row in table.items() if row["stepped_area_fraction"] > STEPPED_WARN_FRACTION]


def main(argv):
    parser = argparse.ArgumentParser(prog="snap_quality.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("foam_case")
    parser.add_argument("surface")
    parser.add_argument("--patches", help="comma-separated (default: the surface's solids in the mesh)")
    parser.add_argument("--angle", type=float, default=STEPPED_ANGLE_DEG, help="degrees off that make a step")
    parser.add_argument("--yaml", help="also write the table here")
    args = parser.parse_args(argv)
    try:
        table = report(args.foam_case, args.surface, args.patches.split(",") if args.patches else None, args.angle)
    except (SnapError, surface_engine.EngineError) as error:
        sys.stderr.write("snap_quality.py: %s\n" % error)
        return 1
    print("%-24s %10s %12s %10s" % ("patch", "stepped", "distance_mm", "area_m2"))
    for patch, row in table.items():
        print("%-24s %9.1f%% %12.2f %10.4f" % (patch, 100 * row["stepped_area_fraction"],
                                               1000 * row["mean_distance_m"], row["area_m2"]))
    for line in warnings(table):
        sys.stderr.write("snap_quality.py: warning: %s\n" % line)
    if args.yaml:
        import yaml
        with open(args.yaml, "w") as f:
            f.write("# snap_quality.py: the body-fitted patches against %s (angle %g deg)\n" % (args.surface, args.angle))
            yaml.safe_dump(table, f, sort_keys=False)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
