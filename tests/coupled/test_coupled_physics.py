#!/usr/bin/python3
"""Coupled runs against derived references: the real fsi-coupler, fsi-structure --coupled and
fsi-prescribed-flow, started by python/fsi/fsi_launch.py, over ZeroMQ on loopback.

    FSI_BIN_DIR=build/bin /usr/bin/python3 tests/coupled/test_coupled_physics.py [Class]

With X_ib^n = X^n the penalty law of Eq. (5) acts on the structure as
    rho_1 (V^{n+1} - V^n) / dt = K dt (U - V^n)     (coupler/PenaltyCouplingLaw.hpp)
so for a rigidly moving sheet in a steady flow U - V^n = (1 - a)^n (U - V^0), a = K dt^2/rho_1.

Round-off floor used below: positions are stored with relative error eps, so each step's
velocity (X^{n+1} - X^n)/dt carries an error of about eps |X| / dt; n steps accumulate at most
n eps |X| / dt. The tolerances are ten times that bound (observed: about a hundredth of it).
"""

import math
import os
import unittest

from coupled_support import (EPS, StructureResults, TempDirTest, case_dir, load_case, np,
                             standalone, status_of, write_case)


def roundoff_velocity_tolerance(n_steps, max_abs_position, dt):
    return 10.0 * n_steps * EPS * max_abs_position / dt


def trapezoid_cumulative(t, y):
    return np.concatenate([[0.0], np.cumsum(np.diff(t) * (y[1:] + y[:-1]) / 2.0)])


class Relaxation(TempDirTest):
    """cases/sheet-in-uniform-flow: V^n = U (1 - (1 - a)^n), and how far that is from exp."""

    def test_sheet_velocity_follows_the_discrete_relaxation(self):
        case = case_dir("sheet-in-uniform-flow")
        c = load_case(case)
        K = float(c["coupling"]["stiffness_n_per_m_per_measure"])
        dt = float(c["run"]["time_step_s"])
        sheet = c["structures"][0]
        rho = float(sheet["material"]["mass_per_area_kg_per_m2"])
        area = float(sheet["size_m"][0]) * float(sheet["size_m"][1])
        U = np.array(c["fluid"]["prescribed"]["uniform"]["velocity_m_per_s"], dtype=float)
        a, tau = K * dt * dt / rho, rho / (K * dt)
        self.assertLess(a, 0.01, "the O(a) analysis below assumes a small a")

        out = os.path.join(self.tmp, "out")
        code, stderr = self.launch(case, out)
        self.assert_run_completed(out, code, stderr)
        r = StructureResults(out)
        t = r.time_s
        n = np.rint(t / dt)
        self.assertAlmostEqual(t[-1], float(c["run"]["end_time_s"]), delta=dt / 2)
        x = r.structures[sheet["name"]]["position_m"]
        v = r.structures[sheet["name"]]["velocity_m_per_s"]
        tol = roundoff_velocity_tolerance(n[-1], np.abs(x).max(), dt)

        # 1. Every point, every output time: the exact discrete law, to round-off.
        expected = np.outer(1.0 - (1.0 - a) ** n, U)                        # [times, 3]
        error = np.abs(v - expected[:, None, :]).max()
        self.assertLess(error, tol, "max |V - U (1 - (1 - a)^n)| = %.3g m/s" % error)
        # Positions: X^n = X^0 + dt sum_{k=1..n} V^k = X^0 + U (t - dt (1-a)(1-(1-a)^n)/a).
        shift = t - dt * (1.0 - a) * (1.0 - (1.0 - a) ** n) / a
        x_error = np.abs(x - x[:1] - np.outer(shift, U)[:, None, :]).max()
        self.assertLess(x_error, t[-1] * tol, "positions off by %.3g m" % x_error)

        # 2. The continuous relaxation U (1 - exp(-t/tau)) differs by U ((1-a)^n - exp(-n a)):
        # with x = n a, (1-a)^n = exp(-x - x a/2 - O(x a^2)), so the gap is x exp(-x) a/2
        # (1 + O(a)), largest at x = 1 (t = tau): a/(2e) |U|, bounded above by a/(2e(1-a)) and
        # below by (a/2 - a^2/8)/e. The sampled times include t = tau (n = 1/a).
        self.assertTrue(np.any(np.abs(n * a - 1.0) < 1e-9), "t = tau is not an output time")
        mean_v = v.mean(axis=1)
        gap = np.linalg.norm(mean_v - np.outer(1.0 - np.exp(-t / tau), U), axis=1).max() / np.linalg.norm(U)
        low, high = (a / 2 - a * a / 8) / math.e, a / (2 * math.e * (1 - a))
        self.assertGreater(gap, low - tol, "gap to exp(-t/tau): %.6g, expected >= %.6g" % (gap, low))
        self.assertLess(gap, high + tol, "gap to exp(-t/tau): %.6g, expected <= %.6g" % (gap, high))

        # 3. Action and reaction: the force on the fluid of step k (row k, written at t^{k+1})
        # is F_fsi^k = -K dt (U - V^k) summed over the area A: -K dt A (1 - a)^k U.
        with __import__("h5py").File(os.path.join(out, "coupling.h5"), "r") as f:
            force = f["total_force_on_fluid_n"][:]
            t_force = f["time_s"][:]
        k = np.rint(t_force / dt) - 1
        expected_force = -K * dt * area * np.outer((1.0 - a) ** k, U)
        f_error = np.abs(force - expected_force).max()
        self.assertLess(f_error, K * dt * area * tol, "total force on the fluid off by %.3g N" % f_error)


