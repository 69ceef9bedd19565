#!/usr/bin/python3
"""Numerical stability suite (issue 5): hard cases run long enough to show instability, each
asserting finite state, bounded energy and stretch, and no point inside a rigid body; cases
beyond a threshold must stop cleanly (exit 1, status 'diverged: step N ... point ...', last
saved state finite). Each class bisects its thresholds (largest stable time step, phi, K_fsi)
with short runs and stores them as rows for OUT/stability.md (python/fsi/stability.py).

Run one class: FSI_BIN_DIR=build/bin python3 test_stability.py -v StiffSheet
(label 'stability': `./fsi test --stability`; not part of the default `./fsi test`).
"""

import math
import sys
import unittest

try:
    import numpy as np
    from fsi import stability as S
except ImportError as e:  # python3-numpy, python3-h5py or python3-yaml missing
    print("skipped: %s" % e)
    sys.exit(77)

DS = 0.004   # the paper's Lagrangian spacing (m)
DT = 5e-5    # the paper's time step (s)
PINNED_S1 = {"s1_min": "pinned", "s1_max": "pinned", "s2_min": "free", "s2_max": "free"}
RAG = dict(rho=0.03, phi=10.0, zeta=1e-6, damping=0.5)          # section 4.2's rag
SOFT_RAG = dict(rho=0.03, phi=10.0, zeta=1e-8, damping=0.0)     # nearly bending-free


def wave_dt(phi, rho, ds=DS):
    """Largest stable step predicted by the stretching-wave speed sqrt(2 phi / rho_1)."""
    return ds / math.sqrt(2.0 * phi / rho)


def penalty_dt(k, rho):
    """Largest stable step of the penalty law: K dt^2 / rho_1 < 2."""
    return math.sqrt(2.0 * rho / k)


def collisions(surfaces, self_collision=False):
    return {"threshold_m": 0.004, "target_distance_m": 0.004, "self_collision": self_collision,
            "surfaces": surfaces}


def dt_row(case, fixed, stable, unstable, predicted, note=""):
    return {"case": case, "quantity": "time step (s)", "fixed": fixed, "stable": stable, "unstable": unstable,
            "predicted": predicted, "ds_over_dt": DS / stable if stable else None, "note": note}


class StabilityCase(unittest.TestCase):
    rows = []

    @classmethod
    def setUpClass(cls):
        cls.rows = []

    @classmethod
    def tearDownClass(cls):
        S.write_row(cls.__name__, sorted(cls.rows, key=lambda r: r.pop("_order", 0)))

    def assertHealthy(self, result, **limits):
        self.assertEqual(S.problems(result, **limits), [], repr(result))

    def assertCleanStop(self, result):
        self.assertEqual(S.clean_stop_problems(result), [], repr(result))

    def bisect_dt(self, name, make, lo, hi, predicted, fixed, note="", order=0, min_steps=3000, min_time_s=0.0,
                  iterations=6, **limits):
        stable, unstable, _ = S.largest_stable(
            lambda dt: S.with_time_step(make(), dt, min_steps=min_steps, min_time_s=min_time_s),
            lo, hi, S.stable_by(**limits), iterations=iterations, name=name)
        row = dt_row(name, fixed, stable, unstable, predicted, note)
        row["_order"] = order
        self.rows.append(row)
        print("%s: largest stable dt %s, first unstable %s, predicted %s" % (name, stable, unstable, predicted))
        return stable, unstable


