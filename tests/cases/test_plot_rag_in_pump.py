#!/usr/bin/python3
"""Checks of python/fsi/plot_rag_in_pump.py (the pictures of cases/rag-in-pump) on a synthetic run
written here: a structure.h5 in the layout of docs/results.md (a 4 x 3 rag, 5 frames), small
ASCII STL files with the pump's region names (a box casing; an impeller of a hub plate, a shroud
plate and a blade plate) and a case.yaml whose impeller turns about -z. No executable needed.

    /usr/bin/python3 tests/cases/test_plot_rag_in_pump.py -v

PlotRagInPump: the PNG files are written with a plausible size; rag_wrap.png pictures the frame
with the most rag points within 1.5 x threshold of the impeller (the rag is laid 3 mm above the
hub plate whole in frame 2, by one row in frame 1, by two in frame 3, far from it in 0 and 4); a
run with a single frame gives its pictures too; without ffmpeg a warning and no video.
"""
import os
import shutil
import sys
import tempfile
import unittest
import warnings
from unittest import mock

try:
    import h5py
    import matplotlib.image
    import numpy as np
    import yaml
    from PIL import Image
except ImportError as e:  # ctest reports exit code 77 as "skipped", with this line
    print("SKIP: %s (install python3-h5py, python3-matplotlib, python3-yaml)" % e)
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in scripts/ or pump/
from fsi import plot_rag_in_pump  # noqa: E402  (python/fsi/plot_rag_in_pump.py)

THRESHOLD_M = 0.004
RATE = 10.0               # rad/s about -z
HUB_Z = -0.05             # the impeller's hub plate (its top), the rag is laid above it
ROWS_ABOVE_HUB = [        # per frame, the height of the rag's 4 rows above the hub (m)
    [0.10, 0.10, 0.10, 0.10],          # 0: far: no point in contact
    [0.003, 0.013, 0.023, 0.033],      # 1: one row (3 points) within 1.5 x 4 mm
    [0.003, 0.003, 0.003, 0.003],      # 2: every point (12)
    [0.003, 0.005, 0.020, 0.030],      # 3: two rows (6)
    [0.10, 0.10, 0.10, 0.10],          # 4: far
]
CONTACTS = [0, 3, 12, 6, 0]


def quad(a, b, c, d):
    return [[a, b, c], [a, c, d]]


def box_faces(low, high):
    """The 6 faces of an axis-aligned box, 2 triangles each: -x, +x, -y, +y, -z, +z."""
    (x0, y0, z0), (x1, y1, z1) = low, high
    return [quad((x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1)),
            quad((x1, y0, z0), (x1, y0, z1), (x1, y1, z1), (x1, y1, z0)),
            quad((x0, y0, z0), (x0, y0, z1), (x1, y0, z1), (x1, y0, z0)),
            quad((x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)),
            quad((x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)),
            quad((x0, y0, z1), (x0, y1, z1), (x1, y1, z1), (x1, y0, z1))]


def write_stl(path, regions):
    with open(path, "w") as f:
        for name, tris in regions.items():
            f.write("solid %s\n" % name)
            for tri in tris:
                f.write("facet normal 0 0 0\nouter loop\n")
                for v in tri:
                    f.write("vertex %.9g %.9g %.9g\n" % tuple(v))
                f.write("endloop\nendfacet\n")
            f.write("endsolid %s\n" % name)


