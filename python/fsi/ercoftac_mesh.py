"""The ERCOFTAC pump's quasi-3-D slab (python/fsi/ercoftac_pump.py) meshed by gmsh: one layer of
hexahedra across the constant channel width, quads recombined from a frontal triangulation, for
both methods of issue 31 on the same cells:

- `penalized`: one conformal mesh of the annulus from the inlet (r = 0.100 m) to the outlet
  (0.500 m) with the diffuser's 12 vanes cut out; the impeller is not in the mesh (it is
  penalized), and the whole rotor (r < 0.217 m, where the blades sweep) has cells of h_near.
- `rotor`, `stator`: the body-fitted reference's two meshes, the rotor with the 7 blades cut out,
  joined by OpenFOAM's mergeMeshes behind an AMI at r = 0.217 m (the radius of the test case's
  own 2-D sliding interface). The stator is the penalized mesh's outer part, cell for cell.

The sizes: h_near in the rotor, along the vanes and in the vaneless gap, growing to h_far at
8 cm from them. Patches (physical groups): inlet, outlet, frontAndBack, vanes, blades, ami_rotor,
ami_stator; cell zones rotor and stator. The inlet's radius is that of the test case's 2-D
OpenFOAM cases (the repository's plot scripts: rIn = 0.1); their outlet, at 0.365 m, 30 mm behind
the vanes' trailing edges, let the vanes' wakes flow back in and the run diverged after 1.3
revolutions (coarse, penalized): ours is at 0.5 m."""

import math
import os
import re
import shutil
import tempfile

import numpy as np

from fsi import ercoftac_pump as ecp

R_INLET_M, R_INTERFACE_M, R_OUTLET_M = 0.100, 0.217, 0.500
REGIONS = ("penalized", "rotor", "stator")


def _profile_loop(geo, profile, h):
    """Splines along the profile's two surfaces, lines across its blunt ends: (loop, curves)."""
    pa = [geo.addPoint(x, y, 0, h) for x, y in profile.a]
    sharp = np.linalg.norm(profile.a[0] - profile.b[0]) < 1e-9
    pb = ([pa[0]] if sharp else [geo.addPoint(*profile.b[0], 0, h)]) + [geo.addPoint(x, y, 0, h) for x, y in profile.b[1:]]
    curves = [geo.addSpline(pa), geo.addLine(pa[-1], pb[-1]), -geo.addSpline(pb)]
    if not sharp:
        curves.append(geo.addLine(pb[0], pa[0]))
    return geo.addCurveLoop(curves), [abs(c) for c in curves]


def _circle_loop(geo, r, h, n=4):
    centre = geo.addPoint(0, 0, 0, h)
    points = [geo.addPoint(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n), 0, h) for k in range(n)]
    arcs = [geo.addCircleArc(points[k], centre, points[(k + 1) % n]) for k in range(n)]
    return geo.addCurveLoop(arcs), arcs


def _size_field(walls, h_near, h_far):
    import gmsh
    field = gmsh.model.mesh.field
    distance = field.add("Distance")
    field.setNumbers(distance, "EdgesList", walls)
    field.setNumber(distance, "NumPointsPerCurve", 200)
    threshold = field.add("Threshold")
    for key, value in (("InField", distance), ("SizeMin", h_near), ("SizeMax", h_far), ("DistMin", 0.01),
                       ("DistMax", 0.08)):
        field.setNumber(threshold, key, value)
    rotor = field.add("Cylinder")     # the whole rotor at h_near: the penalized blades sweep it
    for key, value in (("Radius", R_INTERFACE_M + 0.002), ("VIn", h_near), ("VOut", h_far), ("XAxis", 0.0),
                       ("YAxis", 0.0), ("ZAxis", 1.0), ("XCenter", 0.0), ("YCenter", 0.0), ("ZCenter", 0.0)):
        field.setNumber(rotor, key, value)
    smallest = field.add("Min")
    field.setNumbers(smallest, "FieldsList", [threshold, rotor])
    field.setAsBackgroundMesh(smallest)


def _even_boundaries(free_arcs):
    """Blossom recombines a triangulation into quads only when it has an even number of
    triangles, the parity of its boundary's node count: one node more on an inlet or outlet arc
    (free_arcs) when odd."""
    import gmsh
    gmsh.model.mesh.generate(1)
    for _dim, surface in gmsh.model.getEntities(2):
        box = gmsh.model.getBoundingBox(2, surface)
        if abs(box[2]) > 1e-12 or abs(box[5]) > 1e-12:
            continue                           # only the plane surfaces at z = 0
        curves = [abs(c) for _d, c in gmsh.model.getBoundary([(2, surface)], oriented=False)]
        nodes = sum(len(gmsh.model.mesh.getNodes(1, c)[0]) + 1 for c in curves)
        arcs = [c for c in curves if c in free_arcs]
        if nodes % 2 and arcs:
            gmsh.model.mesh.setTransfiniteCurve(arcs[0], len(gmsh.model.mesh.getNodes(1, arcs[0])[0]) + 3)
    gmsh.model.mesh.clear()