# ------------------------------------------------------------------------------------------------
class StiffSheet(StabilityCase):
    """The sagging sheet (pinned on two edges, rho_1 = 0.08, lambda = 2) from phi = 10 to 1000 N/m."""

    @staticmethod
    def sheet(phi, dt=DT, end=1.0):
        return S.case([S.membrane(phi=phi, rho=0.08, damping=2.0, zeta=1e-4, edges=PINNED_S1)], end, dt)

    def test_1_stable_up_to_250(self):
        for phi in (10.0, 30.0, 100.0, 250.0):
            r = S.run_case(self.sheet(phi), "stiff-phi%g" % phi)
            # damped and started at rest: the total energy may only fall
            self.assertHealthy(r, max_stretch=1.1, energy_max_j=1e-7)

    def test_2_phi_1000_stops_cleanly(self):
        r = S.run_case(self.sheet(1000.0), "stiff-phi1000")
        self.assertCleanStop(r)
        self.assertLess(S.diverged_step(r), 1000)

    def test_3_phi_threshold(self):
        stable, unstable, _ = S.largest_stable(
            lambda phi: S.with_time_step(self.sheet(phi), DT, min_steps=6000, min_time_s=0.0),
            10.0, 1000.0, S.stable_by(max_stretch=1.3), iterations=7, name="stiff-phi")
        predicted = 0.08 / 2.0 * (DS / DT) ** 2   # 256 N/m
        self.rows.append({"case": "stiff sheet", "quantity": "phi (N/m)", "fixed": "dt = 5e-05 s", "stable": stable,
                          "unstable": unstable, "predicted": predicted, "ds_over_dt": DS / DT,
                          "note": "rho_1 = 0.08, lambda = 2, zeta = 1e-4", "_order": 0})
        self.assertIsNotNone(stable)
        self.assertGreater(stable, 0.8 * predicted)
        self.assertLess(unstable, 1.25 * predicted)

    def test_4_largest_time_step(self):
        for i, phi in enumerate((10.0, 100.0, 1000.0)):
            predicted = wave_dt(phi, 0.08)
            stable, unstable = self.bisect_dt("stiff sheet phi=%g" % phi, lambda: self.sheet(phi), 2e-6, 2e-3,
                                              predicted, "phi = %g N/m" % phi, order=1 + i, min_steps=6000,
                                              max_stretch=1.3)
            self.assertIsNotNone(stable)
            self.assertGreater(stable, 0.75 * predicted)   # measured: 1.0-1.5 x the wave prediction
            self.assertLess(unstable, 2.0 * predicted)
        # phi = 1000 runs at 90 % of its measured limit
        r = S.run_case(self.sheet(1000.0, dt=0.9 * stable), "stiff-phi1000-small-dt")
        self.assertHealthy(r, max_stretch=1.1, energy_max_j=1e-7)


# ------------------------------------------------------------------------------------------------
class RagInMixing(StabilityCase):
    """A nearly bending-free rag (zeta = 1e-8 N m) in a strong shear (200 1/s) and a fast solid-body
    rotation (200 rad/s about a tilted axis), penalty law K = 1e5."""

    K = 1e5

    def shear(self, dt=DT, end=0.5, tension="frozen"):
        flow = {"shear": {"reference_point_m": [0, 0, 0], "reference_velocity_m_per_s": [0, 0, 0],
                          "flow_direction": [1, 0, 0], "gradient_direction": [0, 0, 1], "shear_rate_1_per_s": 200.0}}
        sheet = S.membrane(origin=(-0.035, -0.05, -0.035), s1=(1, 0, 1), tension=tension, **SOFT_RAG)  # tilted 45 deg
        return S.case([sheet], end, dt, gravity=(0, 0, 0), flow=flow, stiffness=self.K)

    def rotation(self, dt=DT, end=0.5):
        flow = {"rotation": {"axis_point_m": [0, 0, 0], "axis_direction": [0, 0.3, 1], "rate_rad_per_s": 200.0}}
        sheet = S.membrane(origin=(-0.05, 0, -0.05), s1=(1, 0, 0), s2=(0, 0, 1), **SOFT_RAG)
        return S.case([sheet], end, dt, gravity=(0, 0, 0), flow=flow, stiffness=self.K)

    def test_1_shear(self):
        r = S.run_case(self.shear(), "mixing-shear")
        u_max = 200.0 * 0.075                      # fastest flow the sheet reaches (z up to ~0.075 m)
        self.assertHealthy(r, max_stretch=1.3, energy_max_j=0.5 * 0.03 * 0.01 * u_max ** 2)

    def test_2_rotation(self):
        r = S.run_case(self.rotation(), "mixing-rotation")
        u_max = 200.0 * 0.075
        self.assertHealthy(r, max_stretch=1.3, energy_max_j=0.5 * 0.03 * 0.01 * u_max ** 2)
        self.assertGreater(float(r.structures["sheet"]["kinetic_energy_j"].max()), 1e-3)  # it does spin up

    def test_3_largest_time_step(self):
        predicted = min(wave_dt(10.0, 0.03), penalty_dt(self.K, 0.03))
        u_max = 200.0 * 0.075
        stable, unstable = self.bisect_dt("rag in shear (zeta=1e-8)", lambda: self.shear(end=0.1), DT, 2e-3,
                                          predicted, "K = 1e5, shear 200 1/s", order=10, min_time_s=0.1,
                                          max_stretch=1.3, energy_max_j=0.5 * 0.03 * 0.01 * u_max ** 2)
        self.assertIsNotNone(stable)
        self.assertIsNotNone(unstable)


