"""An independent reckoning of the staircase share of a penalized body's torque
(fsi-openfoam-fluid's parts_staircase.csv, OpenFoamFluidModel::last_step_part_staircase_loads)
from an OpenFOAM time folder written in ascii: every face between a penalized cell
(penalizationRate > 0) and a free one takes the free cell's pressure, -p S with S out of the body
cell; the part of that force off the surface normal (the normal of the STL triangle whose centroid
is nearest the face centre, not the adapter's closest point) is what the staircase's steps take.
Torques about the axis through the origin, at the face centres. Debian's /usr/bin/python3 with
python3-numpy and python3-scipy.
"""

import re

import numpy as np
from scipy.spatial import cKDTree

from penalization_support import read_internal_field


def _list_after_header(text):
    """The first `N (` ... list after the FoamFile header: (N, the text after its opening)."""
    match = re.compile(r"\n(\d+)\s*\n?\(").search(text, text.index("}") if "FoamFile" in text else 0)
    return int(match.group(1)), text[match.end():]


def read_labels(path):
    with open(path) as f:
        n, body = _list_after_header(f.read())
    return np.array(body[:body.index(")")].split()[:n], int)


def read_points(path):
    with open(path) as f:
        n, body = _list_after_header(f.read())
    return np.array(re.findall(r"\(\s*(\S+)\s+(\S+)\s+([^\s()]+)\s*\)", body)[:n], float)


def read_faces(path):
    with open(path) as f:
        n, body = _list_after_header(f.read())
    return [np.array(face.split(), int) for face in re.findall(r"\d+\(([\d ]+)\)", body)[:n]]


def read_stl_triangles(path):
    """(n, 3, 3) vertices of an ascii STL."""
    with open(path) as f:
        vertices = [[float(v) for v in line.split()[1:4]] for line in f if line.split()[:1] == ["vertex"]]
    return np.array(vertices).reshape(-1, 3, 3)


def staircase_torque(foam_case, time_name, stl_path, angle_rad, axis=(0.0, 0.0, 1.0)):
    """(the pressure's torque on the body about `axis` through the origin, its part along the
    surface normal, the staircase's part), N m for water (rho 1000), at time folder `time_name`
    of the ascii case; the STL turned by angle_rad about `axis` (the body's pose then)."""
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    points_path = "%s/%s/polyMesh/points" % (foam_case, time_name)
    try:
        points = read_points(points_path)                       # a moving mesh writes its points
    except FileNotFoundError:
        points = read_points("%s/constant/polyMesh/points" % foam_case)
    faces = read_faces("%s/constant/polyMesh/faces" % foam_case)
    owner = read_labels("%s/constant/polyMesh/owner" % foam_case)
    neighbour = read_labels("%s/constant/polyMesh/neighbour" % foam_case)
    rate = read_internal_field("%s/%s/penalizationRate" % (foam_case, time_name), None)
    pressure = 1000.0 * read_internal_field("%s/%s/p" % (foam_case, time_name), len(rate))
    body = rate > 0.0
    o = owner[:len(neighbour)]
    interface = np.nonzero(body[o] != body[neighbour])[0]
    area, centre = np.zeros((len(interface), 3)), np.zeros((len(interface), 3))
    for k, f in enumerate(interface):
        corners = points[faces[f]]
        middle = corners.mean(axis=0)
        for i in range(len(corners)):
            area[k] += 0.5 * np.cross(corners[i] - middle, corners[(i + 1) % len(corners)] - middle)
        centre[k] = middle
    body_is_owner = body[o[interface]]
    s_out = np.where(body_is_owner[:, None], area, -area)
    free = np.where(body_is_owner, neighbour[interface], o[interface])
    force = -pressure[free][:, None] * s_out
    # The STL at the body's pose: Rodrigues' rotation by angle_rad about the axis.
    tri = read_stl_triangles(stl_path)
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    turned = tri * c + np.cross(axis, tri) * s + np.outer(tri.reshape(-1, 3) @ axis, axis).reshape(tri.shape) * (1 - c)
    normals = np.cross(turned[:, 1] - turned[:, 0], turned[:, 2] - turned[:, 0])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    _, nearest = cKDTree(turned.mean(axis=1)).query(centre)
    n = normals[nearest]                                         # the sign does not matter
    along = np.sum(force * n, axis=1)[:, None] * n
    torque = lambda f: float(np.sum(np.cross(centre, f) @ axis))
    return torque(force), torque(along), torque(force - along)