def _patch_of(surface, region):
    """The patch name of a surface of the extruded slab (None: the penalized mesh's interior)."""
    import gmsh
    x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(2, surface)
    r = max(math.hypot(x, y) for x in (x0, x1) for y in (y0, y1))

    def on(radius):   # an arc's box corner lies at the radius, or sqrt(2) times it
        return min(abs(r - radius), abs(r - radius * math.sqrt(2))) < 1e-4

    if abs(z1 - z0) < 1e-12:
        return "frontAndBack"
    if on(R_INLET_M):
        return "inlet"
    if on(R_OUTLET_M):
        return "outlet"
    if len(gmsh.model.getAdjacencies(2, surface)[0]) == 2:
        return None
    if on(R_INTERFACE_M):
        return "ami_" + region
    return "blades" if region == "rotor" else "vanes"


def write_msh(path, region, h_near_m, h_far_m, thickness_m=None, cut_blades=True):
    """Meshes one region (REGIONS) and writes it as gmsh 2.2 (gmshToFoam's format) to path.
    Returns {"cells": n, "patches": {name: surfaces}}. The slab is thickness_m thick (default
    h_near_m: cubes in the rotor). cut_blades=False: the rotor region without its blades (they
    are penalized in it, turning with its cells)."""
    import gmsh
    if region not in REGIONS:
        raise ValueError("region %r: one of %s" % (region, ", ".join(REGIONS)))
    if not 0 < h_near_m <= h_far_m:
        raise ValueError("sizes h_near %g m, h_far %g m: 0 < h_near <= h_far" % (h_near_m, h_far_m))
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("ercoftac-" + region)
        geo = gmsh.model.geo
        inlet_loop, inlet_arcs = _circle_loop(geo, R_INLET_M, h_near_m)
        interface_loop, interface_arcs = _circle_loop(geo, R_INTERFACE_M, h_near_m)
        outlet_loop, outlet_arcs = _circle_loop(geo, R_OUTLET_M, h_far_m)
        walls, surfaces = list(interface_arcs), []
        if region in ("penalized", "rotor"):
            holes = []
            for k in range(ecp.BLADES if region == "rotor" and cut_blades else 0):
                loop, curves = _profile_loop(geo, ecp.blade().rotated(2 * math.pi * k / ecp.BLADES), h_near_m)
                holes.append(loop)
                walls += curves
            surfaces.append(geo.addPlaneSurface([interface_loop, inlet_loop] + holes))
        if region in ("penalized", "stator"):
            holes = []
            for k in range(ecp.VANES):
                loop, curves = _profile_loop(geo, ecp.vane().rotated(2 * math.pi * k / ecp.VANES), h_near_m)
                holes.append(loop)
                walls += curves
            surfaces.append(geo.addPlaneSurface([outlet_loop, interface_loop] + holes))
        for surface in surfaces:
            geo.mesh.setRecombine(2, surface)
        extruded = geo.extrude([(2, s) for s in surfaces], 0, 0, thickness_m or h_near_m, numElements=[1],
                               recombine=True)
        geo.synchronize()
        _size_field(walls, h_near_m, h_far_m)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.Algorithm", 6)               # frontal-Delaunay
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)  # Blossom
        volumes = [tag for dim, tag in extruded if dim == 3]
        patches = {}
        for _dim, surface in gmsh.model.getEntities(2):
            name = _patch_of(surface, "rotor" if region == "rotor" else "stator")
            if name:
                patches.setdefault(name, []).append(surface)
        for name, tags in patches.items():
            gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), name)
        zones = ["rotor", "stator"] if region == "penalized" else [region]
        for name, volume in zip(zones, volumes):
            gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [volume]), name)
        _even_boundaries(inlet_arcs + outlet_arcs)
        gmsh.model.mesh.generate(3)
        types, tags, _nodes = gmsh.model.mesh.getElements(3)
        gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
        gmsh.write(path)
        return {"cells": int(sum(len(t) for t in tags)), "element_types": [int(t) for t in types],
                "patches": {name: len(tags) for name, tags in patches.items()}}
    finally:
        gmsh.finalize()


PATCH_TYPES = {"frontAndBack": "empty", "inlet": "patch", "outlet": "patch", "vanes": "wall", "blades": "wall"}
AMI_PAIRS = {"ami_rotor": "ami_stator", "ami_stator": "ami_rotor"}