# ------------------------------------------------------------------------------------------------
class StabilizedTension(StabilityCase):
    """solver.tension: stabilized (an upper bound of the stretching stiffness taken implicitly) and
    linearized (the change of the tension linearised about X^n, implicit with its direction) on
    the two cases that the stretching wave limits with the paper's frozen tension: the stiff sheet
    (phi = 1000 N/m: frozen limit 2.4e-5 s) and the soft rag in shear (frozen limit 1.4e-4 s; then
    the penalty law's K dt^2 / rho_1 < 2, dt < 7.7e-4 s, is the next limit)."""

    def stiff_sheet(self, tension, order):
        def sheet():
            return S.case([S.membrane(phi=1000.0, rho=0.08, damping=2.0, zeta=1e-4, edges=PINNED_S1,
                                      tension=tension)], 1.0, DT)
        stable, unstable = self.bisect_dt("stiff sheet phi=1000, tension %s" % tension, sheet, 2e-5, 2e-2, None,
                                          "phi = 1000 N/m", note="frozen tension: 2.39e-5 s (StiffSheet)",
                                          order=order, min_steps=3000, max_stretch=1.3)
        self.assertIsNotNone(stable)
        self.assertGreater(stable, 20 * wave_dt(1000.0, 0.08))

    def rag_in_shear(self, tension, order):
        u_max = 200.0 * 0.075
        predicted = penalty_dt(RagInMixing.K, 0.03)
        stable, unstable = self.bisect_dt("rag in shear (zeta=1e-8), tension %s" % tension,
                                          lambda: RagInMixing().shear(end=0.1, tension=tension), DT, 5e-3,
                                          predicted, "K = 1e5, shear 200 1/s", order=order, min_time_s=0.1,
                                          note="frozen tension: 1.41e-4 s; now the penalty law limits",
                                          max_stretch=1.3, energy_max_j=0.5 * 0.03 * 0.01 * u_max ** 2)
        self.assertIsNotNone(stable)
        self.assertGreater(stable, 3 * wave_dt(10.0, 0.03))
        self.assertLess(stable, 1.2 * predicted)

    def test_1_stiff_sheet_largest_time_step(self):
        self.stiff_sheet("stabilized", 4)

    def test_2_rag_in_shear_largest_time_step(self):
        self.rag_in_shear("stabilized", 11)

    def test_3_linearized_stiff_sheet_largest_time_step(self):
        self.stiff_sheet("linearized", 5)

    def test_4_linearized_rag_in_shear_largest_time_step(self):
        self.rag_in_shear("linearized", 12)