class HangingFilament(TempDirTest):
    """cases/hanging-filament-in-still-fluid against the same scene without fluid.

    In a fluid at rest the penalty law is the drag rho_1 dV/dt = -gamma rho_1 V with
    gamma = K dt / rho_1 = 1/tau, uniform along the filament: a mass-proportional damping.
    (i) The work it does: dE/dt = -2 gamma E_kin, so E_coupled(t) - E_alone(t) = -W(t),
        W(t) = 2 gamma int_0^t E_kin dt' (to first order in gamma t).
    (ii) Tiny K: for the linearised chain M x'' + S x = f, x(t) = int G(t - s) f(s) ds with
        |sin(w u)/w| <= u in every mode, so in the mass-weighted RMS norm
        rms(x_coupled - x_alone)(t) <= gamma t^2 / 2 max_{s<=t} rms V(s).
    (iii) Moderate K (tau = 1 s): the swing decays, the energy decreases at every output time,
        while alone the energy is conserved up to the scheme's fluctuation.
    """

    def run_variant(self, name, case):
        folder = write_case(os.path.join(self.tmp, name), case)
        out = os.path.join(self.tmp, "out-" + name)
        code, stderr = self.launch(folder, out)
        if "fluid" in case:
            self.assert_run_completed(out, code, stderr)
        else:
            self.assertEqual(code, 0, stderr[-3000:])
            self.assertEqual(status_of(os.path.join(out, "structure.h5")), "completed")
        return StructureResults(out)

    def test_drag_of_still_fluid(self):
        case = load_case(case_dir("hanging-filament-in-still-fluid"))
        self.assertIn("quiescent", case["fluid"]["prescribed"])
        chain = case["structures"][0]
        name = chain["name"]
        rho = float(chain["linear_density_kg_per_m"])
        dt = float(case["run"]["time_step_s"])
        K = float(case["coupling"]["stiffness_n_per_m_per_measure"])
        gamma = K * dt / rho

        alone = self.run_variant("alone", standalone(case))
        tiny_case = load_case(case_dir("hanging-filament-in-still-fluid"))
        tiny_a = 1e-9
        tiny_case["coupling"]["stiffness_n_per_m_per_measure"] = tiny_a * rho / dt ** 2
        tiny = self.run_variant("tiny", tiny_case)
        moderate = self.run_variant("moderate", case)
        t = alone.time_s
        np.testing.assert_allclose(tiny.time_s, t)
        np.testing.assert_allclose(moderate.time_s, t)

        e_alone = alone.energy(name)
        drift_alone = np.abs(e_alone - e_alone[0]).max()  # the time scheme's own fluctuation

        # (ii) tiny K: trajectories agree within the Green's-function bound.
        g_tiny = tiny_a / dt
        xa, xt = alone.structures[name]["position_m"], tiny.structures[name]["position_m"]
        va = alone.structures[name]["velocity_m_per_s"]
        rms_dx = np.sqrt(((xt - xa) ** 2).sum(axis=2).mean(axis=1))
        rms_v = np.maximum.accumulate(np.sqrt((va ** 2).sum(axis=2).mean(axis=1)))
        bound = g_tiny * t ** 2 / 2 * rms_v
        worst = np.max(rms_dx[1:] / bound[1:])
        self.assertLessEqual(worst, 1.0, "rms difference exceeds gamma t^2/2 max rms V by %.3g" % worst)
        # ... and the tiny drag is really there, doing the predicted work (i). Tolerance 10 % of
        # W: trapezoidal W on the output grid (h = output_interval_s) while E_kin carries the
        # stretching waves (~70 rad/s): (w h)^2/12 ~ 4 %; the O(gamma t) terms are 1e-5.
        w_tiny = 2 * g_tiny * trapezoid_cumulative(t, alone.structures[name]["kinetic_energy_j"])
        d_e = tiny.energy(name) - e_alone
        self.assertLess(np.abs(d_e + w_tiny).max(), 0.1 * w_tiny[-1],
                        "E_tiny - E_alone = %.4g J at the end, -W = %.4g J" % (d_e[-1], -w_tiny[-1]))

        # (iii) moderate K: energy balance, monotone decay; alone: no decay.
        e_mod = moderate.energy(name)
        w_mod = 2 * gamma * trapezoid_cumulative(t, moderate.structures[name]["kinetic_energy_j"])
        balance = np.abs(e_mod - e_mod[0] + w_mod)
        self.assertLess(balance.max(), 2 * drift_alone + 0.1 * w_mod[-1] * gamma * t[-1],
                        "E(t) - E(0) + W(t) up to %.3g J (W(T) = %.3g J)" % (balance.max(), w_mod[-1]))
        self.assertGreater(w_mod[-1], 50 * drift_alone, "the drag should dissipate far more than the "
                           "scheme's own energy fluctuation")
        steps = np.diff(e_mod)
        self.assertTrue(np.all(steps < 0), "energy rises between outputs by up to %.3g J" % steps.max())
        self.assertLess(drift_alone, 0.02 * w_mod[-1], "alone, the energy should be conserved")
        # The swing: every mode decays as exp(-gamma t/2), so E_kin,coupled(t) ~ exp(-gamma t)
        # E_kin,alone(t). Compared as sums over the last 0.8 s (several beats of the modes), to
        # 10 %: the damped modes also run slower by gamma^2/(8 w^2) ~ 1 % (w >= 3.8 rad/s), a
        # phase slip of up to 0.1 rad by the end. Undamped, the ratio would be exp(gamma t) ~ 5.
        last = t >= t[-1] - 0.8
        ka, km = alone.structures[name]["kinetic_energy_j"], moderate.structures[name]["kinetic_energy_j"]
        ratio = km[last].sum() / (np.exp(-gamma * t[last]) * ka[last]).sum()
        self.assertAlmostEqual(ratio, 1.0, delta=0.1, msg="coupled swing vs exp(-t/tau) x alone")


