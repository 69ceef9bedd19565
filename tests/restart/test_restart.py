#!/usr/bin/python3
"""Checkpoint and restart, with the real executables and the launcher behind ./fsi run: a
structure's run of its own (the rag dropped on the pole: collisions with a cylinder and a box,
self-collision on) and a coupled run (coupler, structure, prescribed flow: the rag in the
swirling flow) over ZeroMQ. A run stopped at step k and resumed with --restart must equal the
uninterrupted run bit for bit: every dataset of structure.h5, probes.csv and the XDMF index.
The negative controls show that the comparison can fail and that damaged checkpoints are
caught: a checkpoint without X^{n-1} is refused, one rounded to 6 digits resumes but differs,
a truncated, bit-flipped or other-case newest set is skipped (with a message naming the file)
and the previous one used. The flow alone (OpenFOAM with a penalized rigid body, no structure,
no coupler) checkpoints and resumes the same way, its tables (forces.csv ...) continued.

FSI_BIN_DIR: the executables (set by ctest; default <source>/build/bin)."""

import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
BIN_DIR = os.environ.get("FSI_BIN_DIR", os.path.join(ROOT, "build", "bin"))
STRUCTURE = os.path.join(BIN_DIR, "fsi-structure")
COUPLER = os.path.join(BIN_DIR, "fsi-coupler")
LAUNCH = os.path.join(ROOT, "python", "fsi", "fsi_launch.py")

try:
    import h5py
    import numpy
    import yaml
    from fsi import state_archive
    from results_diff import differences
except ImportError as missing:  # Debian's python3-h5py, python3-numpy
    print("skipped: %s" % missing)
    sys.exit(77)

END_S, CHECKPOINT_S, DT = 0.2, 0.025, 5.0e-5
EVERY = round(CHECKPOINT_S / DT)


def make_case(folder):
    """sheet-on-pole, 0.2 s, a checkpoint every 0.025 s (500 steps), output every 0.01 s."""
    case = os.path.join(folder, "case")
    shutil.copytree(os.path.join(ROOT, "cases", "sheet-on-pole"), case,
                    ignore=shutil.ignore_patterns("output", "*.png", "*.gif"))
    path = os.path.join(case, "case.yaml")
    with open(path) as f:
        text = f.read()
    text = re.sub(r"end_time_s: [0-9.e-]+", "end_time_s: %g" % END_S, text, count=1)
    text = text.replace("output_interval_s: 0.01", "output_interval_s: 0.01\n  checkpoint_interval_s: %g" % CHECKPOINT_S)
    with open(path, "w") as f:
        f.write(text)
    return case