# ------------------------------------------------------------------------------------------------
class PenaltyLaw(StabilityCase):
    """The sheet-in-uniform-flow case (11 x 11, Delta s = 5 mm, rho_1 = 0.08, phi = 10) with K_fsi from
    1e4 to 1e6 and beyond the limit K dt^2 / rho_1 < 2 (K = 6.4e7 at dt = 5e-5)."""

    U = np.array([0.2, 0.0, 0.1])

    def sheet(self, k, dt=DT, end=0.25):
        flow = {"uniform": {"velocity_m_per_s": self.U.tolist()}}
        sheet = S.membrane(size=(0.05, 0.05), n=(11, 11), rho=0.08, phi=10.0, zeta=1e-6)
        return S.case([sheet], end, dt, gravity=(0, 0, 0), flow=flow, stiffness=k)

    def energy_max(self):
        return 0.5 * 0.08 * 0.05 ** 2 * float(self.U @ self.U) * 1.01   # the sheet cannot outrun the flow

    def test_1_large_k_stable(self):
        for k in (1e4, 1e5, 1e6):
            r = S.run_case(self.sheet(k), "penalty-K%g" % k)
            self.assertHealthy(r, max_stretch=1.01, energy_max_j=self.energy_max())
            if k >= 1e5:   # tau = rho_1 / (K dt) <= 16 ms: relaxed to the flow after 0.25 s
                v = r.structures["sheet"]["velocity_m_per_s"][-1]
                self.assertLess(float(np.abs(v - self.U).max()), 1e-6)

    def test_2_beyond_limit_stops_cleanly(self):
        r = S.run_case(self.sheet(1e8), "penalty-K1e8")
        self.assertCleanStop(r)
        s = r.structures["sheet"]
        ke = float(s["kinetic_energy_j"][-1])
        # The runaway is a rigid mode that hardly stretches the sheet: the speed guard
        # (solver.max_speed_m_per_s) must catch it within a few growth periods (a = 3.1).
        self.assertLessEqual(S.diverged_step(r), 20)
        self.rows.append({"case": "penalty law", "quantity": "K_fsi = 1e8 (a = 3.1)", "fixed": "dt = 5e-05 s",
                          "stable": None, "unstable": 1e8, "predicted": None, "ds_over_dt": None,
                          "note": "stops at step %d; last saved state finite but KE = %.3g J, max abs X = %.3g m "
                                  "(a rigid mode that hardly stretches the sheet: the speed guard stops it)"
                                  % (S.diverged_step(r), ke, float(np.abs(s["position_m"][-1]).max())),
                          "_order": 2})

    def test_3_k_threshold(self):
        predicted = 2.0 * 0.08 / DT ** 2      # 6.4e7 N/m^3
        stable, unstable, _ = S.largest_stable(
            lambda k: S.with_time_step(self.sheet(k), DT, min_steps=3000, min_time_s=0.0),
            1e6, 1e9, S.stable_by(max_stretch=1.3, energy_max_j=self.energy_max()), iterations=7,
            name="penalty-K")
        self.rows.append({"case": "penalty law", "quantity": "K_fsi (N/m^3)", "fixed": "dt = 5e-05 s",
                          "stable": stable, "unstable": unstable, "predicted": predicted, "ds_over_dt": 0.005 / DT,
                          "note": "uniform flow, rho_1 = 0.08", "_order": 0})
        self.assertIsNotNone(stable)
        self.assertGreater(stable, 0.8 * predicted)
        self.assertLess(unstable, 1.25 * predicted)

    def test_4_largest_time_step(self):
        for i, k in enumerate((1e6, 1e7)):
            predicted = min(penalty_dt(k, 0.08), wave_dt(10.0, 0.08, ds=0.005))
            stable, unstable = self.bisect_dt("penalty K=%g" % k, lambda: self.sheet(k), DT / 2, 2e-3, predicted,
                                              "K = %g, Delta s = 5 mm" % k, order=5 + i, min_steps=3000,
                                              max_stretch=1.3, energy_max_j=self.energy_max())
            self.rows[-1]["ds_over_dt"] = 0.005 / stable if stable else None
            self.assertIsNotNone(stable)
            self.assertGreater(stable, 0.6 * predicted)    # penalty damping and tension add up
            self.assertLess(unstable, 1.5 * predicted)