class TwoSheets(TempDirTest):
    """cases/two-sheets-in-shear-flow: each sheet relaxes to the flow at its own height."""

    def test_each_sheet_gets_its_own_flow(self):
        case = case_dir("two-sheets-in-shear-flow")
        c = load_case(case)
        K = float(c["coupling"]["stiffness_n_per_m_per_measure"])
        dt = float(c["run"]["time_step_s"])
        shear = c["fluid"]["prescribed"]["shear"]
        e = np.array(shear["flow_direction"], float)
        g = np.array(shear["gradient_direction"], float)
        e, g = e / np.linalg.norm(e), g / np.linalg.norm(g)
        self.assertAlmostEqual(abs(e[2]), 0.0)  # no z flow: the sheets keep their heights
        x0 = np.array(shear["reference_point_m"], float)
        u0 = np.array(shear["reference_velocity_m_per_s"], float)
        self.assertAlmostEqual(u0[2], 0.0)
        rate = float(shear["shear_rate_1_per_s"])

        def flow(x):
            return u0 + rate * np.dot(x - x0, g) * e

        out = os.path.join(self.tmp, "out")
        code, stderr = self.launch(case, out)
        self.assert_run_completed(out, code, stderr)
        r = StructureResults(out)
        n = np.rint(r.time_s / dt)
        final_velocities = []
        for s in c["structures"]:
            res = r.structures[s["name"]]
            x, v = res["position_m"], res["velocity_m_per_s"]
            self.assertEqual(x.shape[1], int(s["n_points"][0]) * int(s["n_points"][1]))
            rho = float(s["material"]["mass_per_area_kg_per_m2"])
            a = K * dt * dt / rho
            tol = roundoff_velocity_tolerance(n[-1], np.abs(x).max(), dt)
            # Heights stay put (the flow has no z component), so u(z_s) is constant per sheet.
            self.assertLess(np.abs(x[:, :, 2] - x[0, :, 2]).max(), tol * r.time_s[-1])
            u = np.array([flow(p) for p in x[0]])                            # [points, 3]
            expected = (1.0 - (1.0 - a) ** n)[:, None, None] * u[None, :, :]
            error = np.abs(v - expected).max()
            self.assertLess(error, tol, "%s: max |V - u(z) (1 - (1 - a)^n)| = %.3g m/s"
                            % (s["name"], error))
            final_velocities.append(v[-1].mean(axis=0))
        # Points at different heights end at different velocities (checked above against
        # u(z) point by point; here only that the scene really tells the sheets apart).
        self.assertGreater(np.linalg.norm(final_velocities[0] - final_velocities[1]), 1e3 * tol)

        # Action and reaction, per sheet: F^k = -K dt sum_s A_s (1 - a_s)^k u(z_s).
        import h5py
        with h5py.File(os.path.join(out, "coupling.h5"), "r") as f:
            force, t_force = f["total_force_on_fluid_n"][:], f["time_s"][:]
        k = np.rint(t_force / dt) - 1
        expected_force = np.zeros_like(force)
        scale = 0.0
        for s in c["structures"]:
            x0s = r.structures[s["name"]]["position_m"][0]
            a = K * dt * dt / float(s["material"]["mass_per_area_kg_per_m2"])
            area = float(s["size_m"][0]) * float(s["size_m"][1])
            expected_force += -K * dt * area * np.outer((1.0 - a) ** k, flow(x0s.mean(axis=0)))
            scale = max(scale, K * dt * area)
        tol = roundoff_velocity_tolerance(n[-1], 0.1, dt)
        self.assertLess(np.abs(force - expected_force).max(), 2 * scale * tol)


