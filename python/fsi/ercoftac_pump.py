"""The ERCOFTAC centrifugal pump with a vaned diffuser (test case U3, Univ. Genova; Ubaldi, Zunino,
Barigozzi, Cattanei, ASME J. Turbomach. 118, 1996): its geometry and operating point from the
files of cases/ercoftac-pump/data (Table 2 of the test case's description: one blade and one vane,
two surfaces each, radius in mm and angle in degrees), as the external validation of the rotating
penalized impeller (issue 31) needs them: the closed outlines of the 7 blades and the 12 vanes in
the table's frame (x = r cos theta, y = r sin theta, metres), their measured thickness and angles
(the checks that the table was read right), and the blades extruded over a slab as a closed STL
(the penalized impeller).

The impeller turns toward -theta (its blades lean back, theta growing outward): about -z with a
positive rate, 2000 rpm. The test ran in air at 298 K (rho 1.2 kg/m^3) at the flow coefficient
phi = 4 Q / (U2 pi D2^2) = 0.0475."""

import csv
import math
import os

import numpy as np

R2_M = 0.210                    # impeller outlet radius (Table 1: D2 = 420 mm)
SPAN_M = 0.040                  # blade and vane span b (Table 1)
BLADES = 7
VANES = 12
SPEED_RPM = 2000.0
FLOW_COEFFICIENT = 0.0475       # phi = 4 Q / (U2 pi D2^2) (Table 1)
AIR_DENSITY_KG_PER_M3 = 1.2     # air at 298 K (the description's text)
MEASUREMENT_RADIUS_M = 0.2142   # the hot-wire traverse, R / R2 = 1.02

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                    "cases", "ercoftac-pump", "data")


def omega_rad_per_s():
    return SPEED_RPM * math.pi / 30.0


def tip_speed_m_per_s():
    return omega_rad_per_s() * R2_M


def design_flow_rate_m3_per_s():
    """Q of the measured point from its flow coefficient: phi U2 pi D2^2 / 4."""
    return FLOW_COEFFICIENT * tip_speed_m_per_s() * math.pi * (2 * R2_M) ** 2 / 4.0


class Profile:
    """One blade (or vane) of Table 2: its two surfaces A and B as (n, 2) arrays of x, y in metres,
    each from the leading edge."""

    def __init__(self, side_a, side_b, name):
        self.a, self.b, self.name = np.asarray(side_a, float), np.asarray(side_b, float), name

    def outline(self):
        """The closed outline, counterclockwise seen from +z: A from the leading edge to the
        trailing edge, B back (its first point left out when it is A's, a sharp leading edge)."""
        back = self.b[::-1] if np.linalg.norm(self.b[0] - self.a[0]) > 1e-9 else self.b[:0:-1]
        points = np.vstack([self.a, back])
        return points if polygon_area(points) > 0 else points[::-1]

    def rotated(self, angle_rad):
        c, s = math.cos(angle_rad), math.sin(angle_rad)
        turn = np.array([[c, -s], [s, c]])
        return Profile(self.a @ turn.T, self.b @ turn.T, self.name)


def read_profile(path):
    """A Table 2 file (side,r_mm,theta_deg; '#' comment lines) as a Profile. Refuses a file with
    a side other than A or B, or fewer than 3 points on a side."""
    sides = {"A": [], "B": []}
    with open(path) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            if row["side"] not in sides:
                raise ValueError("%s: side %r: only A and B are allowed" % (path, row["side"]))
            r, theta = 1e-3 * float(row["r_mm"]), math.radians(float(row["theta_deg"]))
            sides[row["side"]].append((r * math.cos(theta), r * math.sin(theta)))
    for side, points in sides.items():
        if len(points) < 3:
            raise ValueError("%s: side %s has %d points, at least 3 are needed" % (path, side, len(points)))
    return Profile(sides["A"], sides["B"], os.path.splitext(os.path.basename(path))[0])


def blade():
    return read_profile(os.path.join(DATA, "impeller_blade.csv"))


def vane():
    return read_profile(os.path.join(DATA, "diffuser_vane.csv"))