# ------------------------------------------------------------------------------------------------
class CouplingLaws(StabilityCase):
    """The coupling laws' explicit limits on the pump's light rag (rho_1 = 0.03 kg/m^2, phi = 10,
    a free 11 x 11 sheet, Delta s = 5 mm) in a uniform flow, by bisection in K (penalty,
    two_point_sets) and in beta (feedback, alpha = 0), against the law-alone predictions of
    docs/coupling.md (a = K dt^2 / rho_1 < 2, < 4/3; B = beta dt / rho_1 < 2); and the implicit
    penalty law stable far beyond (coupling.scheme: implicit)."""

    U = np.array([0.2, 0.0, 0.1])
    RHO = 0.03

    def sheet(self, coupling, dt=DT, end=0.15):
        flow = {"uniform": {"velocity_m_per_s": self.U.tolist()}}
        sheet = S.membrane(size=(0.05, 0.05), n=(11, 11), rho=self.RHO, phi=10.0, zeta=1e-6)
        return S.case([sheet], end, dt, gravity=(0, 0, 0), flow=flow, coupling=coupling)

    def energy_max(self):
        return 0.5 * self.RHO * 0.05 ** 2 * float(self.U @ self.U) * 1.01   # the sheet cannot outrun the flow

    def threshold(self, law, key, predicted, extra=None, energy_factor=1.0):
        def make(value):
            coupling = {"law": law, key: float(value)}
            coupling.update(extra or {})
            return S.with_time_step(self.sheet(coupling), DT, min_steps=3000, min_time_s=0.0)
        stable, unstable, _ = S.largest_stable(make, predicted / 10.0, predicted * 10.0,
                                               S.stable_by(max_stretch=1.3,
                                                           energy_max_j=energy_factor * self.energy_max()),
                                               iterations=7, name="%s-%s" % (law, key))
        return stable, unstable

    def test_1_explicit_limits(self):
        # The sheet's fastest mode, omega dt = 2 c dt / Delta s (c = sqrt(2 phi / rho_1)), takes its
        # part of the margin of an explicit law: (omega dt)^2 + 2a < 4 for the drag (docs/coupling.md).
        mode = (2.0 * math.sqrt(2.0 * 10.0 / self.RHO) * DT / 0.005) ** 2
        rows = [("penalty", "stiffness_n_per_m_per_measure", (2.0 - mode / 2.0) * self.RHO / DT ** 2, "K_fsi (N/m^3)",
                 None, 1.0),
                # A spring: the sheet overshoots the flow and swings about its IB points (kinetic
                # energy up to that of 2 U), so the energy bound is four times the drag's.
                # With the mode: X^{n+1} = (2 - 2a - (omega dt)^2) X^n - (1 - a) X^{n-1}, so
                # 3a + (omega dt)^2 < 4.
                ("two_point_sets", "stiffness_n_per_m_per_measure", (4.0 - mode) / 3.0 * self.RHO / DT ** 2,
                 "K_fsi (N/m^3)", None, 4.1),
                ("feedback", "beta_n_s_per_m_per_measure", (2.0 - mode / 2.0) * self.RHO / DT,
                 "beta (N s/m^3), alpha = 0", {"alpha_n_per_m_per_measure": 0.0}, 1.0)]
        for i, (law, key, predicted, quantity, extra, energy_factor) in enumerate(rows):
            stable, unstable = self.threshold(law, key, predicted, extra, energy_factor)
            self.rows.append({"case": "coupling law %s, explicit" % law, "quantity": quantity, "fixed": "dt = 5e-05 s",
                              "stable": stable, "unstable": unstable, "predicted": predicted, "ds_over_dt": 0.005 / DT,
                              "note": "free sheet, uniform flow, rho_1 = 0.03; predicted with the sheet's fastest "
                                      "mode (omega dt)^2 = %.2f where it applies" % mode, "_order": i})
            self.assertIsNotNone(stable, law)
            self.assertGreater(stable, 0.8 * predicted, law)
            self.assertLess(unstable, 1.25 * predicted, law)

    def test_2_implicit_penalty_far_beyond_the_explicit_limit(self):
        limit = 2.0 * self.RHO / DT ** 2
        for factor in (10.0, 100.0):
            coupling = {"law": "penalty", "stiffness_n_per_m_per_measure": factor * limit, "scheme": "implicit",
                        "implicit": {"acceleration": "iqn_ils", "relaxation": 0.1, "tolerance": 1e-6,
                                     "max_iterations": 40}}
            r = S.run_case(S.with_time_step(self.sheet(coupling), DT, min_steps=1000, min_time_s=0.0),
                           "implicit-penalty-%gx" % factor)
            self.assertHealthy(r, max_stretch=1.01, energy_max_j=self.energy_max())
            v = r.structures["sheet"]["velocity_m_per_s"][-1]
            self.assertLess(float(np.abs(v - self.U).max()), 1e-6)   # tau = rho_1 / (K dt) < 1 step: with the flow
            self.rows.append({"case": "coupling law penalty, implicit (IQN-ILS)", "quantity": "K_fsi (N/m^3)",
                              "fixed": "dt = 5e-05 s", "stable": factor * limit, "unstable": None,
                              "predicted": None, "ds_over_dt": 0.005 / DT,
                              "note": "%gx the explicit limit: stable, the sheet moves with the flow" % factor,
                              "_order": 3 + int(factor > 10)})


