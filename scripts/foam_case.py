"""Helpers of the case generators (cases/*/make_case.py): OpenFOAM dictionary files and closed STL
solids, written as text. Standard library only."""

import math
import os

FOAM_HEADER = """/*--------------------------------*- C++ -*----------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %(cls)s;
    object      %(obj)s;
}
"""


def write_foam_file(case_dir, relative_path, cls, body):
    """case_dir/relative_path with the FoamFile header (class cls) and body."""
    path = os.path.join(case_dir, relative_path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(FOAM_HEADER % {"cls": cls, "obj": os.path.basename(relative_path)} + body)
    return path


def cylinder_stl(radius, z0, z1, n, centre=(0.0, 0.0), name="cylinder"):
    """Closed solid cylinder along z through centre = (x, y) (outward normals): side, and caps
    fanned from the axis. n facets around; the polygon misses the circle by about (pi/n)^2 R / 2."""
    cx, cy = centre
    ring = [(cx + radius * math.cos(2 * math.pi * i / n), cy + radius * math.sin(2 * math.pi * i / n))
            for i in range(n)]
    tris = []
    for i in range(n):
        (xa, ya), (xb, yb) = ring[i], ring[(i + 1) % n]
        a0, b0, a1, b1 = (xa, ya, z0), (xb, yb, z0), (xa, ya, z1), (xb, yb, z1)
        tris += [(a0, b0, b1), (a0, b1, a1), ((cx, cy, z0), b0, a0), ((cx, cy, z1), a1, b1)]
    lines = ["solid %s" % name]
    for a, b, c in tris:
        e1 = [b[k] - a[k] for k in range(3)]
        e2 = [c[k] - a[k] for k in range(3)]
        nrm = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        length = math.sqrt(sum(q * q for q in nrm))
        lines.append("  facet normal %.7g %.7g %.7g" % tuple(q / length for q in nrm))
        lines.append("    outer loop")
        lines += ["      vertex %.9g %.9g %.7g" % p for p in (a, b, c)]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid %s" % name)
    return "\n".join(lines) + "\n"