def write_boundary_types(foam_case, patch_types=None):
    """constant/polyMesh/boundary with the patches' OpenFOAM types (gmshToFoam writes them all as
    `patch`; patch_types: {name: type}, default PATCH_TYPES): the slab's faces empty, the walls
    walls, the two sides of the interface (ami_rotor, ami_stator) a cyclicAMI pair (noOrdering:
    their faces do not match one to one)."""
    patch_types = patch_types or PATCH_TYPES
    path = os.path.join(foam_case, "constant", "polyMesh", "boundary")
    with open(path) as f:
        text = f.read()
    patches = re.findall(r"\n\s*(\w+)\s*\{[^}]*?nFaces\s+(\d+);\s*startFace\s+(\d+);[^}]*\}", text)
    if not patches:
        raise ValueError("%s: no patches found (gmshToFoam's output expected)" % path)
    lines = [text[:text.index("// * *")].rstrip() + "\n" + "// " + "* " * 37 + "//\n", "%d\n(" % len(patches)]
    for name, faces, start in patches:
        if name not in patch_types and name not in AMI_PAIRS:
            raise ValueError("%s: patch %r is none of %s" % (path, name, ", ".join(list(patch_types) + list(AMI_PAIRS))))
        body = ["type %s;" % ("cyclicAMI" if name in AMI_PAIRS else patch_types[name])]
        if name in AMI_PAIRS:
            body += ["inGroups (cyclicAMI);", "neighbourPatch %s;" % AMI_PAIRS[name], "transform noOrdering;"]
        elif patch_types[name] in ("empty", "wall"):
            body.append("inGroups (%s);" % patch_types[name])
        body += ["nFaces %s;" % faces, "startFace %s;" % start]
        lines.append("    %s\n    {\n%s\n    }" % (name, "\n".join("        " + b for b in body)))
    lines.append(")\n")
    with open(path, "w") as f:
        f.write("\n".join(lines))


METHODS = ("penalized", "turning", "ami")


def foam_mesh(foam_case, method, h_near_m, h_far_m, logs):
    """The slab's OpenFOAM mesh in foam_case/constant/polyMesh: gmsh (write_msh), gmshToFoam,
    for a rotor behind the AMI the rotor merged into the stator (mergeMeshes), the patch types
    (write_boundary_types), checkMesh. method (METHODS): penalized (one fixed mesh, the blades
    penalized in it), turning (the blades penalized in a rotor mesh turning with them behind the
    AMI) or ami (the blades cut out of that rotor, body-fitted). Returns the cell count."""
    from fsi import pump_ami_run

    def run_tool(tool, case, logs, options=()):
        pump_ami_run.run_tool(tool, case, logs, options, who="ercoftac-mesh")
    if method not in METHODS:
        raise ValueError("method %r: one of %s" % (method, ", ".join(METHODS)))
    os.makedirs(logs, exist_ok=True)
    shutil.rmtree(os.path.join(foam_case, "constant", "polyMesh"), ignore_errors=True)
    with tempfile.TemporaryDirectory() as tmp:
        if method == "penalized":
            made = write_msh(os.path.join(tmp, "penalized.msh"), "penalized", h_near_m, h_far_m)
            run_tool("gmshToFoam", foam_case, logs, [os.path.join(tmp, "penalized.msh")])
            cells = made["cells"]
        else:
            rotor_case = os.path.join(tmp, "rotor")
            os.makedirs(os.path.join(rotor_case, "constant"))
            shutil.copytree(os.path.join(foam_case, "system"), os.path.join(rotor_case, "system"))
            cells = 0
            for region, case in (("stator", foam_case), ("rotor", rotor_case)):
                cells += write_msh(os.path.join(tmp, region + ".msh"), region, h_near_m, h_far_m,
                                   cut_blades=method == "ami")["cells"]
                run_tool("gmshToFoam", case, logs, [os.path.join(tmp, region + ".msh")])
                os.rename(os.path.join(logs, "log.gmshToFoam"), os.path.join(logs, "log.gmshToFoam." + region))
            run_tool("mergeMeshes", foam_case, logs, ["-overwrite", foam_case, rotor_case])
    write_boundary_types(foam_case)
    run_tool("checkMesh", foam_case, logs, ["-constant"])
    with open(os.path.join(logs, "log.checkMesh")) as f:
        if "Mesh OK." not in f.read():
            raise RuntimeError("checkMesh fails the %s mesh of %s: see %s" % (method, foam_case,
                                                                               os.path.join(logs, "log.checkMesh")))
    return cells
