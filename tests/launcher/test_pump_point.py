#!/usr/bin/python3
"""Checks of python/fsi/pump_point.py's revolution statistics on a hand-written run folder (the
documented layout: forces.csv and the total-pressure function objects' .dat files), the torque
by part with the staircase's share beside it in ./fsi pump-compare's table, and of the
refusals of ./fsi pump-compare and pump_ami_run.py --restart before anything runs.
    /usr/bin/python3 tests/launcher/test_pump_point.py
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = os.path.join(HERE, "..", "..", "python")
sys.path.insert(0, PYTHON)
from fsi import pump_compare  # noqa: E402
from fsi import pump_point  # noqa: E402

OMEGA = 150.0   # rad/s
RHO, G = 1000.0, 9.81


def write_dat(folder, name, start, t, values):
    path = os.path.join(folder, "openfoam", "postProcessing", name, repr(start))
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, "surfaceFieldValue.dat"), "w") as f:
        f.write("# Time areaAverage\n")
        for a, b in zip(t, values):
            f.write("%.10g %.10g\n" % (a, b))


def write_run(folder, torque_of_t, head_of_t, revolutions, steps_per_rev=200):
    """forces.csv (torque -T about +z: the shaft supplies T) and inlet/outlet total pressures
    giving the head head_of_t (m), sampled at the ends of the steps."""
    period = 2 * math.pi / OMEGA
    t = np.arange(1, revolutions * steps_per_rev + 1) * period / steps_per_rev
    with open(os.path.join(folder, "forces.csv"), "w") as f:
        f.write("time_s,body0.fx_n,body0.fy_n,body0.fz_n,body0.tx_n_m,body0.ty_n_m,body0.tz_n_m\n")
        for a in t:
            f.write("%.10g,0,0,0,0,0,%.10g\n" % (a, -torque_of_t(a)))
    write_dat(folder, "inletTotalPressure", 0, t, np.full(len(t), 1000.0))
    write_dat(folder, "outletTotalPressure", 0, t, 1000.0 + RHO * G * head_of_t(t))
    return period


class RevolutionMeans(unittest.TestCase):
    def test_means_standard_error_and_drift_of_a_pulsating_drifting_pump(self):
        # Torque 10 N m + 0.1 N m per revolution with a once-per-revolution pulsation of 2 N m
        # (zero over each whole revolution); head 5 m with a pulsation at 3 per revolution.
        with tempfile.TemporaryDirectory() as folder:
            period = 2 * math.pi / OMEGA
            write_run(folder, lambda t: 10.0 + 0.1 * np.floor(t / period - 1e-9) + 2.0 * np.sin(OMEGA * t),
                      lambda t: 5.0 + 0.5 * np.sin(3 * OMEGA * t), revolutions=8)
            p = pump_point.operating_point(folder, OMEGA, [0, 0, 1], 0.1, 0.02, average_revolutions=8,
                                           settle_revolutions=1)
            self.assertEqual(p["revolutions_averaged"], 7)
            expected = [10.0 + 0.1 * k for k in range(1, 8)]
            # Each revolution's mean: the drift step, the pulsation averaging out (1e-3 N m: the
            # sampling of a sine at 200 points a revolution is exact to round-off).
            np.testing.assert_allclose(p["revolution_torque_n_m"], expected, atol=1e-3)
            np.testing.assert_allclose(p["revolution_head_m"], 5.0, atol=1e-3)
            self.assertAlmostEqual(p["torque_standard_error_n_m"], np.std(expected, ddof=1) / math.sqrt(7), places=4)
            self.assertAlmostEqual(p["torque_drift_last_3_revolutions"], 0.2 / np.mean(expected), places=4)
            self.assertLess(p["head_drift_last_3_revolutions"], 1e-3)
            self.assertLess(p["head_standard_error_m"], 1e-3)
            self.assertAlmostEqual(p["shaft_torque_n_m"], np.mean(expected), places=3)
            # The once-per-revolution amplitudes: 2 N m of torque; none of the head (its is at 3).
            self.assertAlmostEqual(p["torque_pulsation_amplitude_n_m"], 2.0, delta=0.01)
            self.assertAlmostEqual(p["torque_pulsation_1_per_rev"], 2.0 / p["shaft_torque_n_m"], delta=0.002)
            self.assertLess(p["head_pulsation_amplitude_m"], 0.01)

    def test_a_continued_run_counts_each_time_once_the_later_start_winning(self):
        with tempfile.TemporaryDirectory() as folder:
            period = write_run(folder, lambda t: 10.0 + 0 * t, lambda t: 5.0 + 0 * t, revolutions=4)
            # A continuation from 2 revolutions (the first run's rows after it are replaced).
            t = np.arange(401, 801) * period / 200
            write_dat(folder, "outletTotalPressure", 2 * period, t, np.full(len(t), 1000.0 + RHO * G * 6.0))
            time, _ = pump_point.read_dat(folder, "outletTotalPressure")
            self.assertEqual(len(time), 800)
            p = pump_point.operating_point(folder, OMEGA, [0, 0, 1], 0.1, 0.02, average_revolutions=2,
                                           settle_revolutions=2)
            np.testing.assert_allclose(p["revolution_head_m"], [6.0, 6.0], atol=1e-9)


class PartsOfTheBodyFittedRun(unittest.TestCase):
    def test_the_pressure_share_of_each_part_is_kept_apart(self):
        # moment.dat of two patches as OpenFOAM's forces function object writes them (total,
        # pressure, viscous; the fluid's moment about +z: the shaft supplies its negative): the
        # hub 1.5 N m of which 1.0 from the pressure, the blade 10 N m of which 9.8.
        from fsi import pump_ami_run
        with tempfile.TemporaryDirectory() as folder:
            period = write_run(folder, lambda t: 11.5 + 0 * t, lambda t: 5.0 + 0 * t, revolutions=3)
            t = np.arange(1, 601) * period / 200
            for part, (total, pressure) in {"hub": (1.5, 1.0), "blade_suction_side": (10.0, 9.8)}.items():
                path = os.path.join(folder, "openfoam", "postProcessing", "forces_" + part, "0")
                os.makedirs(path)
                with open(os.path.join(path, "moment.dat"), "w") as f:
                    f.write("# Time (total_x total_y total_z) (pressure_x pressure_y pressure_z) (viscous_x ...)\n")
                    for a in t:
                        f.write("%.10g (0 0 %r) (0 0 %r) (0 0 %r)\n" % (a, -total, -pressure, pressure - total))
            self.assertEqual(pump_ami_run.write_parts_csv(os.path.join(folder, "openfoam"), folder),
                             ["blade_suction_side", "hub"])
            p = pump_point.operating_point(folder, OMEGA, [0, 0, 1], 0.1, 0.02, average_revolutions=2,
                                           settle_revolutions=1)
            self.assertAlmostEqual(p["torque_by_part_n_m"]["hub"], 1.5, places=9)
            self.assertAlmostEqual(p["torque_by_part_n_m"]["blade_suction_side"], 10.0, places=9)
            self.assertAlmostEqual(p["pressure_torque_by_part_n_m"]["hub"], 1.0, places=9)
            self.assertAlmostEqual(p["pressure_torque_by_part_n_m"]["blade_suction_side"], 9.8, places=9)


class RotorBudget(unittest.TestCase):
    def test_the_rotor_loses_the_shaft_power_its_water_does_not_carry_out(self):
        # Shaft 12 N m at OMEGA: 1800 W. The energy flux out of the rotor's water pulsates once a
        # revolution about 1500 W (it stores nothing over a whole revolution): 300 W lost, 1/6.
        with tempfile.TemporaryDirectory() as folder:
            period = write_run(folder, lambda t: 12.0 + 0 * t, lambda t: 5.0 + 0 * t, revolutions=4)
            t = np.arange(1, 801) * period / 200
            p = pump_point.operating_point(folder, OMEGA, [0, 0, 1], 0.1, 0.02, average_revolutions=3)
            self.assertNotIn("rotor", p)   # a run without the function object: no budget
            write_dat(folder, "rotorEnergyFlux", 0, t, 1500.0 + 400.0 * np.sin(OMEGA * t))
            p = pump_point.operating_point(folder, OMEGA, [0, 0, 1], 0.1, 0.02, average_revolutions=3)
            self.assertAlmostEqual(p["rotor"]["energy_flux_out_w"], 1500.0, places=6)
            self.assertAlmostEqual(p["rotor"]["loss_w"], 300.0, places=6)
            self.assertAlmostEqual(p["rotor"]["loss_fraction"], 300.0 / 1800.0, places=9)


class Staircase(unittest.TestCase):
    def test_the_steps_share_of_each_part_is_read_and_shown_beside_it(self):
        # parts.csv and parts_staircase.csv of a penalized run (torques on the fluid about +z: the
        # shaft's share is minus them), none of the latter in the AMI run
        def write_parts(folder, name, torques):
            period = 2 * math.pi / OMEGA
            t = np.arange(1, 801) * period / 200
            with open(os.path.join(folder, name), "w") as f:
                f.write("time_s," + ",".join("body0.%s.t%s_n_m" % (p, c) for p in torques for c in "xyz") + "\n")
                for a in t:
                    f.write("%.10g," % a + ",".join("0,0,%.10g" % -v for v in torques.values()) + "\n")
        with tempfile.TemporaryDirectory() as ibm, tempfile.TemporaryDirectory() as ami:
            for folder, torque in ((ibm, 15.0), (ami, 14.0)):
                write_run(folder, lambda t, T=torque: T + 0 * t, lambda t: 5.0 + 0 * t, revolutions=4)
                write_parts(folder, "parts.csv", {"blade_suction_side": torque - 3.0, "hub": 3.0})
            write_parts(ibm, "parts_staircase.csv", {"blade_suction_side": 1.25, "hub": 0.5})
            points = {m: pump_point.operating_point(f, OMEGA, [0, 0, 1], 0.1, 0.02, average_revolutions=3)
                      for m, f in (("ibm", ibm), ("ami", ami))}
            for m in points:
                points[m]["front_side_space_leak_m3_per_s"], points[m]["front_side_space_leak_from"] = 0.0, "window"
            self.assertEqual(points["ibm"]["staircase_torque_by_part_n_m"], {"blade_suction_side": 1.25, "hub": 0.5})
            self.assertNotIn("staircase_torque_by_part_n_m", points["ami"])
            costs = {"ranks": 1, "ibm": {"cells": 1, "wall_s_per_revolution": 1.0},
                     "ami": {"cells": 1, "wall_s_per_revolution": 2.0}}
            text = pump_compare.table(points, pump_compare.compare(None, points, 1.0, costs))
            self.assertIn("| torque on blade_suction_side (N m) | 12.00 (steps 1.25) | 11.00 | +1.00 N m |", text)
            self.assertIn("| torque on hub (N m) | 3.00 (steps 0.50) | 3.00 | +0.00 N m |", text)
            self.assertRegex(text, r"staircase's steps.*\| 1\.75 \|")


class RunFingerprint(unittest.TestCase):
    def test_a_run_is_stale_when_its_own_inputs_change_and_only_then(self):
        from fsi import pump_compare
        with tempfile.TemporaryDirectory() as case:
            def write(path, text):
                os.makedirs(os.path.dirname(os.path.join(case, path)), exist_ok=True)
                with open(os.path.join(case, path), "w") as f:
                    f.write(text)
            write("case.yaml", "run: {}\n")
            write("pump.yaml", "impeller: {}\n")
            write("geometry/impeller.stl", "solid hub\nendsolid hub\n")
            write("presets/coarse-ami-mesh.yaml", "fluid: {}\n")
            write("openfoam-coarse-ami-mesh/system/controlDict", "a\n")
            write("openfoam-ami-coarse/system/controlDict", "b\n")
            os.makedirs(os.path.join(case, "openfoam-ami-coarse", "constant", "triSurface"))
            os.symlink(os.path.join("..", "..", "..", "geometry", "impeller.stl"),
                       os.path.join(case, "openfoam-ami-coarse", "constant", "triSurface", "impeller.stl"))
            before = {m: pump_compare.run_fingerprint(case, m, "coarse") for m in ("ibm", "ami")}
            # Another resolution's folders, a new preset, a script: neither run is stale.
            write("openfoam-ami-coarse-fine-blade/system/controlDict", "c\n")
            write("presets/coarse-fine-blade-ami-mesh.yaml", "run: {}\n")
            write("make_ami_case.py", "# changed\n")
            self.assertEqual({m: pump_compare.run_fingerprint(case, m, "coarse") for m in ("ibm", "ami")}, before)
            # The AMI folder's own file, and the geometry its link names: the AMI run only.
            write("openfoam-ami-coarse/system/controlDict", "b2\n")
            after = {m: pump_compare.run_fingerprint(case, m, "coarse") for m in ("ibm", "ami")}
            self.assertEqual(after["ibm"], before["ibm"])
            self.assertNotEqual(after["ami"], before["ami"])
            write("geometry/impeller.stl", "solid hub\nendsolid hub\n\n")
            self.assertNotEqual(pump_compare.run_fingerprint(case, "ami", "coarse"), after["ami"])
            # The case's keys: both.
            write("case.yaml", "run: {end_time_s: 1}\n")
            self.assertNotEqual(pump_compare.run_fingerprint(case, "ibm", "coarse"), before["ibm"])


class Refusals(unittest.TestCase):
    def run_module(self, *args):
        env = dict(os.environ, PYTHONPATH=PYTHON)
        return subprocess.run([sys.executable, "-m"] + list(args), capture_output=True, text=True, env=env,
                              stdin=subprocess.DEVNULL, timeout=60)

    def test_pump_compare_without_a_settled_state_names_the_command_that_makes_it(self):
        case = os.path.join(HERE, "..", "..", "cases", "centrifugal-pump")
        with tempfile.TemporaryDirectory() as out:
            made = self.run_module("fsi.pump_compare", "--bin-dir", out, "--from", os.path.join(out, "none"),
                                   "-o", out, case)
        self.assertNotEqual(made.returncode, 0)
        self.assertIn("the settled state", made.stderr)
        self.assertIn("./fsi pump-curve --points 1", made.stderr)

    def test_pump_compare_refuses_too_few_revolutions(self):
        case = os.path.join(HERE, "..", "..", "cases", "centrifugal-pump")
        made = self.run_module("fsi.pump_compare", "--bin-dir", "/nonexistent", "--revolutions", "3", case)
        self.assertNotEqual(made.returncode, 0)
        self.assertIn("--revolutions 3: at least 4", made.stderr)

    def test_pump_compare_refuses_a_run_folder_another_comparison_holds(self):
        import fcntl
        case = os.path.join(HERE, "..", "..", "cases", "centrifugal-pump")
        with tempfile.TemporaryDirectory() as out:
            os.makedirs(os.path.join(out, "ibm"))
            with open(os.path.join(out, "ibm", ".pump-compare.lock"), "w") as held:
                fcntl.flock(held, fcntl.LOCK_EX)
                made = self.run_module("fsi.pump_compare", "--bin-dir", out, "--from", out, "-o", out, case)
        self.assertNotEqual(made.returncode, 0)
        self.assertIn("is in use by another pump-compare", made.stderr)

    def test_pump_compare_keeps_each_resolution_in_its_own_folder(self):
        import fcntl
        import shutil
        case = os.path.join(HERE, "..", "..", "cases", "centrifugal-pump")
        with tempfile.TemporaryDirectory() as tmp:
            copy = os.path.join(tmp, "pump")
            os.makedirs(os.path.join(copy, "presets"))
            for name in ("case.yaml", "pump.yaml", os.path.join("presets", "coarse-fine-blade-ami-mesh.yaml")):
                shutil.copy(os.path.join(case, name), os.path.join(copy, name))
            os.makedirs(os.path.join(copy, "output", "pump-curve", "q1.00", "openfoam"))
            # The coarse pair's default folder is q1.00; the fine-blade pair's with the penalized impeller
            # on the fixed mesh, q1.00-coarse-fine-blade-fixed-mesh (held here, so the comparison stops
            # before it runs anything and names it).
            fine = os.path.join(copy, "output", "pump-compare", "q1.00-coarse-fine-blade-fixed-mesh", "ibm")
            os.makedirs(fine)
            with open(os.path.join(fine, ".pump-compare.lock"), "w") as held:
                fcntl.flock(held, fcntl.LOCK_EX)
                made = self.run_module("fsi.pump_compare", "--bin-dir", tmp, "--resolution", "coarse-fine-blade",
                                       "--penalized-mesh", "fixed", copy)
            # No turning-mesh preset at that resolution: refused, naming the option.
            missing = self.run_module("fsi.pump_compare", "--bin-dir", tmp, "--resolution", "coarse-fine-blade", copy)
            self.assertNotEqual(missing.returncode, 0)
            self.assertIn("--penalized-mesh turning", missing.stderr)
            self.assertIn("coarse-fine-blade-turning-mesh.yaml does not exist", missing.stderr)
            self.assertFalse(os.path.exists(os.path.join(copy, "output", "pump-compare", "q1.00")))
        self.assertNotEqual(made.returncode, 0)
        self.assertIn("is in use by another pump-compare", made.stderr)
        self.assertIn(fine, made.stderr)

    def test_summarize_without_finished_runs_runs_nothing_and_says_so(self):
        case = os.path.join(HERE, "..", "..", "cases", "centrifugal-pump")
        with tempfile.TemporaryDirectory() as out:
            made = self.run_module("fsi.pump_compare", "--bin-dir", out, "--from", out, "--summarize", "-o", out, case)
            self.assertEqual(sorted(os.listdir(out)), [])
        self.assertNotEqual(made.returncode, 0)
        self.assertIn("--summarize: %s has no finished run" % os.path.join(out, "ibm"), made.stderr)

    def test_ami_restart_without_a_run_says_so(self):
        case = os.path.join(HERE, "..", "..", "cases", "centrifugal-pump")
        with tempfile.TemporaryDirectory() as out:
            made = self.run_module("fsi.pump_ami_run", "--restart", "--ranks", "2", "--flow-rate", "0.02",
                                   "--end-time", "0.1", "-o", out, case)
        self.assertNotEqual(made.returncode, 0)
        self.assertIn("no fields to continue from on 2 ranks", made.stderr)


if __name__ == "__main__":
    unittest.main()
