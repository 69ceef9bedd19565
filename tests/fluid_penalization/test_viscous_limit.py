#!/usr/bin/python3
"""The time-step limit of OpenFOAM's PISO loop in a viscous flow, and the runaway check of a
body's load (fluid_adapter/PisoLimit.hpp, fluid_adapter/rigid/RunawayLoadCheck.hpp;
docs/verification.md, "The limits of PISO"). Label: fluid_penalization.

PisoLimit: a lid-driven cavity (quasi-2D, 20 x 20 cells, no body) with the project's PIMPLE
  settings (momentum predictor, two correctors, measured to diverge above a viscous number
  nu dt sum 1/dx^2 of 30.5): at 0.78 of the limit it runs 150 steps and its speeds stay those of
  the lid; at 1.2 times the limit it is refused before its first step, naming the largest
  stable time step (0.8 of the limit).
RunawayLoad: a penalized cylinder turning slowly in a closed box (3D, 20^3 cells) at twice the
  limit, run anyway (viscous_limit: warn): the force on it, which symmetry makes zero, grows by
  a constant factor every step while its torque stays right; the run stops once it has grown 30
  steps in a row (before any velocity nears the speed limit), naming the body, the load and the
  step, with the fields of that step written.
"""

import os
import re
import subprocess
import unittest

from penalization_support import (BIN_DIR, LAUNCHER, PYTHON, Block, PenalizationTest, cylinder_triangles, latest_time_dir,
                                  read_internal_field, write_openfoam_case, write_stl, np, yaml)

NU = 1.0e-3       # m^2/s
LID = 0.0015      # m/s
LIMIT = 30.5      # the measured limit of D for momentumPredictor yes, nCorrectors 2


def write_flow_alone_case(folder, dt, n_steps, surfaces=(), viscous_limit="refuse"):
    case = {
        "run": {"end_time_s": n_steps * dt, "time_step_s": dt, "output_interval_s": n_steps * dt},
        "gravity_m_per_s2": [0.0, 0.0, 0.0],
        "structures": [],
        "fluid": {"openfoam": {"case_directory": "openfoam", "density_kg_per_m3": 1000.0,
                               "penalization_time_s": 1e-6, "viscous_limit": viscous_limit}},
    }
    if surfaces:
        case["collisions"] = {"threshold_m": 5.0e-4, "target_distance_m": 5.0e-4, "surfaces": list(surfaces)}
    with open(os.path.join(folder, "case.yaml"), "w") as f:
        yaml.safe_dump(case, f, default_flow_style=None, sort_keys=False)


