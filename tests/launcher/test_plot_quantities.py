#!/usr/bin/python3
"""Checks of python/fsi/plot_quantities.py on hand-written results files (the documented
layout of structure.h5 and coupling.h5): the picture and forces.csv when there is something to
show, nothing at all (and exit 0, silent) when there is not.
    /usr/bin/python3 tests/launcher/test_plot_quantities.py
"""
import csv
import os
import shutil
import subprocess
import tempfile
import unittest

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "python", "fsi", "plot_quantities.py")


def write_structure_h5(path, probes, n_saved=4):
    time_s = np.linspace(0.0, 0.03, n_saved)
    config = "probes:\n" + "".join(f"  - {{name: {p}, structure: s}}\n" for p in probes)
    with h5py.File(path, "w") as f:
        f.attrs["config_yaml"] = config
        f["time_s"] = time_s
        f.create_group("structures")
        for k, name in enumerate(probes):
            g = f.create_group(f"probes/{name}")
            g["position_m"] = np.column_stack([time_s, -time_s, np.full(n_saved, float(k))])
            g["velocity_m_per_s"] = np.tile([1.0, -1.0, 0.0], (n_saved, 1))


def write_coupling_h5(path, bodies=(), n_steps=5):
    time_s = 1e-3 * np.arange(1, n_steps + 1)
    with h5py.File(path, "w") as f:
        f["time_s"] = time_s
        f["total_force_on_fluid_n"] = np.column_stack([time_s, 2 * time_s, 3 * time_s])
        for name in bodies:
            f[f"rigid_bodies/{name}/force_n"] = np.ones((n_steps, 3))
            f[f"rigid_bodies/{name}/torque_n_m"] = np.zeros((n_steps, 3))


class PlotQuantities(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp(prefix="plot_quantities_")

    def tearDown(self):
        shutil.rmtree(self.out)

    def path(self, name):
        return os.path.join(self.out, name)

    def run_script(self):
        result = subprocess.run(["/usr/bin/python3", SCRIPT, self.out], capture_output=True, text=True, timeout=120)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        return result

    def test_nothing_to_show_writes_nothing_and_says_nothing(self):
        write_structure_h5(self.path("structure.h5"), probes=[])
        result = self.run_script()
        self.assertEqual(result.stdout + result.stderr, "")
        self.assertEqual(sorted(os.listdir(self.out)), ["structure.h5"])

    def test_an_empty_folder_is_fine_too(self):
        self.assertEqual(self.run_script().stdout, "")
        self.assertEqual(os.listdir(self.out), [])

    def test_probes_alone_give_the_picture_and_no_forces_csv(self):
        write_structure_h5(self.path("structure.h5"), probes=["tip", "centre"])
        open(self.path("forces.csv"), "w").write("stale\n")
        self.run_script()
        with open(self.path("quantities.png"), "rb") as png:
            self.assertEqual(png.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertFalse(os.path.exists(self.path("forces.csv")), "a stale forces.csv stays behind")

    def test_coupled_run_writes_forces_csv_aligned_with_its_time(self):
        write_structure_h5(self.path("structure.h5"), probes=["centre"])
        write_coupling_h5(self.path("coupling.h5"), bodies=["pole"])
        self.run_script()
        with open(self.path("forces.csv")) as f:
            rows = list(csv.reader(f))
        self.assertEqual(rows[0], ["time_s", "total_force_on_fluid.x_n", "total_force_on_fluid.y_n",
                                   "total_force_on_fluid.z_n", "pole.force_x_n", "pole.force_y_n", "pole.force_z_n",
                                   "pole.torque_x_n_m", "pole.torque_y_n_m", "pole.torque_z_n_m"])
        self.assertEqual(len(rows), 1 + 5)
        self.assertAlmostEqual(float(rows[2][0]), 0.002)
        self.assertAlmostEqual(float(rows[2][3]), 0.006)
        self.assertTrue(os.path.exists(self.path("quantities.png")))

    def test_a_stale_picture_goes_when_the_run_has_nothing_to_show(self):
        open(self.path("quantities.png"), "w").write("stale")
        self.run_script()
        self.assertFalse(os.path.exists(self.path("quantities.png")))


if __name__ == "__main__":
    unittest.main()