def polygon_area(points):
    """Signed area (m^2), positive for a counterclockwise polygon."""
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def distance_to_polyline(point, line):
    best = math.inf
    for p, q in zip(line[:-1], line[1:]):
        d = q - p
        t = min(1.0, max(0.0, float(np.dot(point - p, d) / np.dot(d, d))))
        best = min(best, float(np.linalg.norm(point - (p + t * d))))
    return best


def thickness_m(profile):
    """The distance of each point of B from the polyline of A (the profile's thickness along it)."""
    return np.array([distance_to_polyline(p, profile.a) for p in profile.b])


def angle_from_radial_deg(profile, r_m):
    """The angle between side A's direction and the radial direction at radius r (degrees): the
    blade (or vane) angle measured from radial, as Table 1 gives beta and alpha."""
    radii = np.linalg.norm(profile.a, axis=1)
    i = int(np.searchsorted(radii, r_m))
    i = min(max(i, 1), len(radii) - 1)
    d = profile.a[i] - profile.a[i - 1]
    mid = 0.5 * (profile.a[i] + profile.a[i - 1])
    radial = mid / np.linalg.norm(mid)
    return math.degrees(math.acos(abs(float(np.dot(d, radial))) / float(np.linalg.norm(d))))


def cap_triangles(profile):
    """The outline's interior as triangles (indices into outline()): the strip between the two
    surfaces, point i of A with point i of B. Refuses a profile whose strip folds over (a
    triangle turned the other way, or areas that do not add up to the outline's)."""
    outline = profile.outline()
    n = len(outline)
    index = {tuple(np.round(p, 12)): k for k, p in enumerate(outline)}
    a = [index[tuple(np.round(p, 12))] for p in profile.a]
    b = [index[tuple(np.round(p, 12))] for p in profile.b]
    tris = []
    for i in range(min(len(a), len(b)) - 1):
        quad = [a[i], a[i + 1], b[i + 1], b[i]]
        for tri in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
            if len(set(tri)) == 3:
                tris.append(tri)
    areas = [polygon_area(outline[list(t)]) for t in tris]
    if any(area <= 0 for area in areas) and not all(area < 0 for area in areas):
        raise ValueError("%s: the strip between its surfaces folds over: give both sides the same "
                         "number of points, from the leading edge" % profile.name)
    if areas[0] < 0:
        tris = [(t[0], t[2], t[1]) for t in tris]
    if abs(abs(sum(areas)) - polygon_area(outline)) > 1e-9 * n:
        raise ValueError("%s: the strip's area %.6g m^2 is not the outline's %.6g m^2"
                         % (profile.name, abs(sum(areas)), polygon_area(outline)))
    return tris


def extruded_triangles(profile, z0, z1):
    """A closed prism of the profile from z0 to z1, as triangles of 3-D points, normals outward."""
    outline, tris = profile.outline(), cap_triangles(profile)
    bottom = [(float(x), float(y), z0) for x, y in outline]
    top = [(float(x), float(y), z1) for x, y in outline]
    out = [(bottom[i], bottom[k], bottom[j]) for i, j, k in tris] + [(top[i], top[j], top[k]) for i, j, k in tris]
    n = len(outline)
    for i in range(n):
        j = (i + 1) % n
        out += [(bottom[i], bottom[j], top[j]), (bottom[i], top[j], top[i])]
    return out


def impeller_triangles(z0, z1):
    """The 7 blades, pitch 360/7 deg, from z0 to z1."""
    one = blade()
    return [t for k in range(BLADES) for t in extruded_triangles(one.rotated(2 * math.pi * k / BLADES), z0, z1)]


def read_numbers(path):
    """A data file of numbers (a header line of names, '#' comment lines) as an array of rows."""
    with open(path) as f:
        return np.array([[float(v) for v in row.values()] for row in
                         csv.DictReader(line for line in f if not line.startswith("#"))])


def periodic_mean(x, y, period):
    """The mean of y(x) over one period by the trapezoid rule, closed across the period's ends."""
    order = np.argsort(x)
    x, y = np.asarray(x, float)[order], np.asarray(y, float)[order]
    xx, yy = np.append(x, x[0] + period), np.append(y, y[0])
    return float(np.sum(0.5 * (yy[1:] + yy[:-1]) * np.diff(xx))) / period