class FlowAlone(PenalizationTest):
    def launch(self, case, out):
        made = subprocess.run([PYTHON, LAUNCHER, "--bin-dir", BIN_DIR, "-o", out, case], stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
        return made.returncode, made.stdout


class PisoLimit(FlowAlone):
    N = 20
    HALF = 0.05

    def cavity(self, name, viscous_number, n_steps):
        """The lid-driven cavity at D = nu dt (1/dx^2 + 1/dy^2): (exit code, output, folder)."""
        h = 2 * self.HALF / self.N
        dt = viscous_number * h * h / (2.0 * NU)
        case = os.path.join(self.tmp, name)
        out = case + "-out"
        os.makedirs(case)
        block = Block([-self.HALF, -self.HALF, 0.0], [self.HALF, self.HALF, h], [self.N, self.N, 1])
        patches = {"walls": ("wall", ["xmin", "xmax", "ymin"]), "lid": ("wall", ["ymax"]),
                   "frontAndBack": ("empty", ["zmin", "zmax"])}
        write_openfoam_case(os.path.join(case, "openfoam"), block, patches, NU, (0, 0, 0),
                            {"walls": "type noSlip;", "lid": "type fixedValue; value uniform (%r 0 0);" % LID,
                             "frontAndBack": "type empty;"},
                            {"walls": "type zeroGradient;", "lid": "type zeroGradient;", "frontAndBack": "type empty;"})
        write_flow_alone_case(case, dt, n_steps)
        code, log = self.launch(case, out)
        return code, log, out

    def max_speed(self, out):
        u = read_internal_field(os.path.join(latest_time_dir(os.path.join(out, "openfoam")), "U"), self.N * self.N)
        return float(np.max(np.linalg.norm(u, axis=1)))

    def test_a_time_step_over_the_limit_is_refused_naming_the_largest_stable_one(self):
        code, log, out = self.cavity("under", 0.78 * LIMIT, 150)
        self.assertEqual(code, 0, log[-3000:])
        self.assertIn("viscous number nu_eff dt sum 1/dx^2", log)
        speed = self.max_speed(out)
        self.assertLess(speed, 1.05 * LID)  # a steady cavity: no speed above the lid's
        print("lid-driven cavity at D = %.1f (0.78 of the limit): 150 steps, max |U| %.4g m/s (lid %g)"
              % (0.78 * LIMIT, speed, LID))

        code, log, _ = self.cavity("over", 1.2 * LIMIT, 150)
        self.assertEqual(code, 2, log[-3000:])
        self.assertIn("diverges above 30.5", log)
        stable = re.search(r"Use run\.time_step_s <= ([0-9.e+-]+) s", log)
        self.assertIsNotNone(stable, log[-3000:])
        h = 2 * self.HALF / self.N
        self.assertAlmostEqual(float(stable.group(1)) * 2.0 * NU / (h * h), 0.8 * LIMIT, delta=0.01 * LIMIT)
        print("at D = %.1f: refused, largest stable time step %s s" % (1.2 * LIMIT, stable.group(1)))


class RunawayLoad(FlowAlone):
    def test_a_load_growing_without_bound_stops_the_run(self):
        n, half, radius, omega = 20, 0.05, 0.015, 0.1
        h = 2 * half / n
        dt = 2.0 * LIMIT * h * h / (3.0 * NU)  # D = nu dt 3 / h^2 = twice the limit
        case = os.path.join(self.tmp, "cylinder")
        out = case + "-out"
        os.makedirs(case)
        block = Block([-half] * 3, [half] * 3, [n] * 3)
        write_openfoam_case(os.path.join(case, "openfoam"), block,
                            {"walls": ("wall", ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"])}, NU, (0, 0, 0),
                            {"walls": "type noSlip;"}, {"walls": "type zeroGradient;"})
        write_stl(os.path.join(case, "rotor.stl"), cylinder_triangles(radius, -radius, radius, 128), "rotor")
        rotor = {"mesh": {"file": "rotor.stl"}, "motion": {"rotation": {
            "axis_point_m": [0.0, 0.0, 0.0], "axis_direction": [0.0, 0.0, 1.0], "rate_rad_per_s": omega}}}
        write_flow_alone_case(case, dt, 120, [rotor], viscous_limit="warn")
        code, log = self.launch(case, out)
        self.assertEqual(code, 1, log[-3000:])
        self.assertIn("running anyway", log)
        found = re.search(r"the fluid diverged at step (\d+) \(t = [0-9.e+-]+ s\): the force on rigid body "
                          r"'surface0' grows without bound: it grew by at least 10 % at each of the last 30 steps, "
                          r"from ([0-9.e+-]+) N to ([0-9.e+-]+) N", log)
        self.assertIsNotNone(found, log[-3000:])
        step = int(found.group(1))
        self.assertLess(step, 60)  # 47 measured; at D = 120 the speed limit alone stopped it at step 62
        rows = np.loadtxt(os.path.join(out, "forces.csv"), delimiter=",", skiprows=1, ndmin=2)
        torque = rows[:, 6]
        # The torque stays right while the force runs away: steady within 2 % over the last 10 steps.
        self.assertLess(np.ptp(torque[-10:]) / abs(np.mean(torque[-10:])), 0.02)
        self.assertIsNotNone(latest_time_dir(os.path.join(out, "openfoam")))
        print("penalized cylinder at D = %.0f: stopped at step %d, force %s N -> %s N, torque %.4g N m"
              % (2 * LIMIT, step, found.group(2), found.group(3), torque[-1]))


if __name__ == "__main__":
    unittest.main()