class CleanShutdown(TempDirTest):
    """A completed run ends with exit 0 for every process: the participants get the coupler's
    final Shutdown(success = true). Eight short runs, since the loss is intermittent."""

    def test_participants_receive_the_final_shutdown(self):
        c = load_case(case_dir("sheet-in-uniform-flow"))
        c["run"]["end_time_s"] = 0.02
        c["coupling"]["heartbeat_interval_s"] = 0.1
        c["coupling"]["timeout_s"] = 0.5
        case = write_case(os.path.join(self.tmp, "case"), c)
        outcomes = []
        for i in range(8):
            out = os.path.join(self.tmp, "out%d" % i)
            code, _ = self.launch(case, out)
            outcomes.append((code, status_of(os.path.join(out, "coupling.h5")),
                             status_of(os.path.join(out, "structure.h5"))))
        bad = [o for o in outcomes if o != (0, "completed", "completed")]
        self.assertEqual(bad, [], "%d of 8 completed runs ended with a participant that never got "
                         "the final Shutdown (launcher code, coupling status, structure status)" % len(bad))


class EnteringAndLeaving(TempDirTest):
    """Structures that enter and leave a coupled run (issue 33's feed): in the uniform flow of
    cases/sheet-in-uniform-flow, the sheet is removed once all its points are past x = 0.02 m,
    and a second sheet, released at 0.05 s, waits untouched until then and relaxes to the flow
    from its release exactly as the first did from the start: V^k = U (1 - (1 - a)^k), k the
    steps since its release. Nothing acts on a structure out of the scene, in either process."""

    def test_a_late_sheet_relaxes_from_its_release_and_a_passed_one_is_removed(self):
        import copy
        import h5py
        c = load_case(case_dir("sheet-in-uniform-flow"))
        c["run"]["end_time_s"] = 0.2
        c["run"]["output_interval_s"] = 0.0025
        del c["probes"]
        first = c["structures"][0]
        first["remove_when_past"] = {"point_m": [0.02, 0, 0], "normal": [1, 0, 0]}
        late = copy.deepcopy(first)
        del late["remove_when_past"]
        late.update({"name": "late", "origin_m": [0, 0.1, 0], "release_time_s": 0.05})
        c["structures"].append(late)
        case = write_case(os.path.join(self.tmp, "case"), c)
        out = os.path.join(self.tmp, "out")
        code, stderr = self.launch(case, out)
        self.assert_run_completed(out, code, stderr)
        K, dt = float(c["coupling"]["stiffness_n_per_m_per_measure"]), float(c["run"]["time_step_s"])
        a = K * dt * dt / 0.08
        U = np.array(c["fluid"]["prescribed"]["uniform"]["velocity_m_per_s"], dtype=float)
        r = StructureResults(out)
        t, n = r.time_s, np.rint(r.time_s / dt)
        x, v = r.structures["late"]["position_m"], r.structures["late"]["velocity_m_per_s"]
        tol = roundoff_velocity_tolerance(n[-1], np.abs(x).max(), dt)
        before = t < 0.05 - dt / 2
        self.assertTrue(np.all(x[before] == x[0]), "the late sheet moved before its release")
        self.assertTrue(np.all(v[before] == 0.0))
        k = np.maximum(n - 1000, 0)  # released at the start of step 1000 (t = 0.05 s)
        expected = np.outer(1.0 - (1.0 - a) ** k, U)
        error = np.abs(v - expected[:, None, :]).max()
        self.assertLess(error, tol, "late sheet: max |V - U (1 - (1 - a)^k)| = %.3g m/s" % error)
        # The first sheet: removed at the first step with every point past x = 0.02 m (0.146 s,
        # StopWhenPast below), then still.
        xs = r.structures["sheet"]["position_m"]
        with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
            exit_s = float(f["structures/sheet"].attrs["exit_time_s"])
            self.assertEqual(float(f["structures/late"].attrs["release_time_s"]), 0.05)
            self.assertTrue(np.isnan(f["structures/late"].attrs["exit_time_s"]))
        self.assertAlmostEqual(exit_s, 0.146, delta=0.005)
        after = t > exit_s + dt / 2
        self.assertTrue(np.all(xs[after] == xs[after][0]), "the removed sheet moved after its exit")
        self.assertTrue(np.all(xs[after][0][:, 0] > 0.02))
        # The coupler's force on the fluid: the first sheet's until its exit, the late one's from
        # its release; -K dt A (1 - a)^k U each.
        with h5py.File(os.path.join(out, "coupling.h5"), "r") as f:
            force, t_force = f["total_force_on_fluid_n"][:], f["time_s"][:]
        step = np.rint(t_force / dt) - 1
        area = 0.05 * 0.05
        on = lambda k, live: np.where(live, (1.0 - a) ** np.maximum(k, 0), 0.0)
        magnitude = on(step, step * dt < exit_s - dt / 2) + on(step - 1000, step >= 1000)
        expected_force = -K * dt * area * np.outer(magnitude, U)
        self.assertLess(np.abs(force - expected_force).max(), K * dt * area * tol)
        with open(os.path.join(out, "coupler.log")) as f:
            self.assertIn("structure 'late' released at t = 0.05 s", f.read())