def write_case(folder):
    """case.yaml, geometry/impeller.stl and geometry/casing.stl of a toy pump."""
    os.makedirs(os.path.join(folder, "geometry"))
    faces = box_faces((-0.2, -0.2, -0.3), (0.2, 0.2, 0.1))
    write_stl(os.path.join(folder, "geometry", "casing.stl"), {
        "inlet": faces[4], "suction_wall": faces[0], "volute_wall": faces[2] + faces[3],
        "cut_water": [faces[1][0]], "discharge_wall": [faces[1][1]], "outlet": faces[5]})
    r, zs = 0.05, -0.15
    plate = lambda z: quad((-r, -r, z), (r, -r, z), (r, r, z), (-r, r, z))  # noqa: E731
    write_stl(os.path.join(folder, "geometry", "impeller.stl"), {
        "hub": plate(HUB_Z), "shroud": plate(zs),
        "blade_pressure_side": quad((0.01, 0.001, zs), (0.05, 0.001, zs),
                                    (0.05, 0.001, HUB_Z), (0.01, 0.001, HUB_Z)),
        "blade_suction_side": quad((0.01, -0.001, zs), (0.01, -0.001, HUB_Z),
                                   (0.05, -0.001, HUB_Z), (0.05, -0.001, zs)),
        "blade_leading_edge": quad((0.01, -0.001, zs), (0.01, 0.001, zs),
                                   (0.01, 0.001, HUB_Z), (0.01, -0.001, HUB_Z)),
        "blade_trailing_edge": quad((0.05, -0.001, zs), (0.05, -0.001, HUB_Z),
                                    (0.05, 0.001, HUB_Z), (0.05, 0.001, zs)),
        "eye": [[(-0.01, -0.01, zs - 0.001), (0.01, -0.01, zs - 0.001), (0.0, 0.01, zs - 0.001)]]})
    case = {"run": {"end_time_s": 0.04, "time_step_s": 1e-3, "output_interval_s": 0.01},
            "collisions": {"threshold_m": THRESHOLD_M, "surfaces": [
                {"mesh": {"file": "geometry/impeller.stl"},
                 "motion": {"rotation": {"axis_point_m": [0, 0, 0], "axis_direction": [0, 0, -1],
                                         "rate_rad_per_s": RATE}}},
                {"mesh": {"file": "geometry/casing.stl", "fluid_side": "inside"}}]},
            "structures": [{"name": "rag", "model": "membrane", "size_m": [0.06, 0.04], "n_points": [4, 3]}]}
    with open(os.path.join(folder, "case.yaml"), "w") as f:
        yaml.safe_dump(case, f)


def write_run(folder, frames=None):
    """structure.h5 (docs/results.md) of a 4 x 3 rag over the hub plate, 2 cm across, at the
    heights of ROWS_ABOVE_HUB (or those of the frames listed)."""
    frames = range(len(ROWS_ABOVE_HUB)) if frames is None else frames
    x = np.array([-0.02, 0.0, 0.02])             # along s2
    y = np.array([-0.03, -0.01, 0.01, 0.03])     # along s1
    positions = []
    for k in frames:
        z = HUB_Z + np.array(ROWS_ABOVE_HUB[k])
        grid = np.stack(np.broadcast_arrays(x[None, :], y[:, None], z[:, None]), axis=-1)  # [4, 3, 3]
        positions.append(grid.reshape(-1, 3))
    positions = np.array(positions)
    os.makedirs(folder, exist_ok=True)
    with h5py.File(os.path.join(folder, "structure.h5"), "w") as f:
        f.attrs["status"] = "completed"
        f.attrs["units"] = "SI"
        f["time_s"] = 0.01 * np.arange(len(positions))
        f["step"] = 10 * np.arange(len(positions))
        g = f.create_group("structures/rag")
        g.attrs["model"] = "membrane"
        g.attrs["grid_shape"] = np.array([4, 3], dtype=np.int64)
        g.attrs["point_order"] = "row-major over (s1, s2): index = i1 * n2 + i2"
        g["position_m"] = positions
        g["velocity_m_per_s"] = np.zeros_like(positions)
        index = np.arange(12).reshape(4, 3)
        g["connectivity"] = np.stack([index[:-1, :-1], index[1:, :-1], index[1:, 1:], index[:-1, 1:]],
                                     axis=-1).reshape(-1, 4)