class WallAndRotor(StabilityCase):
    """A rag thrown at 10 m/s into the corner of a box (floor plane + box walls), and a rag falling
    onto a paddle (solid cylinder, radius 0.1 m) rotating at 150 rad/s: 15 m/s tip speed."""

    RATE = 150.0

    def wall(self, dt=DT, end=0.2):
        surfaces = [{"plane": {"point_m": [0, 0, -0.05], "normal": [0, 0, 1]}},
                    {"box": {"min_m": [-0.2, -0.2, -0.05], "max_m": [0.2, 0.2, 0.2]}}]
        sheet = S.membrane(origin=(-0.05, -0.05, 0.0), s1=(1, 0, 0.3), velocity=(4, 2, -10), **RAG)
        return S.case([sheet], end, dt, output_interval_s=1e-3, collisions=collisions(surfaces))

    def rotor(self, dt=DT, end=0.3):
        paddle = {"cylinder": {"axis_start_m": [-0.1, 0, 0], "axis_end_m": [0.1, 0, 0], "radius_m": 0.01},
                  "motion": {"rotation": {"axis_point_m": [0, 0, 0], "axis_direction": [0, 0, 1],
                                          "rate_rad_per_s": self.RATE}}}
        surfaces = [paddle, {"box": {"min_m": [-0.2, -0.2, -0.2], "max_m": [0.2, 0.2, 0.2]}}]
        sheet = S.membrane(origin=(-0.05, -0.05, 0.03), **RAG)
        return S.case([sheet], end, dt, output_interval_s=5e-4, collisions=collisions(surfaces))

    def test_1_wall(self):
        r = S.run_case(self.wall(), "wall")
        self.assertHealthy(r, max_stretch=1.3, energy_max_j=1e-6, wall_min_m=0.0)
        z = r.structures["sheet"]["position_m"][:, :, 2]
        self.assertLess(float(z.min()), -0.05 + 0.0045)   # it did reach the floor

    def test_2_rotor(self):
        self.assertAlmostEqual(self.RATE * 0.1, 15.0)
        r = S.run_case(self.rotor(), "rotor")
        self.assertHealthy(r, max_stretch=1.3, energy_max_j=0.5 * 0.03 * 0.01 * (2 * 15.0) ** 2, wall_min_m=0.0)
        v = np.linalg.norm(r.structures["sheet"]["velocity_m_per_s"], axis=2)
        self.assertGreater(float(v.max()), 2.0)     # the paddle did strike the rag

    def test_3_largest_time_step(self):
        predicted = wave_dt(10.0, 0.03)
        stable, _ = self.bisect_dt("rag hitting a wall", self.wall, DT, 2e-3, predicted, "10 m/s impact",
                                   order=20, min_time_s=0.2, max_stretch=1.3, energy_max_j=1e-6, wall_min_m=0.0)
        self.assertIsNotNone(stable)
        stable, _ = self.bisect_dt("rag on 15 m/s rotor", self.rotor, DT / 2, 2e-3, predicted,
                                   "paddle 150 rad/s", order=21, min_time_s=0.3, max_stretch=1.3,
                                   energy_max_j=0.5 * 0.03 * 0.01 * 30.0 ** 2, wall_min_m=0.0)
        self.assertIsNotNone(stable)


