#!/usr/bin/python3
"""Faults in coupled runs, with the real executables over ZeroMQ on loopback: a participant
killed (-9) mid-run, a participant started with another case, Ctrl-C at the launcher.
(Wrong protocol version and garbage bytes need raw sockets: ProtocolFaultsTest.cpp.)

    FSI_BIN_DIR=build/bin /usr/bin/python3 tests/coupled/test_coupled_faults.py [Class]

The case is cases/sheet-in-uniform-flow made long (end_time 5 s: far more steps than the test
waits for) with coupling.heartbeat_interval_s = 0.1 and coupling.timeout_s = 1.0.
"""

import os
import re
import signal
import subprocess
import time
import unittest

from coupled_support import (LAUNCHER, BIN_DIR, PYTHON, TempDirTest, alive, case_dir,
                             children_of, load_case, read, status_of, wait_exit, wait_for_text,
                             write_case)

HEARTBEAT_S, TIMEOUT_S = 0.1, 1.0
# Beyond timeout_s: the coupler checks liveness every <= 100 ms, then writes coupling.h5 and exits.
MARGIN_S = 1.5
PROGRESS = r"step (\d+)/(\d+)"


def long_case(folder, **run_changes):
    c = load_case(case_dir("sheet-in-uniform-flow"))
    c["run"]["end_time_s"] = 5.0
    c["run"]["progress_interval_s"] = 0.2
    c["run"].update(run_changes)
    c["coupling"]["heartbeat_interval_s"] = HEARTBEAT_S
    c["coupling"]["timeout_s"] = TIMEOUT_S
    c["coupling"]["handshake_timeout_s"] = 5.0
    return write_case(folder, c)


class KilledParticipant(TempDirTest):
    def kill_mid_run(self, victim):
        case = long_case(os.path.join(self.tmp, "case"))
        out = os.path.join(self.tmp, "out")
        coupler, endpoint = self.start_coupler(case, out)
        procs = {"structure": self.start_participant("structure", case, out, endpoint),
                 "fluid": self.start_participant("fluid", case, out, endpoint)}
        self.assertIsNotNone(wait_for_text(coupler.log_path, PROGRESS, 20, coupler),
                             "no progress: " + read(coupler.log_path)[-2000:])
        procs[victim].send_signal(signal.SIGKILL)
        killed_at = time.monotonic()
        code = wait_exit(coupler, TIMEOUT_S + MARGIN_S)
        elapsed = time.monotonic() - killed_at
        log = read(coupler.log_path)
        self.assertEqual(code, 1, "coupler after %s was killed (%.2f s): %s" % (victim, elapsed, log[-2000:]))
        name = "%s:main" % victim
        line = [l for l in log.splitlines() if "[error]" in l and name in l]
        self.assertTrue(line, log[-2000:])
        self.assertRegex(line[0], r"step \d+", "the error names no step")
        failed = status_of(os.path.join(out, "coupling.h5"))
        self.assertTrue(failed.startswith("failed"), failed)
        self.assertIn(name, failed)
        other_name = "fluid" if victim == "structure" else "structure"
        other = procs[other_name]
        # Told by Shutdown(success = false), or at worst by its own timeout_s.
        other_code = wait_exit(other, TIMEOUT_S + MARGIN_S)
        self.assertNotIn(other_code, (None, 0), "the %s participant after the %s died" % (other_name, victim))
        return elapsed, out

    def test_structure_killed(self):
        elapsed, out = self.kill_mid_run("structure")
        print("coupler exited %.2f s after kill -9 of the structure" % elapsed)

    def test_fluid_killed(self):
        elapsed, out = self.kill_mid_run("fluid")
        status = status_of(os.path.join(out, "structure.h5"))
        self.assertNotEqual(status, "completed")
        print("coupler exited %.2f s after kill -9 of the fluid; structure.h5 status: %s" % (elapsed, status))


def with_rotating_pole(folder, rate_rad_per_s):
    """long_case with a collision surface the coupler turns (its motion is part of the case)."""
    c = load_case(long_case(folder))
    c["collisions"] = {"threshold_m": 0.004, "target_distance_m": 0.004, "surfaces": [
        {"cylinder": {"axis_start_m": [0.5, 0.5, -0.1], "axis_end_m": [0.5, 0.5, 0.1], "radius_m": 0.01},
         "motion": {"rotation": {"axis_point_m": [0.0, 0.0, 0.0], "axis_direction": [0.0, 0.0, 1.0],
                                 "rate_rad_per_s": rate_rad_per_s}}}]}
    return write_case(folder, c)