class PlotRagInPump(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="plot-rag-in-pump-")
        self.case = os.path.join(self.tmp, "case")
        self.run_dir = os.path.join(self.tmp, "run")
        write_case(self.case)

    def tearDown(self):
        if os.environ.get("FSI_KEEP_TEST_DIRS") != "1":
            shutil.rmtree(self.tmp, ignore_errors=True)
        else:
            print("kept", self.tmp)

    def assert_picture(self, path):
        self.assertTrue(os.path.isfile(path), path)
        self.assertGreater(os.path.getsize(path), 20e3, path)   # drawn, not blank
        self.assertLess(os.path.getsize(path), 5e6, path)
        height, width = matplotlib.image.imread(path).shape[:2]
        self.assertGreater(width, 500, path)
        self.assertGreater(height, 400, path)

    def test_pictures_and_the_frame_of_most_contact(self):
        write_run(self.run_dir)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")   # no ffmpeg: a warning, checked below
            written = plot_rag_in_pump.write_pictures(self.run_dir, self.case, frames=4, animation=True)
        for name in ("rag_sequence.png", "rag_wrap.png"):
            path = os.path.join(self.run_dir, name)
            self.assertIn(path, written)
            self.assert_picture(path)
        # The contact counts, exact within 1.5 x threshold whatever the impeller's pose.
        run, pump = plot_rag_in_pump.Run(self.run_dir), plot_rag_in_pump.Pump(self.run_dir, self.case)
        _, to_impeller = plot_rag_in_pump.distances(run, pump)
        self.assertEqual(list(plot_rag_in_pump.contact_counts(to_impeller, THRESHOLD_M)), CONTACTS)
        self.assertEqual(plot_rag_in_pump.wrap_frame(to_impeller, THRESHOLD_M), int(np.argmax(CONTACTS)))
        description = Image.open(os.path.join(self.run_dir, "rag_wrap.png")).text["Description"]
        self.assertTrue(description.startswith("frame 2 of 5,"), description)
        self.assertIn("12 points in contact", description)
        self.assertAlmostEqual(to_impeller[2].max(), 0.003, delta=1e-9)   # above the hub plate
        video = os.path.join(self.run_dir, "rag_passage.mp4")
        if shutil.which("ffmpeg"):
            self.assertIn(video, written)
            self.assertGreater(os.path.getsize(video), 1000)
            self.assertLess(os.path.getsize(video), 5e6)
        else:
            self.assertNotIn(video, written)

    def test_the_rags_largest_bend_round_the_leading_edge_is_the_wrap_picture(self):
        # rag_metrics.yaml says the rag bent 150 deg round the edge at t of frame 3: that frame is
        # drawn, not the frame of most contact (2); under its wrap angle, the contact's frame
        write_run(self.run_dir)
        times = plot_rag_in_pump.Run(self.run_dir).time_s
        for angle, frame in ((150.0, 3), (60.0, 2)):
            with open(os.path.join(self.run_dir, "rag_metrics.yaml"), "w") as f:
                yaml.safe_dump({"max_wrap_angle_deg": angle, "max_wrap_angle_time_s": float(times[3]),
                                "parameters": {"wrap_angle_deg": 90.0}}, f)
            written = plot_rag_in_pump.write_pictures(self.run_dir, self.case, animation=False)
            description = Image.open(written[1]).text["Description"]
            self.assertTrue(description.startswith("frame %d of 5," % frame), description)

    def test_one_frame(self):
        write_run(self.run_dir, frames=[3])
        written = plot_rag_in_pump.write_pictures(self.run_dir, self.case, animation=False)
        self.assertEqual(written, [os.path.join(self.run_dir, n) for n in ("rag_sequence.png", "rag_wrap.png")])
        for path in written:
            self.assert_picture(path)
        self.assertTrue(Image.open(written[1]).text["Description"].startswith("frame 0 of 1,"))

    def test_no_ffmpeg_warns_and_goes_on(self):
        write_run(self.run_dir, frames=[0, 2])
        with mock.patch.object(plot_rag_in_pump.shutil, "which", return_value=None):
            with self.assertWarnsRegex(UserWarning, "no ffmpeg"):
                written = plot_rag_in_pump.write_pictures(self.run_dir, self.case, frames=2)
        self.assertEqual(len(written), 2)
        self.assertFalse(os.path.exists(os.path.join(self.run_dir, "rag_passage.mp4")))


if __name__ == "__main__":
    unittest.main()