def run(case, out, *extra, check=True):
    made = subprocess.run([STRUCTURE, case, "-o", out] + list(extra), stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if check and made.returncode != 0:
        raise AssertionError("fsi-structure %s failed (%d):\n%s" % (" ".join(extra), made.returncode, made.stdout[-3000:]))
    return made


def newest_set(out):
    root = os.path.join(out, "checkpoints")
    return os.path.join(root, sorted(os.listdir(root))[-1])


def rewrite_part(set_folder, change):
    """Applies change(entries) to the set's structure.ckpt and updates the manifest's checksum,
    so that the set passes its checks and only the change is the fault."""
    part = os.path.join(set_folder, "structure.ckpt")
    entries = state_archive.read(part)
    change(entries)
    state_archive.write(part, entries)
    manifest_path = os.path.join(set_folder, "manifest.ckpt")
    manifest = state_archive.read(manifest_path)
    with open(part, "rb") as f:
        manifest["parts/0/checksum"] = "%016x" % int.from_bytes(f.read()[-8:], "little")
    state_archive.write(manifest_path, manifest)


class Fixture(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not os.access(STRUCTURE, os.X_OK):
            raise unittest.SkipTest("%s not built" % STRUCTURE)
        cls.tmp = tempfile.mkdtemp(prefix="fsi_restart_")
        cls.case = make_case(cls.tmp)
        cls.full = os.path.join(cls.tmp, "full")
        started = time.time()
        run(cls.case, cls.full)
        cls.full_wall_s = time.time() - started

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def stopped_copy(self, name, stop_s=0.1):
        """A run stopped at stop_s by a shorter end time (its last checkpoint is there)."""
        out = os.path.join(self.tmp, name)
        run(self.case, out, "--end-time", repr(stop_s))
        return out


class StructureAlone(Fixture):
    def test_a_run_stopped_by_its_end_time_and_restarted_equals_the_uninterrupted_run(self):
        out = self.stopped_copy("end_time", 0.0875)  # 1750 steps: a checkpoint, not an output step
        self.assertNotEqual(differences(self.full, out), [])  # the control: short, so not equal yet
        made = subprocess.run([sys.executable, LAUNCH, "--bin-dir", BIN_DIR, "-o", out, "--restart", self.case],
                              stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("resumed from the checkpoint of step 1750", made.stdout)
        self.assertEqual(differences(self.full, out), [])
        with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
            self.assertEqual(f.attrs["status"], "completed")

    def test_a_run_stopped_by_sigterm_resumes_from_the_step_it_stopped_at(self):
        out = os.path.join(self.tmp, "sigterm")
        child = subprocess.Popen([STRUCTURE, self.case, "-o", out], stdin=subprocess.DEVNULL,
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        # SIGTERM once the first periodic checkpoint is on disk (step 500 of 4000), not after a
        # fraction of the uninterrupted run's wall time: that run, slowed by a neighbouring test,
        # once took 2.5 times longer than this one, which had finished before the signal.
        wait_for_set(child, out, EVERY)
        self.assertIsNone(child.poll(), "the run ended before its first checkpoint")
        child.send_signal(signal.SIGTERM)
        text = child.communicate(timeout=60)[0]
        self.assertEqual(child.returncode, 130, text[-2000:])
        stopped = re.search(r"checkpoint of step (\d+) written", text)
        self.assertTrue(stopped, text[-2000:])
        made = run(self.case, out, "--restart")
        self.assertIn("resumed from the checkpoint of step %s " % stopped.group(1), made.stdout)
        self.assertEqual(differences(self.full, out), [])

    def test_a_run_killed_at_a_seeded_random_moment_resumes_from_its_last_checkpoint(self):
        draw = random.Random(20261203)
        resumed = 0
        for attempt in range(2):
            out = os.path.join(self.tmp, "kill9-%d" % attempt)
            child = subprocess.Popen([STRUCTURE, self.case, "-o", out], stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(draw.uniform(0.3, 0.8) * self.full_wall_s)
            child.kill()
            child.wait()
            if not os.path.isdir(os.path.join(out, "checkpoints")):
                run(self.case, out)  # killed before the first checkpoint: nothing to resume
                continue
            made = run(self.case, out, "--restart")
            self.assertIn("resumed from the checkpoint of step", made.stdout)
            self.assertEqual(differences(self.full, out), [])
            resumed += 1
        self.assertGreaterEqual(resumed, 1, "the kills fell before the first checkpoint: the test did not test")


class DamagedCheckpoints(Fixture):
    def test_a_checkpoint_without_the_previous_positions_is_refused(self):
        out = self.stopped_copy("no_previous")
        rewrite_part(newest_set(out), lambda e: e.pop("structures/rag/x_previous_m"))
        made = run(self.case, out, "--restart", check=False)
        self.assertEqual(made.returncode, 2, made.stdout[-2000:])
        self.assertIn("has no entry 'structures/rag/x_previous_m'", made.stdout)

    def test_a_checkpoint_rounded_to_six_digits_resumes_but_does_not_equal_the_run(self):
        out = self.stopped_copy("six_digits")

        def round6(entries):
            for name in ("structures/rag/x_m", "structures/rag/x_previous_m", "structures/rag/velocity_m_per_s"):
                entries[name] = numpy.array([float("%.6g" % v) for v in entries[name].ravel()]).reshape(-1, 3)
        rewrite_part(newest_set(out), round6)
        run(self.case, out, "--restart")
        self.assertNotEqual(differences(self.full, out), [])

    def test_a_bad_newest_set_is_skipped_by_name_and_the_previous_one_used(self):
        for fault in ("truncated", "flipped", "other_case"):
            out = self.stopped_copy(fault)  # checkpoints of steps 1500 and 2000 (keep 2)
            newest = newest_set(out)
            part, manifest = os.path.join(newest, "structure.ckpt"), os.path.join(newest, "manifest.ckpt")
            if fault == "truncated":
                os.truncate(part, os.path.getsize(part) - 100)
            elif fault == "flipped":
                with open(part, "r+b") as f:
                    f.seek(os.path.getsize(part) // 2)
                    byte = f.read(1)
                    f.seek(-1, 1)
                    f.write(bytes([byte[0] ^ 0x04]))
            else:
                entries = state_archive.read(manifest)
                entries["fingerprint"] = "0123456789abcdef"
                state_archive.write(manifest, entries)
            made = run(self.case, out, "--restart")
            expected = {"truncated": part + ": truncated", "flipped": part + ": checksum mismatch",
                        "other_case": "written by another case (fingerprint 0123456789abcdef"}[fault]
            self.assertIn(expected, made.stdout, fault)
            self.assertIn("resumed from the checkpoint of step 1500 ", made.stdout, fault)
            self.assertEqual(differences(self.full, out), [], fault)

    def test_a_kill_between_write_and_rename_leaves_the_old_or_the_new_set_never_a_partial_one(self):
        # R7: the fault hook kills the process after the file is written under its temporary
        # name and before the rename, at the third set: of the part, then of the manifest.
        for name in ("structure.ckpt", "manifest.ckpt"):
            out = os.path.join(self.tmp, "killed_before_rename_" + name.split(".")[0])
            child = subprocess.run([STRUCTURE, self.case, "-o", out], stdin=subprocess.DEVNULL,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                   env=dict(os.environ, FSI_FAULT_KILL_BEFORE_RENAME=name + ":3"))
            self.assertEqual(child.returncode, -signal.SIGKILL, name)
            folder = os.path.join(out, "checkpoints")
            sets = sorted(os.listdir(folder))
            self.assertEqual(len(sets), 3, (name, sets))
            for s in sets:  # every file under its final name is whole
                for f in os.listdir(os.path.join(folder, s)):
                    if f.endswith(".ckpt"):
                        state_archive.read(os.path.join(folder, s, f))
            last = os.listdir(os.path.join(folder, sets[-1]))
            self.assertIn(name + ".tmp", last)
            self.assertNotIn("manifest.ckpt", last)
            made = run(self.case, out, "--restart")
            self.assertIn("resumed from the checkpoint of step %d " % (2 * EVERY), made.stdout, name)
            self.assertEqual(differences(self.full, out), [], name)

    def test_a_restart_without_a_checkpoint_says_so(self):
        out = os.path.join(self.tmp, "never_run")
        made = run(self.case, out, "--restart", check=False)
        self.assertEqual(made.returncode, 2)
        self.assertIn("no complete checkpoint of this case", made.stdout)


class KilledWriter(unittest.TestCase):
    """A run killed (kill -9) while it writes structure.h5 every step, 20 times at seeded random
    moments: the file opens, and the rows its `complete_steps` marker counts
    (python/fsi/results_file.py) equal the uninterrupted run's, bit for bit.

    The moments are fractions of the writing phase (from the file's creation to the run's end)
    and count from the killed run's own file creation, so that a machine busier during the kills
    than during the timed run still kills inside the writing, not in the start-up."""

    def test_the_marked_rows_of_a_killed_writer_are_complete(self):
        from fsi.results_file import complete_rows
        tmp = tempfile.mkdtemp(prefix="fsi_killed_writer_")
        self.addCleanup(shutil.rmtree, tmp, True)
        case = make_case(tmp)
        path = os.path.join(case, "case.yaml")
        with open(path) as f:
            text = f.read()
        text = re.sub(r"end_time_s: [0-9.e-]+", "end_time_s: 0.05", text, count=1)
        text = text.replace("output_interval_s: 0.01", "output_interval_s: 5.0e-5")  # a row every step
        with open(path, "w") as f:
            f.write(text)
        def start(out):
            """The structure solver on the case, once its structure.h5 exists (or it ended)."""
            child = subprocess.Popen([STRUCTURE, case, "-o", out], stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            while not os.path.exists(os.path.join(out, "structure.h5")) and child.poll() is None:
                time.sleep(0.002)
            return child

        full = os.path.join(tmp, "full")
        child = start(full)
        writing_started = time.time()
        self.assertEqual(child.wait(), 0)
        writing = time.time() - writing_started
        with h5py.File(os.path.join(full, "structure.h5"), "r") as f:
            reference = f["structures/rag/position_m"][()]
        draw = random.Random(6)
        marked = []
        for attempt in range(20):
            out = os.path.join(tmp, "killed")
            shutil.rmtree(out, ignore_errors=True)
            child = start(out)
            time.sleep(draw.uniform(0.1, 0.9) * writing)
            child.kill()
            child.wait()
            h5 = os.path.join(out, "structure.h5")
            if not os.path.exists(h5):
                continue
            with h5py.File(h5, "r") as f:
                rows = complete_rows(f)
                self.assertLessEqual(rows, len(f["time_s"]))
                x = f["structures/rag/position_m"][:rows]
            self.assertEqual(x.tobytes(), reference[:rows].tobytes(), "attempt %d, %d rows" % (attempt, rows))
            marked.append(rows)
        self.assertGreaterEqual(len([m for m in marked if m > 1]), 10, marked)


COUPLED_FILES = ("structure.h5", "coupling.h5", "structure.xdmf")


def launch(case, out, *extra):
    return subprocess.run([sys.executable, LAUNCH, "--bin-dir", BIN_DIR, "-o", out] + list(extra) + [case],
                          stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def start_until_first_set(case, out, first_step, new_session=False, extra=(), env=None):
    """The launcher on `case` (with the options `extra`, in the environment `env`), running in the
    background, once the checkpoint set of `first_step` is complete (or the run ended, or 120 s
    passed). new_session: in a process group of its own, to which a test sends Ctrl-C."""
    child = subprocess.Popen([sys.executable, LAUNCH, "--bin-dir", BIN_DIR, "-o", out] + list(extra) + [case],
                             stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                             start_new_session=new_session, env=env)
    wait_for_set(child, out, first_step)
    return child


def wait_for_set(child, out, step, limit_s=120):
    """Until the checkpoint set of `step` in `out` is complete, the child ended or limit_s passed."""
    first = os.path.join(out, "checkpoints", "step-%09d" % step, "manifest.ckpt")
    deadline = time.time() + limit_s
    while not os.path.exists(first) and child.poll() is None and time.time() < deadline:
        time.sleep(0.02)


def stop_at_boundary(out):
    """(signal, who, step) of the coupler's "interrupted by signal ... after step N" line, or None."""
    with open(os.path.join(out, "coupler.log")) as f:
        found = re.search(r"interrupted by signal (\d+) at (the coupler|participant \S+) after step (\d+)", f.read())
    return (int(found.group(1)), found.group(2), int(found.group(3))) if found else None


def make_coupled_case(folder, law=None):
    """rag-in-prescribed-flow (coupler, structure, prescribed flow), 0.2 s (5000 steps of 4e-5 s),
    a checkpoint every 0.05 s (1250 steps); `law` replaces the penalty law's line."""
    case = os.path.join(folder, "coupled_case" + ("_" + law.split()[0] + ("_implicit" if "implicit" in law else "")
                                                  + ("_iqn" if "iqn" in law else "") if law else ""))
    shutil.copytree(os.path.join(ROOT, "cases", "rag-in-prescribed-flow"), case,
                    ignore=shutil.ignore_patterns("output", "*.png", "*.gif"))
    path = os.path.join(case, "case.yaml")
    with open(path) as f:
        text = f.read()
    text = re.sub(r"end_time_s: [0-9.e-]+", "end_time_s: 0.2", text, count=1)
    text = text.replace("output_interval_s: 0.01", "output_interval_s: 0.01\n  checkpoint_interval_s: 0.05")
    if law:
        text, n = re.subn(r"\n  law: penalty\n  stiffness_n_per_m_per_measure: [0-9.e+-]+[^\n]*", "\n  law: " + law, text)
        assert n == 1, "no penalty law in the case"
    with open(path, "w") as f:
        f.write(text)
    return case


class CoupledPrescribedFlow(unittest.TestCase):
    """The coupler asks every participant for its part at the step boundary, adds its own
    (X^n, X^{n-1}) and the manifest; a restart resumes all three from the same set."""

    @classmethod
    def setUpClass(cls):
        if not (os.access(STRUCTURE, os.X_OK) and os.access(COUPLER, os.X_OK)):
            raise unittest.SkipTest("executables not built in %s" % BIN_DIR)
        cls.tmp = tempfile.mkdtemp(prefix="fsi_restart_coupled_")
        cls.case = make_coupled_case(cls.tmp)
        cls.full = os.path.join(cls.tmp, "full")
        started = time.time()
        made = launch(cls.case, cls.full)
        cls.full_wall_s = time.time() - started
        if made.returncode != 0:
            raise AssertionError("the uninterrupted run failed:\n" + made.stdout[-3000:])

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_a_coupled_run_stopped_by_its_end_time_and_restarted_equals_the_uninterrupted_run(self):
        out = os.path.join(self.tmp, "end_time")
        self.assertEqual(launch(self.case, out, "--end-time", "0.07").returncode, 0)
        self.assertEqual(sorted(os.listdir(os.path.join(out, "checkpoints", "step-000001750"))),
                         ["coupler.ckpt", "fluid.ckpt", "manifest.ckpt", "structure.ckpt"])
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("restart: resumed from the checkpoint of step 1750", made.stdout)
        self.assertEqual(differences(self.full, out, COUPLED_FILES), [])

    def test_a_coupled_run_with_one_process_killed_resumes_from_its_last_complete_checkpoint(self):
        """kill -9 of the coupler, the structure, the fluid, each at a seeded random moment: the
        others stop (the heartbeat), the newest complete set is used, the results equal."""
        draw = random.Random(1203)
        resumed = 0
        for victim in ("fsi-coupler", "fsi-structure", "fsi-prescribed-flow"):
            out = os.path.join(self.tmp, "kill-" + victim)
            # After the first complete set, at a seeded moment within the next 40 % of the run (a
            # fraction of the uninterrupted run's wall time alone could fall before the first set
            # on a loaded machine, and the restart then has nothing to resume from).
            child = start_until_first_set(self.case, out, 1250)
            time.sleep(draw.uniform(0.0, 0.4) * self.full_wall_s)
            subprocess.run(["pkill", "-9", "-f", "%s .*-o %s" % (victim, out)])
            code = child.wait(timeout=60)
            if code == 0:
                continue  # the run ended before the kill: nothing to resume
            self.assertNotEqual(code, 0, victim)
            made = launch(self.case, out, "--restart")
            self.assertEqual(made.returncode, 0, victim + ":\n" + made.stdout[-3000:])
            self.assertIn("restart: resumed from the checkpoint of step", made.stdout, victim)
            self.assertEqual(differences(self.full, out, COUPLED_FILES), [], victim)
            resumed += 1
        self.assertGreaterEqual(resumed, 2, "the kills fell outside the run: the test did not test")

    def stop_by_signal(self, name, send):
        """Starts the run, and at a seeded moment after its first complete set calls send(launcher,
        out); returns (out, the launcher's exit code, the step the coupler says it stopped after)."""
        out = os.path.join(self.tmp, name)
        child = start_until_first_set(self.case, out, 1250, new_session=True)
        time.sleep(random.Random(name).uniform(0.05, 0.3) * self.full_wall_s)
        send(child, out)
        code = child.wait(timeout=90)
        stopped = stop_at_boundary(out)
        self.stopped_by = stopped[1] if stopped else None
        return out, code, stopped[2] if stopped else None

    def assert_checkpointed_at_the_stop_and_resumed(self, out, code, stopped):
        self.assertEqual(code, 130)
        self.assertIsNotNone(stopped, "the coupler did not end the run at a step boundary")
        self.assertNotEqual(stopped % 1250, 0, "the stop fell on a periodic checkpoint: the test did not test")
        self.assertEqual(os.path.basename(newest_set(out)), "step-%09d" % stopped)
        self.assertTrue(os.path.exists(os.path.join(newest_set(out), "manifest.ckpt")))
        for name in ("coupling.h5", "structure.h5"):
            with h5py.File(os.path.join(out, name), "r") as f:
                self.assertEqual(f.attrs["status"].decode() if isinstance(f.attrs["status"], bytes)
                                 else f.attrs["status"], "interrupted", name)
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("restart: resumed from the checkpoint of step %d" % stopped, made.stdout)
        self.assertEqual(differences(self.full, out, COUPLED_FILES), [])

    def test_ctrl_c_ends_a_coupled_run_at_a_step_boundary_with_its_checkpoint(self):
        """Ctrl-C in a terminal (SIGINT to the launcher's whole process group): the coupler
        finishes the step, checkpoints it, ends the run; every process exits 130; the restart
        resumes from that very step and equals the uninterrupted run."""
        out, code, stopped = self.stop_by_signal("ctrl-c", lambda child, _: os.killpg(child.pid, signal.SIGINT))
        self.assert_checkpointed_at_the_stop_and_resumed(out, code, stopped)
        print("Ctrl-C: stopped after step %d, checkpointed, resumed equal" % stopped)

    def test_sigterm_to_one_participant_ends_the_run_the_same_way(self):
        """SIGTERM to the structure alone (a user's kill, a scheduler's): it tells the coupler
        (Heartbeat.stop_signal), which ends the run at the step boundary as for Ctrl-C."""
        out, code, stopped = self.stop_by_signal(
            "sigterm-structure",
            lambda _, out: subprocess.run(["pkill", "-TERM", "-f", "fsi-structure .*-o %s" % out], check=True))
        self.assertEqual(self.stopped_by, "participant structure:main")
        self.assert_checkpointed_at_the_stop_and_resumed(out, code, stopped)
        print("SIGTERM to the structure: stopped after step %d, checkpointed, resumed equal" % stopped)


def make_openfoam_case(folder, mpi_ranks=1):
    """sheet-in-openfoam-channel (coupler, structure, OpenFOAM fluid), 0.02 s (400 steps of
    5e-5 s), the backward time scheme (its restart needs U_0 and phi_0), a checkpoint every
    0.005 s (100 steps); the fluid on mpi_ranks MPI ranks."""
    case = os.path.join(folder, "openfoam_case_%d" % mpi_ranks)
    shutil.copytree(os.path.join(ROOT, "cases", "sheet-in-openfoam-channel"), case,
                    ignore=shutil.ignore_patterns("output", "*.png", "*.gif"))
    path = os.path.join(case, "case.yaml")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text.replace("output_interval_s: 0.005", "output_interval_s: 0.005\n  checkpoint_interval_s: 0.005"))
    schemes = os.path.join(case, "openfoam", "system", "fvSchemes")
    with open(schemes) as f:
        text = f.read()
    assert "default Euler;" in text
    with open(schemes, "w") as f:
        f.write(text.replace("default Euler;", "default backward;", 1))
    if mpi_ranks > 1:
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(re.sub(r"(\n  openfoam:\n)", r"\1    mpi_ranks: %d\n" % mpi_ranks, text, count=1))
    return case


def drop_old_time_fields(set_folder):
    """The negative control of fact 1 (../shared/docs/reliability-tests.md): the fluid's part
    without U_0 and phi_0, its file list and the manifest's checksum made to match."""
    part = os.path.join(set_folder, "fluid.ckpt")
    entries = state_archive.read(part)
    kept = []
    for i in range(entries["n_files"]):
        name, digest = entries.pop("files/%d/name" % i), entries.pop("files/%d/hash" % i)
        if os.path.basename(name) in ("U_0", "phi_0"):
            os.remove(os.path.join(set_folder, "fluid", name))  # names under fluid/: <time>/U_0
        else:
            kept.append((name, digest))
    for i, (name, digest) in enumerate(kept):
        entries["files/%d/name" % i], entries["files/%d/hash" % i] = name, digest
    entries["n_files"] = len(kept)
    state_archive.write(part, entries)
    manifest_path = os.path.join(set_folder, "manifest.ckpt")
    manifest = state_archive.read(manifest_path)
    with open(part, "rb") as f:
        checksum = "%016x" % int.from_bytes(f.read()[-8:], "little")
    for i in range(manifest["n_parts"]):
        if manifest["parts/%d/name" % i] == "fluid.ckpt":
            manifest["parts/%d/checksum" % i] = checksum
    state_archive.write(manifest_path, manifest)
    return len(kept)


FEED_CASE = """# Five 3 cm rags fed into a uniform flow every 25 ms, removed past x = 0.04 m.
run: {end_time_s: 0.2, time_step_s: 5.0e-5, output_interval_s: 0.005, checkpoint_interval_s: 0.05}
gravity_m_per_s2: [0, 0, 0]
collisions: {structure_contact: true}
feed:
  rags: 5
  seed: 3
  interval_s: 0.025
  first_release_s: 0.005
  region: {min_m: [0.03, -0.05, -0.05], max_m: [0.04, 0.05, 0.05]}
  kinds:
    - model: membrane
      size_m: [0.03, 0.03]
      n_points: [7, 7]
      material:
        mass_per_area_kg_per_m2: 0.08
        coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
  remove_when_past: {point_m: [0.04, 0, 0], normal: [1, 0, 0]}
fluid:
  prescribed:
    uniform: {velocity_m_per_s: [1.0, 0.0, 0.2]}
coupling: {law: penalty, stiffness_n_per_m_per_measure: 3.2e4}
"""


class FeedRestart(unittest.TestCase):
    """A feed resumed: rags released before the checkpoint and after it, one removed before it
    and others after, in a coupled run (coupler, structure, prescribed flow) and in a structure
    run of its own (the same rags falling along x). The resumed run equals the uninterrupted
    one bit for bit, exit times included. In the coupled run rag05 is released onto rag04, which
    has not left its place yet: the two pass through each other until they part."""

    @classmethod
    def setUpClass(cls):
        if not (os.access(STRUCTURE, os.X_OK) and os.access(COUPLER, os.X_OK)):
            raise unittest.SkipTest("executables not built in %s" % BIN_DIR)
        cls.tmp = tempfile.mkdtemp(prefix="fsi_restart_feed_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def write_case(self, name, text):
        case = os.path.join(self.tmp, name)
        os.makedirs(case)
        with open(os.path.join(case, "case.yaml"), "w") as f:
            f.write(text)
        return case

    def life(self, out):
        with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
            return {name: (float(g.attrs["release_time_s"]), float(g.attrs["exit_time_s"]))
                    for name, g in f["structures"].items()}

    def check_resumed(self, case, files):
        full, stopped = case + "_full", case + "_stopped"
        made = launch(case, full)
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        life = self.life(full)
        exits = sorted(e for _, e in life.values() if e == e)
        self.assertEqual(sorted(life), ["rag01", "rag02", "rag03", "rag04", "rag05"])
        # The story the test needs: a rag gone before the checkpoint of 0.1 s, one after it, and
        # one released after it.
        self.assertLess(exits[0], 0.1, life)
        self.assertGreater(exits[-1], 0.1, life)
        self.assertGreater(max(r for r, _ in life.values()), 0.1, life)
        self.assertEqual(launch(case, stopped, "--end-time", "0.1").returncode, 0)
        self.assertNotEqual(differences(full, stopped, files), [])
        made = launch(case, stopped, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("resumed from the checkpoint of step 2000", made.stdout)
        self.assertEqual(differences(full, stopped, files), [])
        self.assertEqual(self.life(stopped), life)

    def test_a_coupled_feed_resumes_bit_for_bit(self):
        self.check_resumed(self.write_case("coupled", FEED_CASE), COUPLED_FILES)

    def test_a_rag_torn_off_in_a_coupled_run_stays_torn_on_resuming(self):
        # A rag pinned along an edge in the stream, released at 90 ms and torn off above a stretch
        # ratio of 1.004 (at 92.85 ms): the structure and the coupler tear it at the same step (or
        # their idle lists would disagree and stop the run). Stopped at 91 ms, before the tear,
        # and resumed, the resumed processes tear it at the same step and the run equals the
        # uninterrupted one; stopped at 100 ms, after it, a torn rag stays torn.
        text = FEED_CASE + """structures:
  - name: hanging
    model: membrane
    size_m: [0.03, 0.03]
    n_points: [7, 7]
    origin_m: [-0.02, -0.1, 0.0]
    s1_direction: [1, 0, 0]
    s2_direction: [0, 0, 1]
    edges: {s1_min: pinned}
    material:
      mass_per_area_kg_per_m2: 0.08
      coefficients: {tension_coefficient_n_per_m: 10, bending_rigidity_n_m: 1.0e-6}
    release_time_s: 0.09
    tear_above_stretch_ratio: 1.004
"""
        case = self.write_case("torn", text)
        full = case + "_full"
        made = launch(case, full)
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("[coupler] [warning] structure 'hanging' torn off the scene", made.stdout)
        with h5py.File(os.path.join(full, "structure.h5"), "r") as f:
            g = f["structures"]["hanging"]
            reason = g.attrs["exit_reason"]
            self.assertEqual(reason.decode() if isinstance(reason, bytes) else str(reason), "torn")
            self.assertTrue(0.09 < float(g.attrs["exit_time_s"]) < 0.1, float(g.attrs["exit_time_s"]))
        for stop in ("0.091", "0.1"):
            stopped = "%s_stopped_%s" % (case, stop)
            self.assertEqual(launch(case, stopped, "--end-time", stop).returncode, 0)
            made = launch(case, stopped, "--restart")
            self.assertEqual(made.returncode, 0, made.stdout[-3000:])
            self.assertEqual("torn off the scene" in made.stdout, stop == "0.091", stop)
            self.assertEqual(differences(full, stopped, COUPLED_FILES), [], stop)

    def test_a_structure_feed_resumes_bit_for_bit(self):
        text = FEED_CASE.split("fluid:")[0].replace("gravity_m_per_s2: [0, 0, 0]", "gravity_m_per_s2: [200, 0, 0]")
        self.check_resumed(self.write_case("alone", text), ("structure.h5", "structure.xdmf"))


class TurbulentFeedRestart(unittest.TestCase):
    """cases/rag-feed shortened (a precursor of 10 steps, 3 rags released 4 steps apart, 16
    coupled steps) through the launcher: coupler, structure and OpenFOAM with Spalart-Allmaras
    DDES and wall functions, the impeller penalized and turning. Each rag waits where the feed
    placed it, bit for bit, until its release time, and is carried up by the water after it; the
    case's postprocess.py writes the feed's report (every rag still in the sump, none retained:
    the run is shorter than the rise into the pump) and its pictures. The same run stopped after 8 steps and
    resumed equals the uninterrupted one bit for bit: the rags, the coupling, the impeller's
    loads and the fields. (A uniform patch value is written as text: at OpenFOAM's writePrecision
    of 8 digits the inlet's nut came back rounded and the first step after a restart differed by
    round-off; the fluid writes every digit.)"""

    @classmethod
    def setUpClass(cls):
        if not os.access(os.path.join(BIN_DIR, "fsi-openfoam-fluid"), os.X_OK):
            raise unittest.SkipTest("fsi-openfoam-fluid not built (no OpenFOAM)")
        cls.tmp = tempfile.mkdtemp(prefix="fsi_restart_turbulent_feed_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def check_the_feed_and_its_report(self, case, out):
        with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
            times = f["time_s"][:]
            self.assertEqual(sorted(f["structures"].keys()), ["rag01", "rag03", "square02"])
            for name, release in (("rag01", 0.0), ("square02", 0.001), ("rag03", 0.002)):
                g = f["structures"][name]
                self.assertAlmostEqual(float(g.attrs["release_time_s"]), release, delta=1e-12)
                self.assertTrue(numpy.isnan(g.attrs["exit_time_s"]), name)   # none has left
                x = g["position_m"][:]
                before = times < release - 1e-9
                self.assertTrue(numpy.array_equal(x[before], numpy.broadcast_to(x[0], x[before].shape)), name)
                self.assertGreater(float(numpy.mean(x[-1, :, 2] - x[0, :, 2])), 0.0, name)   # carried up
        made = subprocess.run([sys.executable, os.path.join(case, "postprocess.py"), out, case, "--no-animation"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python")))
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        with open(os.path.join(out, "feed_report.yaml")) as f:
            report = yaml.safe_load(f)
        # 16 steps: each rag carried up a little, none into the suction pipe yet.
        self.assertEqual((report["rags"], report["outcomes"]["in_sump"]), (3, 3))
        self.assertFalse(report["verdict"]["clogged"])
        self.assertEqual(report["verdict"]["saturation_rags"], 0)
        for name in ("feed_rags.csv", "feed_revolutions.csv", "feed_timeline.png", "feed_retained.png"):
            self.assertTrue(os.path.isfile(os.path.join(out, name)), name)

    def test_a_turbulent_feed_in_the_pump_resumes_bit_for_bit(self):
        case = os.path.join(self.tmp, "case")
        shutil.copytree(os.path.join(ROOT, "cases", "rag-feed"), case, ignore=shutil.ignore_patterns(
            "output", "geometry", "openfoam-*", "pump.yaml", ".geometry.lock"))
        path = os.path.join(case, "case.yaml")
        with open(path) as f:
            text = f.read()
        for old, new in (("precursor_time_s: 0.5", "precursor_time_s: 0.0025"), ("rags: 20", "rags: 3"),
                         ("interval_s: 0.083333", "interval_s: 0.001"), ("end_time_s: 2.0", "end_time_s: 0.004")):
            self.assertIn(old, text)
            text = text.replace(old, new)
        with open(path, "w") as f:
            f.write(text)
        full, stopped = os.path.join(self.tmp, "full"), os.path.join(self.tmp, "stopped")
        made = launch(case, full)
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.check_the_feed_and_its_report(case, full)
        # The stopped run starts from the same precursor (the launcher reuses it: same fingerprint).
        shutil.copytree(os.path.join(full, "precursor"), os.path.join(stopped, "precursor"), copy_function=os.link)
        made = launch(case, stopped, "--end-time", "0.002")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        files = COUPLED_FILES   # coupling.h5 holds the impeller's loads
        self.assertNotEqual(differences(full, stopped, files), [])
        made = launch(case, stopped, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("resumed from the checkpoint of step 8", made.stdout)
        self.assertEqual(differences(full, stopped, files), [])
        for field in ("U", "p", "phi", "nut", "nuTilda"):
            with open(os.path.join(full, "openfoam", "0.004", field), "rb") as a, \
                    open(os.path.join(stopped, "openfoam", "0.004", field), "rb") as b:
                self.assertEqual(a.read(), b.read(), field)


class CouplingLawState(unittest.TestCase):
    """The laws with a state of their own: the paper's IB points X_ib (two_point_sets) and the
    feedback integral go into the coupler's part; a restart without them could not be exact."""

    def setUp(self):
        if not (os.access(STRUCTURE, os.X_OK) and os.access(COUPLER, os.X_OK)):
            self.skipTest("executables not built in %s" % BIN_DIR)
        self.tmp = tempfile.mkdtemp(prefix="fsi_restart_law_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_a_law_with_state_resumes_bit_for_bit(self):
        for law in ("two_point_sets\n  stiffness_n_per_m_per_measure: 2.5e5",
                    "feedback\n  alpha_n_per_m_per_measure: 2.5e5\n  beta_n_s_per_m_per_measure: 5",
                    # Implicit coupling: the next step's first iterate is in the coupler's part
                    # (Aitken keeps nothing across steps), and so are IQN-ILS's columns of the
                    # last reuse_steps steps (without them the resumed run differs: structure.h5
                    # from the tolerance's digits on, checked once by skipping their load).
                    "penalty\n  stiffness_n_per_m_per_measure: 2.5e7\n  scheme: implicit\n  implicit:\n"
                    "    acceleration: aitken\n    tolerance: 1.0e-8",
                    "penalty\n  stiffness_n_per_m_per_measure: 2.5e7\n  scheme: implicit\n  implicit:\n"
                    "    acceleration: iqn_ils\n    reuse_steps: 4\n    tolerance: 1.0e-8"):
            name = law.split()[0] + ("_implicit" if "implicit" in law else "") + ("_iqn" if "iqn" in law else "")
            case = make_coupled_case(self.tmp, law)
            full = os.path.join(self.tmp, name + "_full")
            made = launch(case, full)
            self.assertEqual(made.returncode, 0, made.stdout[-3000:])
            self.assertIn("coupling law: " + law.split()[0], made.stdout)
            out = os.path.join(self.tmp, name + "_stopped")
            self.assertEqual(launch(case, out, "--end-time", "0.07").returncode, 0)
            made = launch(case, out, "--restart")
            self.assertEqual(made.returncode, 0, made.stdout[-3000:])
            self.assertIn("restart: resumed from the checkpoint of step 1750", made.stdout)
            self.assertEqual(differences(full, out, COUPLED_FILES), [], name)


def start_openfoam_fixture(cls, prefix, make):
    """setUpClass of an OpenFOAM restart class: skips without the fluid; cls.tmp, cls.case =
    make(cls.tmp), cls.full (the uninterrupted run, which must succeed), its wall time and output."""
    if not os.access(os.path.join(BIN_DIR, "fsi-openfoam-fluid"), os.X_OK):
        raise unittest.SkipTest("fsi-openfoam-fluid not built (no OpenFOAM)")
    cls.tmp = tempfile.mkdtemp(prefix=prefix)
    cls.case = make(cls.tmp)
    cls.full = os.path.join(cls.tmp, "full")
    started = time.time()
    made = launch(cls.case, cls.full)
    cls.full_wall_s = time.time() - started
    if made.returncode != 0:
        raise AssertionError("the uninterrupted run failed:\n" + made.stdout[-3000:])
    cls.full_log = made.stdout


class CoupledOpenFoam(unittest.TestCase):
    """The OpenFOAM fluid's part: its binary fields of the checkpoint's time with the old-time
    fields and uniform/time; a restart starts OpenFOAM from them. Bitwise, as a static mesh
    with binary fields allows (fact 1 of ../shared/docs/reliability-tests.md)."""

    @classmethod
    def setUpClass(cls):
        start_openfoam_fixture(cls, "fsi_restart_openfoam_", make_openfoam_case)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def fields_equal(self, out):
        for field in ("U", "p", "phi"):
            with open(os.path.join(self.full, "openfoam", "0.02", field), "rb") as a, \
                    open(os.path.join(out, "openfoam", "0.02", field), "rb") as b:
                if a.read() != b.read():
                    return False
        return True

    def test_an_openfoam_run_stopped_and_restarted_equals_the_uninterrupted_run(self):
        out = os.path.join(self.tmp, "end_time")
        self.assertEqual(launch(self.case, out, "--end-time", "0.0075").returncode, 0)
        fields = os.listdir(os.path.join(out, "checkpoints", "step-000000150", "fluid", "0.0075"))
        self.assertTrue({"U", "U_0", "p", "phi", "phi_0", "uniform"} <= set(fields), fields)
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        with open(os.path.join(out, "fluid.log")) as f:
            self.assertIn("restart: the fields of t = 0.0075 s (step 150)", f.read())
        self.assertEqual(differences(self.full, out, COUPLED_FILES), [])
        self.assertTrue(self.fields_equal(out))

    def test_a_checkpoint_without_the_old_time_fields_resumes_but_does_not_equal_the_run(self):
        out = os.path.join(self.tmp, "no_old_time")
        self.assertEqual(launch(self.case, out, "--end-time", "0.0075").returncode, 0)
        drop_old_time_fields(os.path.join(out, "checkpoints", "step-000000150"))
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertNotEqual(differences(self.full, out, COUPLED_FILES), [])
        self.assertFalse(self.fields_equal(out))

    def test_an_openfoam_run_with_the_fluid_killed_resumes_from_its_last_complete_checkpoint(self):
        draw = random.Random(77)
        out = os.path.join(self.tmp, "kill-fluid")
        # After its first checkpoint, at a seeded moment within the next tenth of the run (a
        # fraction of the uninterrupted run's wall time alone would miss on a loaded machine).
        child = start_until_first_set(self.case, out, 100)
        time.sleep(draw.uniform(0.0, 0.1) * self.full_wall_s)
        subprocess.run(["pkill", "-9", "-f", "fsi-openfoam-fluid .*-o %s" % out])
        self.assertNotEqual(child.wait(timeout=60), 0)
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("restart: resumed from the checkpoint of step", made.stdout)
        self.assertEqual(differences(self.full, out, COUPLED_FILES), [])
        self.assertTrue(self.fields_equal(out))

    def test_ctrl_c_ends_an_openfoam_run_at_a_step_boundary_with_its_checkpoint(self):
        """Ctrl-C (SIGINT to the launcher's process group): OpenFOAM finishes the step with the
        others, writes its fields into the set of that step; the restart equals the run."""
        out, stopped = ctrl_c_and_restart(self, self.case, os.path.join(self.tmp, "ctrl-c"), 78)
        self.assertEqual(differences(self.full, out, COUPLED_FILES), [])
        self.assertTrue(self.fields_equal(out))
        print("Ctrl-C: the OpenFOAM run stopped after step %d, checkpointed, resumed equal" % stopped)


def ctrl_c_and_restart(test, case, out, seed):
    """Starts the run, sends SIGINT to the launcher's process group at a seeded moment after
    the first checkpoint (step 100), checks that the run ended at a step boundary with that
    step's set, and resumes it; returns (out, the step)."""
    child = start_until_first_set(case, out, 100, new_session=True)
    time.sleep(random.Random(seed).uniform(0.05, 0.5))
    os.killpg(child.pid, signal.SIGINT)
    test.assertEqual(child.wait(timeout=90), 130)
    stopped = stop_at_boundary(out)
    test.assertTrue(stopped, "the coupler did not end the run at a step boundary")
    test.assertEqual(stopped[0], 2)
    step = stopped[2]
    test.assertNotIn(step, (100, 200, 300, 400), "the stop fell on a periodic checkpoint: the test did not test")
    test.assertEqual(os.path.basename(newest_set(out)), "step-%09d" % step)
    made = launch(case, out, "--restart")
    test.assertEqual(made.returncode, 0, made.stdout[-3000:])
    test.assertIn("restart: resumed from the checkpoint of step %d" % step, made.stdout)
    return out, step


class CoupledOpenFoamRanks(unittest.TestCase):
    """The OpenFOAM fluid on 2 MPI ranks: every rank writes its processor<k>/<time> folder at
    the checkpoint (a collective write), the master copies them into the set, and a restart
    restores them into the same decomposition and starts mpirun from them. Bitwise, like one
    rank. A restart with another number of ranks is refused."""

    @classmethod
    def setUpClass(cls):
        start_openfoam_fixture(cls, "fsi_restart_ranks_", lambda tmp: make_openfoam_case(tmp, mpi_ranks=2))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_a_run_on_two_ranks_stopped_and_restarted_equals_the_uninterrupted_run(self):
        out = os.path.join(self.tmp, "end_time")
        self.assertEqual(launch(self.case, out, "--end-time", "0.0075").returncode, 0)
        part = os.path.join(out, "checkpoints", "step-000000150", "fluid")
        self.assertEqual(sorted(os.listdir(part)), ["processor0", "processor1"])
        self.assertTrue({"U", "U_0", "phi_0", "uniform"} <= set(os.listdir(os.path.join(part, "processor1", "0.0075"))))
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertEqual(differences(self.full, out, COUPLED_FILES), [])
        for rank in ("processor0", "processor1"):
            for field in ("U", "p", "phi"):
                with open(os.path.join(self.full, "openfoam", rank, "0.02", field), "rb") as a, \
                        open(os.path.join(out, "openfoam", rank, "0.02", field), "rb") as b:
                    self.assertEqual(a.read(), b.read(), (rank, field))

    def test_ctrl_c_ends_a_run_on_two_ranks_at_a_step_boundary_with_its_checkpoint(self):
        out, stopped = ctrl_c_and_restart(self, self.case, os.path.join(self.tmp, "ctrl-c"), 79)
        self.assertEqual(differences(self.full, out, COUPLED_FILES), [])
        for rank in ("processor0", "processor1"):
            for field in ("U", "p", "phi"):
                with open(os.path.join(self.full, "openfoam", rank, "0.02", field), "rb") as a, \
                        open(os.path.join(out, "openfoam", rank, "0.02", field), "rb") as b:
                    self.assertEqual(a.read(), b.read(), (rank, field))
        print("Ctrl-C: the run on 2 ranks stopped after step %d, checkpointed, resumed equal" % stopped)

    def test_a_restart_with_another_number_of_ranks_is_refused(self):
        # mpi_ranks is part of the case, so its checkpoints are another case's (fluid.ckpt also
        # records its ranks, should a set be moved by hand).
        out = os.path.join(self.tmp, "other_ranks")
        self.assertEqual(launch(self.case, out, "--end-time", "0.0075").returncode, 0)
        one_rank = os.path.join(self.tmp, "one_rank_case")
        shutil.copytree(self.case, one_rank)
        path = os.path.join(one_rank, "case.yaml")
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text.replace("    mpi_ranks: 2\n", "", 1))
        made = launch(one_rank, out, "--restart")
        self.assertEqual(made.returncode, 2, made.stdout[-2000:])
        self.assertIn("written by another case", made.stdout)
        self.assertIn("fluid.openfoam.mpi_ranks was 2, is 1 now", made.stdout)  # the key that changed, named
        self.assertIn("--restart: no complete checkpoint of this case", made.stdout)


def make_flow_alone_case(folder, write_format="binary"):
    """rotating-disc (the flow alone: OpenFOAM with the penalized disc turning), 2 s (100 steps of
    0.02 s), a checkpoint every 0.2 s (10 steps), its fields written in write_format."""
    case = os.path.join(folder, "flow_alone_" + write_format)
    shutil.copytree(os.path.join(ROOT, "cases", "rotating-disc"), case,
                    ignore=shutil.ignore_patterns("output", "*.png", "*.gif", "openfoam-*"))
    path = os.path.join(case, "case.yaml")
    with open(path) as f:
        text = f.read()
    text = re.sub(r"end_time_s: [0-9.e-]+", "end_time_s: 2.0", text, count=1)
    text = text.replace("output_interval_s: 4.0", "output_interval_s: 2.0\n  checkpoint_interval_s: 0.2")
    with open(path, "w") as f:
        f.write(text)
    control = os.path.join(case, "openfoam", "system", "controlDict")
    with open(control) as f:
        text = f.read()
    assert "writeFormat     ascii;" in text
    with open(control, "w") as f:
        f.write(text.replace("writeFormat     ascii;", "writeFormat     %s;" % write_format))
    return case


FLOW_ALONE_TABLES = ("forces.csv", "parts.csv", "parts_staircase.csv", "penalization.csv")


class FlowAloneOpenFoam(unittest.TestCase):
    """A case without structures (a pump's operating point): the fluid checkpoints by itself
    (no coupler asks it), every interval, at the end and on Ctrl-C; a restart starts OpenFOAM
    from the newest set and continues forces.csv, parts.csv, parts_staircase.csv, penalization.csv
    and timings.csv from its step. Bitwise on a static mesh with binary fields; ascii fields are warned of."""

    @classmethod
    def setUpClass(cls):
        start_openfoam_fixture(cls, "fsi_restart_alone_", make_flow_alone_case)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def assert_equals_the_uninterrupted_run(self, out, tables=FLOW_ALONE_TABLES):
        for table in tables:
            with open(os.path.join(self.full, table), "rb") as a, open(os.path.join(out, table), "rb") as b:
                self.assertEqual(a.read(), b.read(), table)
        with open(os.path.join(out, "timings.csv")) as f:
            self.assertEqual([line.split(",")[0] for line in f], [line.split(",")[0] for line in open(
                os.path.join(self.full, "timings.csv"))])
        for field in ("U", "p", "phi"):
            with open(os.path.join(self.full, "openfoam", "2", field), "rb") as a, \
                    open(os.path.join(out, "openfoam", "2", field), "rb") as b:
                self.assertEqual(a.read(), b.read(), field)

    def test_a_run_stopped_by_its_end_time_and_restarted_equals_the_uninterrupted_run(self):
        self.assertIn("checkpoint: step 100 (t = 2 s)", self.full_log)
        self.assertNotIn("writeFormat ascii", self.full_log)
        out = os.path.join(self.tmp, "end_time")
        self.assertEqual(launch(self.case, out, "--end-time", "0.7").returncode, 0)
        # The end of the run is a set (step 35), the periodic ones before it: the last 2 kept.
        self.assertEqual(sorted(os.listdir(os.path.join(out, "checkpoints"))),
                         ["step-000000030", "step-000000035"])
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("restart: resumed from the checkpoint of step 35 (t = 0.7 s)", made.stdout)
        self.assert_equals_the_uninterrupted_run(out)
        with open(os.path.join(out, "fluid.log")) as f:
            log = f.read()
        self.assertIn("flow: t = 0.7 of 0.7 s", log)   # the first run's log is continued, not replaced
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 2, made.stdout[-2000:])
        self.assertIn("the newest checkpoint is of step 100", made.stdout)
        self.assertIn("give a later --end-time", made.stdout)

    def test_a_run_that_ended_on_a_short_step_goes_on_from_its_own_time(self):
        # --end-time 0.71: 35 steps of 0.02 s and one of 0.01 s. The restart's steps start there
        # (not at 36 dt = 0.72 s, where the bodies' poses would run ahead of the mesh's time)
        # and land on the case's end with a last step of 0.01 s.
        out = os.path.join(self.tmp, "short_step")
        self.assertEqual(launch(self.case, out, "--end-time", "0.71").returncode, 0)
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("restart: resumed from the checkpoint of step 36 (t = 0.71 s)", made.stdout)
        times = numpy.loadtxt(os.path.join(out, "forces.csv"), delimiter=",", skiprows=1, ndmin=2)[:, 0]
        self.assertAlmostEqual(times[35], 0.71, places=9)
        numpy.testing.assert_allclose(numpy.diff(times[35:-1]), 0.02, rtol=1e-6)
        self.assertAlmostEqual(times[-1], 2.0, places=9)
        self.assertTrue(os.path.isdir(os.path.join(out, "openfoam", "2")))

    def test_rows_written_after_the_checkpoint_a_line_cut_short_and_an_older_builds_table(self):
        """A run killed after its tables were flushed past its last set: the restart keeps their
        rows up to the set's time only. Its penalization.csv lacks the last column
        (held_fluid_power_w, added on 2026-12-06), as a set of a run begun before that has it:
        the restart keeps those rows with the new column nan."""
        out = os.path.join(self.tmp, "rows_after")
        self.assertEqual(launch(self.case, out, "--end-time", "0.6").returncode, 0)
        path = os.path.join(out, "penalization.csv")
        with open(path) as f:
            lines = [line.rstrip("\n").rsplit(",", 1)[0] for line in f]
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        for table in FLOW_ALONE_TABLES + ("timings.csv",):
            with open(os.path.join(out, table), "a") as f:
                f.write("0.62,1,2,3,4,5,6\n0.64,1,2")
        made = launch(self.case, out, "--restart")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assert_equals_the_uninterrupted_run(out, ("forces.csv", "parts.csv", "parts_staircase.csv"))
        with open(path) as f, open(os.path.join(self.full, "penalization.csv")) as g:
            rows, full = f.read().splitlines(), g.read().splitlines()
        self.assertEqual(rows[0], full[0])
        self.assertTrue(rows[0].endswith(",held_fluid_power_w"))
        self.assertEqual(len(rows), len(full))
        self.assertEqual(rows[30], lines[30] + ",nan")    # t = 0.6 s, written before
        self.assertEqual(rows[31:], full[31:])            # after the restart: the run's own

    def ctrl_c_then_restart(self, child, case, out, wait_s, *restart_options):
        """Ctrl-C to the launcher's process group: the fluid exits 130 with the set of the step it
        says it stopped after, and the restart resumes from that set. Returns the step."""
        os.killpg(child.pid, signal.SIGINT)
        self.assertEqual(child.wait(timeout=wait_s), 130)
        with open(os.path.join(out, "fluid.log")) as f:
            found = re.search(r"flow interrupted at t = \S+ s after step (\d+)", f.read())
        self.assertTrue(found, "the fluid did not say where it stopped")
        step = int(found.group(1))
        self.assertEqual(os.path.basename(newest_set(out)), "step-%09d" % step)
        made = launch(case, out, "--restart", *restart_options)
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("restart: resumed from the checkpoint of step %d" % step, made.stdout)
        return step

    def test_ctrl_c_ends_the_flow_at_a_step_boundary_with_its_checkpoint(self):
        out = os.path.join(self.tmp, "ctrl-c")
        child = start_until_first_set(self.case, out, 10, new_session=True)
        time.sleep(random.Random(80).uniform(0.3, 1.5))
        step = self.ctrl_c_then_restart(child, self.case, out, 90)
        self.assertLess(step, 100)
        self.assert_equals_the_uninterrupted_run(out)
        print("Ctrl-C: the flow alone stopped after step %d, checkpointed, resumed equal" % step)

    def test_ctrl_c_on_two_ranks_waits_for_a_step_longer_than_mpiruns_kill_delay(self):
        """mpirun, given SIGINT, passes SIGTERM to the ranks and kills them a second later: a
        pump's step takes longer. The fluid keeps mpirun out of the terminal's reach and passes
        the stop on as SIGUSR1, which leaves the ranks running: they finish a 3 s step and
        checkpoint it."""
        case = os.path.join(self.tmp, "two_ranks_slow")
        shutil.copytree(self.case, case)
        path = os.path.join(case, "case.yaml")
        with open(path) as f:
            text = f.read()
        self.assertIn("  openfoam:\n", text)
        with open(path, "w") as f:
            f.write(text.replace("  openfoam:\n", "  openfoam:\n    mpi_ranks: 2\n", 1))
        out = os.path.join(self.tmp, "two_ranks_slow_out")
        child = start_until_first_set(case, out, 2, new_session=True, extra=["--set", "run.checkpoint_interval_s=0.04"],
                                      env=dict(os.environ, FSI_FAULT_STEP_SLEEP_S="3"))
        self.assertIsNone(child.poll(), "the run ended before its first checkpoint")
        time.sleep(0.5)  # within step 3's 3 s
        self.assertGreaterEqual(self.ctrl_c_then_restart(child, case, out, 60, "--end-time", "0.1"), 3)

    def test_fields_written_in_ascii_are_warned_of(self):
        case = make_flow_alone_case(self.tmp, "ascii")
        made = launch(case, os.path.join(self.tmp, "ascii"), "--end-time", "0.04")
        self.assertEqual(made.returncode, 0, made.stdout[-3000:])
        self.assertIn("writeFormat ascii", made.stdout)
        self.assertIn("writeFormat binary makes it exact", made.stdout)


if __name__ == "__main__":
    unittest.main()