class StopWhenPast(TempDirTest):
    """run.stop_when_past: the sheet carried by a uniform flow crosses a plane; the coupled run
    ends, completed, at the first step where every point is past it, and so does the same
    scene in a structure run of its own (the sheet falling under gravity)."""

    def assert_stopped_at_the_crossing(self, out, plane_x, end_time_s, dt):
        r = StructureResults(out)
        x = r.structures["sheet"]["position_m"]
        t = r.time_s
        self.assertLess(t[-1], end_time_s - dt / 2, "the run did not stop early")
        self.assertTrue(np.all(x[-1][:, 0] > plane_x), "the last frame is not past the plane")
        self.assertFalse(np.all(x[-2][:, 0] > plane_x), "an earlier frame was already past the plane")
        self.assertEqual(status_of(os.path.join(out, "structure.h5")), "completed")
        return t[-1]

    def test_coupled_run_ends_when_the_sheet_has_passed(self):
        c = load_case(case_dir("sheet-in-uniform-flow"))
        c["run"]["stop_when_past"] = {"point_m": [0.02, 0, 0], "normal": [1, 0, 0]}
        case = write_case(os.path.join(self.tmp, "case"), c)
        out = os.path.join(self.tmp, "out")
        code, stderr = self.launch(case, out)
        self.assert_run_completed(out, code, stderr)
        dt, end = float(c["run"]["time_step_s"]), float(c["run"]["end_time_s"])
        t_stop = self.assert_stopped_at_the_crossing(out, 0.02, end, dt)
        # The sheet's trailing edge x = 0 moves as U_x (t - tau (1 - exp(-t/tau))) (the penalty
        # relaxation, Relaxation above): it reaches 0.02 m at about 0.146 s.
        K, rho = float(c["coupling"]["stiffness_n_per_m_per_measure"]), 0.08
        tau = rho / (K * dt)
        expected = next(tk for tk in np.arange(0, end, dt) if 0.2 * (tk - tau * (1 - math.exp(-tk / tau))) > 0.02)
        self.assertAlmostEqual(t_stop, expected, delta=0.005)
        with __import__("h5py").File(os.path.join(out, "coupling.h5"), "r") as f:
            self.assertAlmostEqual(f["time_s"][-1], t_stop, delta=dt / 2)

    def test_structure_run_ends_when_the_sheet_has_passed(self):
        c = load_case(case_dir("sheet-in-uniform-flow"))
        del c["fluid"], c["coupling"]
        c["gravity_m_per_s2"] = [9.81, 0, 0]
        c["run"]["stop_when_past"] = {"point_m": [0.02, 0, 0], "normal": [1, 0, 0]}
        case = write_case(os.path.join(self.tmp, "case"), c)
        out = os.path.join(self.tmp, "out")
        code, stderr = self.launch(case, out)
        self.assertEqual(code, 0, stderr[-3000:])
        t_stop = self.assert_stopped_at_the_crossing(out, 0.02, float(c["run"]["end_time_s"]),
                                                     float(c["run"]["time_step_s"]))
        self.assertAlmostEqual(t_stop, math.sqrt(2 * 0.02 / 9.81), delta=0.005)  # free fall by 2 cm


if __name__ == "__main__":
    unittest.main()