def impeller_outlet_averages(path=None):
    """The measured velocities at R/R2 = 1.02 (impeller_outlet_velocity.csv) averaged as the
    comparison uses them: over two blade pitches (periodic), then over the four instants; per span,
    and over the span (trapezoid over the measured Z/B 0.05-0.95). `mass` weighs c_u with the
    radial velocity (the swirl the through-flow carries: the work input). Returns a dict of
    floats (over U2) and per_span: {z_over_b: (cr, cu)}."""
    path = path or os.path.join(DATA, "impeller_outlet_velocity.csv")
    rows = read_numbers(path)
    instants, spans = sorted(set(rows[:, 0])), sorted(set(rows[:, 1]))
    cr, cu, crcu = (np.zeros((len(instants), len(spans))) for _ in range(3))
    for i, t in enumerate(instants):
        for j, z in enumerate(spans):
            s = rows[(rows[:, 0] == t) & (rows[:, 1] == z)]
            cr[i, j] = periodic_mean(s[:, 2], s[:, 3], 2.0)
            cu[i, j] = periodic_mean(s[:, 2], s[:, 4], 2.0)
            crcu[i, j] = periodic_mean(s[:, 2], s[:, 3] * s[:, 4], 2.0)
    z = np.array(spans)

    def over_span(v):
        return float(np.sum(0.5 * (v[1:] + v[:-1]) * np.diff(z)) / (z[-1] - z[0]))

    mid = spans.index(0.5)
    return {"cr_over_u2_midspan": float(cr[:, mid].mean()), "cu_over_u2_midspan": float(cu[:, mid].mean()),
            "cr_over_u2_span_average": over_span(cr.mean(axis=0)), "cu_over_u2_span_average": over_span(cu.mean(axis=0)),
            "cu_over_u2_mass_average": over_span(crcu.mean(axis=0)) / over_span(cr.mean(axis=0)),
            "instants": instants,
            "per_span": {z: (float(cr[:, j].mean()), float(cu[:, j].mean())) for j, z in enumerate(spans)}}


def measured_profile(z_over_b=0.5, bins=100, path=None):
    """The measured c_r and c_u over U2 across one pitch at span z_over_b: the four instants and
    the two pitches of the data folded onto one pitch, in `bins` bins (the data's fraction)."""
    path = path or os.path.join(DATA, "impeller_outlet_velocity.csv")
    rows = read_numbers(path)
    rows = rows[np.abs(rows[:, 1] - z_over_b) < 1e-9]
    k = np.minimum((np.mod(rows[:, 2], 1.0) * bins).astype(int), bins - 1)
    counts = np.bincount(k, minlength=bins).astype(float)
    fill = counts > 0
    cr = np.bincount(k, rows[:, 3], minlength=bins)[fill] / counts[fill]
    cu = np.bincount(k, rows[:, 4], minlength=bins)[fill] / counts[fill]
    return ((np.arange(bins) + 0.5) / bins)[fill], cr, cu


def casing_radii_over_r2(path=None):
    """The ten radii of the casing's pressure taps (casing_pressure.csv), over R2."""
    return sorted(set(read_numbers(path or os.path.join(DATA, "casing_pressure.csv"))[:, 0].tolist()))


def measured_casing_pressure(bins=100, path=None):
    """The measured casing pressure coefficient (vane-averaged) at each tap radius across one
    blade pitch: the data's two pitches folded onto one in `bins` bins of the data's angle (its
    origin is not documented; it grows outward along the blade as Table 2's). Returns (radii over
    R2, bin centres as pitch fractions, cp[radius, bin], NaN where a bin holds no point)."""
    rows = read_numbers(path or os.path.join(DATA, "casing_pressure.csv"))
    radii = sorted(set(rows[:, 0].tolist()))
    cp = np.full((len(radii), bins), np.nan)
    for i, r in enumerate(radii):
        s = rows[rows[:, 0] == r]
        k = np.minimum((np.mod(s[:, 1] / (360.0 / BLADES), 1.0) * bins).astype(int), bins - 1)
        counts = np.bincount(k, minlength=bins)
        cp[i, counts > 0] = np.bincount(k, s[:, 2], minlength=bins)[counts > 0] / counts[counts > 0]
    return np.array(radii), (np.arange(bins) + 0.5) / bins, cp
