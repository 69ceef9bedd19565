"""The one place that writes OpenFOAM dictionaries from Python: whole files for the case
generators (cases/*/make_case.py) and the runs of stock OpenFOAM (python/fsi/pump_ami_run.py), and
single entries read or set through OpenFOAM's own foamDictionary, never by pattern; plus closed
STL solids, written as text. Standard library only."""

import math
import os
import re
import subprocess

# Debian's OpenFOAM reads its etc/ through WM_PROJECT_DIR while its libraries load, before
# main(): every OpenFOAM program (our fluid, foamDictionary, pimpleFoam) is started with it set.
OPENFOAM_ENVIRONMENT = {"WM_PROJECT_DIR": "/usr/share/openfoam", "FOAM_ETC": "/usr/share/openfoam/etc"}

FOAM_HEADER = """/*--------------------------------*- C++ -*----------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %(cls)s;
    object      %(obj)s;
}
"""


# fvSchemes of a laminar incompressible case: Euler in time, second order in space
# (linearUpwind convection), non-orthogonal corrections.
LAMINAR_FV_SCHEMES = """ddtSchemes      { default Euler; }
gradSchemes     { default Gauss linear; }
divSchemes
{
    default         none;
    div(phi,U)      Gauss linearUpwind grad(U);
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes   { default corrected; }
"""


# fvSchemes of the turbulent pump cases (Spalart-Allmaras or k-omega SST): Euler in time, LUST
# convection of U, bounded convection of the turbulence variables, limited corrections (the
# snapped cells), the wall distance by meshWave.
TURBULENT_FV_SCHEMES = """ddtSchemes      { default Euler; }
gradSchemes     { default Gauss linear; grad(U) cellLimited Gauss linear 1; }
divSchemes
{
    default         none;
    div(phi,U)      Gauss LUST grad(U);
    div(phi,nuTilda) Gauss limitedLinear 1;
    div(phi,k)      Gauss limitedLinear 1;
    div(phi,omega)  Gauss limitedLinear 1;
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear limited 0.5; }
interpolationSchemes { default linear; }
snGradSchemes   { default limited 0.5; }
wallDist        { method meshWave; }
"""

def field_value_function(entry, region_type, region, operation, field, interval):
    """A controlDict `functions` entry: a surfaceFieldValue of `field` over a region (a patch, a
    faceZone, a sampled surface), computed and written every `interval` steps, not logged."""
    return """    %s
    {
        type            surfaceFieldValue;
        libs            ("libfieldFunctionObjects.so");
        regionType      %s;
        name            %s;
        operation       %s;
        fields          (%s);
        writeFields     false;
        log             false;
        executeControl  timeStep;
        executeInterval %d;
        writeControl    timeStep;
        writeInterval   %d;
    }
""" % (entry, region_type, region, operation, field, interval, interval)


def foam_header(cls, obj):
    """The FoamFile header of a dictionary or field file: class cls, object obj."""
    return FOAM_HEADER % {"cls": cls, "obj": obj}


def write_foam_file(case_dir, relative_path, cls, body):
    """case_dir/relative_path with the FoamFile header (class cls) and body."""
    path = os.path.join(case_dir, relative_path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(foam_header(cls, os.path.basename(relative_path)) + body)
    return path


def write_operating_point(case_dir, flow_rate_m3_per_s):
    """constant/operatingPoint, as fsi-openfoam-fluid writes it from fluid.openfoam.operating_point:
    the imposed volume flow rate at the inlet that 0/U includes ($flowRate, m^3/s)."""
    return write_foam_file(case_dir, "constant/operatingPoint", "dictionary",
                           "// The imposed volume flow rate at the inlet (m^3/s).\nflowRate        %r;\n"
                           % float(flow_rate_m3_per_s))


def foam_dictionary(path, *options):
    """OpenFOAM's foamDictionary on the dictionary file `path` (a finished process)."""
    return subprocess.run(["foamDictionary"] + list(options) + [path], stdin=subprocess.DEVNULL,
                          capture_output=True, text=True, env=dict(OPENFOAM_ENVIRONMENT, **os.environ))


def foam_entry(path, key):
    """The value of `key` in the OpenFOAM dictionary file `path`, as text (foamDictionary -value)."""
    done = foam_dictionary(path, "-entry", key, "-value")
    if done.returncode != 0:
        raise ValueError("%s: no entry %s (foamDictionary: %s)" % (path, key, done.stderr.strip()[-300:]))
    return done.stdout.strip()


def set_foam_entry(path, key, value):
    """Sets `key` of the OpenFOAM dictionary file `path` to `value` (foamDictionary -set)."""
    done = foam_dictionary(path, "-entry", key, "-set", str(value))
    if done.returncode != 0:
        raise ValueError("%s: cannot set %s (foamDictionary: %s)" % (path, key, done.stderr.strip()[-300:]))


def cylinder_stl(radius, z0, z1, n, centre=(0.0, 0.0), name="cylinder", parts=None):
    """Closed solid cylinder along z through centre = (x, y) (outward normals): side, and caps
    fanned from the axis. n facets around; the polygon misses the circle by about (pi/n)^2 R / 2.
    parts = (caps, side): two `solid` blocks of these names instead of one named `name` (the
    parts whose loads the penalized runs split, parts.csv)."""
    cx, cy = centre
    ring = [(cx + radius * math.cos(2 * math.pi * i / n), cy + radius * math.sin(2 * math.pi * i / n))
            for i in range(n)]
    side, caps = [], []
    for i in range(n):
        (xa, ya), (xb, yb) = ring[i], ring[(i + 1) % n]
        a0, b0, a1, b1 = (xa, ya, z0), (xb, yb, z0), (xa, ya, z1), (xb, yb, z1)
        side += [(a0, b0, b1), (a0, b1, a1)]
        caps += [((cx, cy, z0), b0, a0), ((cx, cy, z1), a1, b1)]
    if parts is None:
        return _stl_solid(name, [t for i in range(n) for t in (side[2 * i], side[2 * i + 1], caps[2 * i], caps[2 * i + 1])])
    return _stl_solid(parts[0], caps) + _stl_solid(parts[1], side)


def _stl_solid(name, tris):
    """One `solid NAME` block of triangles (outward normals from the vertex order)."""
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


def patch_names(case_dir):
    """The patch names of case_dir/constant/polyMesh/boundary (a list of named dictionaries), in
    order. Raises FileNotFoundError for a case without a mesh."""
    path = os.path.join(case_dir, "constant", "polyMesh", "boundary")
    if not os.path.isfile(path):
        raise FileNotFoundError("%s: no constant/polyMesh/boundary (not a meshed OpenFOAM case)" % case_dir)
    with open(path) as f:
        text = re.sub(r"/\*.*?\*/|//[^\n]*", "", f.read(), flags=re.S)
    body = text[text.index("(", text.index("}") if "FoamFile" in text else 0) + 1:]
    return re.findall(r"([A-Za-z_][\w.:-]*)\s*\{", body)