# ------------------------------------------------------------------------------------------------
class SelfFold(StabilityCase):
    """A 0.3 m x 0.05 m ribbon (Delta s = 4 mm), bowed, dropped at 2 m/s onto the floor: it buckles
    and folds onto itself. Self-collision on: no two points more than two grid steps apart come
    closer than d_t / 2 (no self-penetration). Off: reported (points pass through each other)."""

    GRID = (76, 13)

    def ribbon(self, self_collision, dt=DT, end=0.4):
        sheet = S.membrane(size=(0.3, 0.05), n=self.GRID, origin=(0, -0.025, 0.31), s1=(0, 0, -1), s2=(0, 1, 0),
                           curvature=3.0, velocity=(0, 0, -2), **RAG)
        floor = {"plane": {"point_m": [0, 0, 0], "normal": [0, 0, 1]}}
        return S.case([sheet], end, dt, output_interval_s=2e-3, collisions=collisions([floor], self_collision))

    def test_1_self_collision_on(self):
        r = S.run_case(self.ribbon(True), "fold-self-on")
        self.assertHealthy(r, max_stretch=1.3, energy_max_j=1e-6, wall_min_m=0.0)
        d = S.min_self_distance(r, "sheet", self.GRID)
        self.rows.append({"case": "folding ribbon, self-collision on", "quantity": "min distance of non-neighbours (m)",
                          "fixed": "dt = 5e-05 s", "stable": d, "unstable": None, "predicted": 0.004,
                          "ds_over_dt": DS / DT, "note": "no self-penetration", "_order": 30})
        self.assertGreater(d, 0.002)

    def test_2_self_collision_off(self):
        r = S.run_case(self.ribbon(False), "fold-self-off")
        self.assertHealthy(r, max_stretch=1.3, energy_max_j=1e-6, wall_min_m=0.0)   # stable, but ...
        d = S.min_self_distance(r, "sheet", self.GRID)
        self.rows.append({"case": "folding ribbon, self-collision off", "quantity": "min distance of non-neighbours (m)",
                          "fixed": "dt = 5e-05 s", "stable": d, "unstable": None, "predicted": None,
                          "ds_over_dt": DS / DT, "note": "stable, but the folds pass through each other",
                          "_order": 31})
        self.assertLess(d, 0.002)   # ... without self-collision the folds pass through each other

    def test_3_largest_time_step(self):
        stable, _ = self.bisect_dt("folding ribbon (self-collision on)", lambda: self.ribbon(True), DT, 2e-3,
                                   wave_dt(10.0, 0.03), "2 m/s drop", order=32, min_time_s=0.4, iterations=5,
                                   max_stretch=1.3, energy_max_j=1e-6, wall_min_m=0.0)
        self.assertIsNotNone(stable)


# ------------------------------------------------------------------------------------------------
class Report(unittest.TestCase):
    """Collects the rows of the other classes into OUT/stability.md and prints it (run last)."""

    def test_report(self):
        text = S.report()
        print(text)
        self.assertIn("| stiff sheet |", text)


if __name__ == "__main__":
    unittest.main()