class CaseMismatch(TempDirTest):
    def test_structure_with_another_case_is_refused(self):
        case = long_case(os.path.join(self.tmp, "case"))
        other = long_case(os.path.join(self.tmp, "other"), end_time_s=4.0)
        self.assert_structure_refused(case, other)

    def test_structure_whose_case_moves_a_surface_otherwise_is_refused(self):
        """The coupler is the only process that evaluates a prescribed motion, and participants
        take the poses it sends; a participant whose case declares another motion is refused
        at the handshake (the motion is part of the case fingerprint), before any step."""
        case = with_rotating_pole(os.path.join(self.tmp, "case"), 1.0)
        other = with_rotating_pole(os.path.join(self.tmp, "other"), 2.0)
        self.assert_structure_refused(case, other)

    def assert_structure_refused(self, case, other):
        # The other case's fingerprint, as a coupler started on it reports it.
        probe_out = os.path.join(self.tmp, "probe")
        probe, _ = self.start_coupler(other, probe_out)
        match = wait_for_text(probe.log_path, r"case fingerprint ([0-9a-f]{16})", 10, probe)
        probe.send_signal(signal.SIGINT)
        self.assertEqual(wait_exit(probe, 10), 130)
        self.assertIsNotNone(match)
        theirs = match.group(1)

        out = os.path.join(self.tmp, "out")
        coupler, endpoint = self.start_coupler(case, out)
        ours = wait_for_text(coupler.log_path, r"case fingerprint ([0-9a-f]{16})", 10, coupler).group(1)
        self.assertNotEqual(ours, theirs)
        fluid = self.start_participant("fluid", case, out, endpoint)
        self.assertIsNotNone(wait_for_text(coupler.log_path, r"fluid:main joined", 10, coupler))
        structure = self.start_participant("structure", other, out, endpoint)
        code = wait_exit(coupler, 10)
        log = read(coupler.log_path)
        self.assertEqual(code, 2, log[-2000:])
        refusal = [l for l in log.splitlines() if "[error]" in l and "structure:main" in l]
        self.assertTrue(refusal, log[-2000:])
        self.assertIn(ours, refusal[0])
        self.assertIn(theirs, refusal[0])
        self.assertTrue(status_of(os.path.join(out, "coupling.h5")).startswith("refused"))
        # Both participants stop, non-zero: told by the coupler, or by their handshake/timeout.
        self.assertNotIn(wait_exit(structure, 5.0 + MARGIN_S), (None, 0))
        self.assertNotIn(wait_exit(fluid, TIMEOUT_S + MARGIN_S), (None, 0))


class CtrlC(TempDirTest):
    def interrupt(self, whole_group):
        case = long_case(os.path.join(self.tmp, "case"))
        out = os.path.join(self.tmp, "out")
        with open(os.path.join(self.tmp, "launcher.err"), "wb") as err:
            launcher = subprocess.Popen([PYTHON, LAUNCHER, "--bin-dir", BIN_DIR, "-o", out, case],
                                        stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=err, start_new_session=True)
        self.processes.append(launcher)
        console = os.path.join(out, "logs", "coupler.console")
        deadline = time.monotonic() + 20
        while time.monotonic() < deadline and not (
                re.search(PROGRESS, read(console)) and len(children_of(launcher.pid)) == 3):
            time.sleep(0.02)
        children = children_of(launcher.pid)
        self.assertEqual(len(children), 3, read(console)[-2000:])
        if whole_group:  # Ctrl-C in a terminal: the whole foreground process group
            os.killpg(launcher.pid, signal.SIGINT)
        else:
            launcher.send_signal(signal.SIGINT)
        code = wait_exit(launcher, 10)
        self.assertEqual(code, 130, read(os.path.join(self.tmp, "launcher.err"))[-2000:])
        self.assertEqual([p for p in children if alive(p)], [], "processes left running")
        self.assertEqual(status_of(os.path.join(out, "coupling.h5")), "interrupted")
        # The coupler ended the run at a step boundary (Shutdown.interrupted): no process failed.
        status = status_of(os.path.join(out, "structure.h5"))
        self.assertEqual(status, "interrupted")
        self.assertRegex(read(os.path.join(out, "coupler.log")),
                         r"interrupted by signal 2 at (the coupler|participant \S+) after step \d+ .*no checkpoint")
        return status

    def test_ctrl_c_to_the_process_group(self):
        print("structure.h5 status after Ctrl-C (group): %s" % self.interrupt(True))

    def test_sigint_to_the_launcher_only(self):
        print("structure.h5 status after SIGINT to the launcher: %s" % self.interrupt(False))


if __name__ == "__main__":
    unittest.main()
