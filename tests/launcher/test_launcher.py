#!/usr/bin/python3
"""Contract tests of python/fsi/fsi_launch.py (the launcher behind `./fsi run`), against fake
fsi-coupler / fsi-structure / fsi-prescribed-flow executables written into a temporary bin
folder. The fakes follow the executables' contract (--plan, coupler.endpoint, spdlog-like
lines, exit codes, signals) and record what they were given. Standard library only:
    /usr/bin/python3 tests/launcher/test_launcher.py
"""

import json
import os
import signal
import subprocess
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
LAUNCHER = os.path.join(HERE, "..", "..", "python", "fsi", "fsi_launch.py")
PYTHON = "/usr/bin/python3"

# One fake for all three executables: its role comes from its file name, its behaviour from
# fake.json next to it; it records its arguments, pid and the signals it received in RECORD/.
FAKE = r'''#!/usr/bin/python3
import json, os, signal, sys, time

ROLE = {"fsi-coupler": "coupler", "fsi-structure": "structure",
        "fsi-prescribed-flow": "fluid"}[os.path.basename(sys.argv[0])]
here = os.path.dirname(os.path.abspath(sys.argv[0]))
config = json.load(open(os.path.join(here, "fake.json")))
record = config["record_dir"]
args = sys.argv[1:]

def note(event):
    with open(os.path.join(record, ROLE + ".events"), "a") as f:
        f.write(event + "\n")

def open_events(role):
    try:
        with open(os.path.join(record, role + ".events")) as f:
            return f.read().split("\n")
    except OSError:
        return []

def log(level, message):
    print("[21:10:00.123] [%s] [%s] %s" % (ROLE, level, message), file=sys.stderr, flush=True)

if args and args[0] == "--plan":
    plan = config["plan"]
    if plan.get("exit", 0):
        print(plan["stderr"], file=sys.stderr)
        sys.exit(plan["exit"])
    out = args[args.index("-o") + 1] if "-o" in args else plan["output"]
    print("output " + os.path.abspath(out))
    for name, exe in plan["processes"]:
        print("process %s %s" % (name, exe))
    for name in plan.get("precursors", []):
        print("precursor %s" % name)
    sys.exit(0)

me = config.get(ROLE, {})
if "--precursor" in args:
    with open(os.path.join(record, ROLE + ".precursor.json"), "w") as f:
        json.dump({"argv": args, "pid": os.getpid(), "at": time.time()}, f)
    time.sleep(me.get("precursor_sleep", 0))
    sys.exit(me.get("precursor_exit", 0))
with open(os.path.join(record, ROLE + ".json"), "w") as f:
    json.dump({"argv": args, "pid": os.getpid(), "at": time.time()}, f)

def on_signal(signum, _frame):
    note(signal.Signals(signum).name)
    if signum == signal.SIGTERM and me.get("ignore_sigterm"):
        return
    if signum == signal.SIGINT and me.get("finish_step_s") is not None:  # our processes: the step first
        return
    sys.exit(130)

signal.signal(signal.SIGINT, on_signal)
signal.signal(signal.SIGTERM, on_signal)

if ROLE == "coupler" and me.get("endpoint"):
    out = args[args.index("-o") + 1] if "-o" in args else config["plan"]["output"]
    time.sleep(me.get("endpoint_delay", 0))
    tmp = os.path.join(out, "coupler.endpoint.tmp")
    with open(tmp, "w") as f:
        f.write(me["endpoint"] + "\n")
    os.rename(tmp, os.path.join(out, "coupler.endpoint"))

for level, message in me.get("lines", []):
    log(level, message)
if me.get("after_exit_of"):   # the sleep counts from another fake's exit, not from this one's start
    while not any(line.startswith("exit") for line in open_events(me["after_exit_of"])):
        time.sleep(0.01)
deadline = time.monotonic() + me.get("sleep", 0)
while time.monotonic() < deadline:
    time.sleep(0.01)
note("exit %d" % me.get("exit", 0))
sys.exit(me.get("exit", 0))
'''

COUPLED = [["coupler", "fsi-coupler"], ["structure", "fsi-structure"],
           ["fluid", "fsi-prescribed-flow"]]
ENDPOINT = "tcp://127.0.0.1:40123"


class LauncherTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="fsi-launcher-test-")
        root = self.tmp.name
        self.bin = os.path.join(root, "bin")
        self.record = os.path.join(root, "record")
        self.case = os.path.join(root, "case")
        self.out = os.path.join(self.case, "output")
        for d in (self.bin, self.record, self.out):
            os.makedirs(d)
        with open(os.path.join(self.case, "case.yaml"), "w") as f:
            f.write("run: {end_time_s: 1}\n")
        for exe in ("fsi-coupler", "fsi-structure", "fsi-prescribed-flow"):
            path = os.path.join(self.bin, exe)
            with open(path, "w") as f:
                f.write(FAKE)
            os.chmod(path, 0o755)
        self.env = dict(os.environ, FSI_STOP_GRACE_S="1", FSI_KILL_GRACE_S="0.5",
                        FSI_ENDPOINT_TIMEOUT_S="5")
        self.launcher = None

    def tearDown(self):
        if self.launcher is not None and self.launcher.poll() is None:
            os.killpg(self.launcher.pid, signal.SIGKILL)
            self.launcher.wait()
        for name in ("coupler", "structure", "fluid"):  # leave no fake running
            info = self.recorded(name)
            if info and info["pid"] != getattr(self.launcher, "pid", None):
                try:
                    os.kill(info["pid"], signal.SIGKILL)
                except OSError:
                    pass
        self.tmp.cleanup()

    # helpers -----------------------------------------------------------------------------
    def configure(self, processes=COUPLED, plan_exit=0, plan_stderr="", precursors=(), **roles):
        config = {"record_dir": self.record,
                  "plan": {"output": self.out, "processes": processes, "exit": plan_exit,
                           "stderr": plan_stderr, "precursors": list(precursors)}}
        config.update(roles)
        with open(os.path.join(self.bin, "fake.json"), "w") as f:
            json.dump(config, f)

    def start(self, *args, env=None):
        command = [PYTHON, LAUNCHER, "--bin-dir", self.bin] + list(args)
        self.launcher = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                         env=env or self.env, start_new_session=True)
        return self.launcher

    def launch(self, *args, timeout=20, env=None):
        p = self.start(*args, env=env)
        began = time.monotonic()
        out, err = p.communicate(timeout=timeout)
        return p.returncode, out.decode(), err.decode(), time.monotonic() - began

    def recorded(self, name):
        try:
            with open(os.path.join(self.record, name + ".json")) as f:
                return json.load(f)
        except (OSError, ValueError):
            return None

    def events(self, name):
        try:
            with open(os.path.join(self.record, name + ".events")) as f:
                return f.read().split("\n")[:-1]
        except OSError:
            return []

    def wait_started(self, names, timeout=5):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if all(self.recorded(n) for n in names):
                return
            time.sleep(0.02)
        self.fail("not all of %s started" % names)

    @staticmethod
    def alive(pid):
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return False
        try:  # a zombie is not alive
            with open("/proc/%d/stat" % pid) as f:
                return f.read().split(")")[-1].split()[0] != "Z"
        except OSError:
            return False

    def assertNoTraceback(self, err):
        self.assertNotIn("Traceback", err)

    # structure only ----------------------------------------------------------------------
    def test_structure_only_execs_the_structure_solver_with_its_exit_code(self):
        self.configure(processes=[["structure", "fsi-structure"]],
                       structure={"exit": 1, "lines": [["info", "step 1"]]})
        code, _, err, _ = self.launch(self.case)
        self.assertEqual(code, 1)
        info = self.recorded("structure")
        self.assertEqual(info["argv"], [self.case])  # exactly today's command line
        self.assertEqual(info["pid"], self.launcher.pid)  # exec'd in place of the launcher
        self.assertIn("[structure] [info] step 1", err)
        self.assertIsNone(self.recorded("coupler"))

    def test_structure_only_passes_output_dir_and_verbose(self):
        self.configure(processes=[["structure", "fsi-structure"]], structure={})
        other = os.path.join(self.tmp.name, "elsewhere")
        code, _, _, _ = self.launch("-o", other, "-v", self.case)
        self.assertEqual(code, 0)
        self.assertEqual(self.recorded("structure")["argv"], [self.case, "-o", other, "-v"])

    def test_end_time_is_passed_to_every_process(self):
        self.configure(processes=[["structure", "fsi-structure"]], structure={})
        code, _, _, _ = self.launch("--end-time", "0.25", self.case)
        self.assertEqual(code, 0)
        self.assertEqual(self.recorded("structure")["argv"], [self.case, "--end-time", "0.25"])

    def test_keys_set_on_the_command_line_reach_every_process_in_order(self):
        """--set (./fsi pump-curve's flow rate per point) goes to every process, as the preset
        does, so that all of them read the same case and agree on its fingerprint."""
        self.configure(processes=[["structure", "fsi-structure"]], structure={})
        code, _, _, _ = self.launch("--set", "a.b=1", "--resolution", "coarse", "--set", "c=[1, 2]", self.case)
        self.assertEqual(code, 0)
        self.assertEqual(self.recorded("structure")["argv"],
                         [self.case, "--resolution", "coarse", "--set", "a.b=1", "--set", "c=[1, 2]"])

    # coupled -----------------------------------------------------------------------------
    def coupled_with_precursor(self, **fluid):
        with open(os.path.join(self.out, "coupler.endpoint"), "w") as f:
            f.write("tcp://127.0.0.1:5555\n")
        self.configure(precursors=["fluid"], coupler={"endpoint": "tcp://127.0.0.1:5555"},
                       structure={}, fluid=dict(precursor_sleep=0.3, **fluid))

    def test_a_precursor_runs_to_its_end_before_the_coupled_processes_start(self):
        self.coupled_with_precursor()
        code, _, err, _ = self.launch("--end-time", "0.5", self.case)
        self.assertEqual(code, 0, err)
        precursor = self.recorded("fluid.precursor")
        self.assertEqual(precursor["argv"], [self.case, "--end-time", "0.5", "--precursor"])
        for name in ("coupler", "structure", "fluid"):
            self.assertGreater(self.recorded(name)["at"], precursor["at"] + 0.3, name)
        self.assertNotIn("--precursor", self.recorded("fluid")["argv"])
        self.assertIn("fluid: precursor run", err)

    def test_a_failed_precursor_stops_the_run_before_anything_else_starts(self):
        self.coupled_with_precursor(precursor_exit=1)
        code, _, err, _ = self.launch(self.case)
        self.assertEqual(code, 1)
        self.assertIn("the precursor run failed with exit code 1", err)
        self.assertNoTraceback(err)
        for name in ("coupler", "structure", "fluid"):
            self.assertIsNone(self.recorded(name), name)

    def test_coupled_starts_three_with_the_published_endpoint(self):
        with open(os.path.join(self.out, "coupler.endpoint"), "w") as f:
            f.write("tcp://127.0.0.1:1\n")  # stale, from an earlier run
        self.configure(
            coupler={"endpoint": ENDPOINT, "endpoint_delay": 0.3, "sleep": 0.3,
                     "lines": [["info", "step 10/100, ETA 3 s"]]},
            structure={"lines": [["info", "structure quiet line"], ["warning", "stretched a lot"]]},
            fluid={"lines": [["debug", "fluid debug line"], ["error", "fluid complains"]]})
        code, _, err, elapsed = self.launch(self.case)
        self.assertEqual(code, 0, err)
        coupler, structure, fluid = (self.recorded(n) for n in ("coupler", "structure", "fluid"))
        self.assertEqual(coupler["argv"], [self.case])
        self.assertEqual(structure["argv"], [self.case, "--coupled", "--endpoint", ENDPOINT])
        self.assertEqual(fluid["argv"], [self.case, "--endpoint", ENDPOINT])
        # console: the coupler in full, participants from warning up, prefixed
        self.assertIn("\n[21:10:00.123] [coupler] [info] step 10/100, ETA 3 s\n", "\n" + err)
        self.assertIn("[structure] [21:10:00.123] [structure] [warning] stretched a lot", err)
        self.assertIn("[fluid] [21:10:00.123] [fluid] [error] fluid complains", err)
        self.assertNotIn("structure quiet line", err)
        self.assertNotIn("fluid debug line", err)
        self.assertNotIn("exited with code", err)
        # nothing lost: every line in logs/<name>.console
        with open(os.path.join(self.out, "logs", "structure.console")) as f:
            self.assertIn("structure quiet line", f.read())
        with open(os.path.join(self.out, "logs", "fluid.console")) as f:
            self.assertIn("fluid debug line", f.read())
        with open(os.path.join(self.out, "logs", "coupler.console")) as f:
            self.assertIn("ETA 3 s", f.read())
        self.assertLess(elapsed, 5)

    def test_a_second_run_into_a_folder_being_written_is_refused_and_the_lock_released_after(self):
        self.configure(coupler={"endpoint": ENDPOINT, "sleep": 0.2}, structure={}, fluid={})
        import fcntl
        with open(os.path.join(self.out, ".fsi-run.lock"), "w") as held:
            fcntl.flock(held, fcntl.LOCK_EX)   # another run writes this folder
            code, _, err, _ = self.launch(self.case)
        self.assertNotEqual(code, 0)
        self.assertIn("%s is being written by another run" % os.path.realpath(self.out), err)
        self.assertIn("-o", err)
        self.assertNoTraceback(err)
        self.assertIsNone(self.recorded("coupler"))   # nothing started
        code, _, err, _ = self.launch(self.case)        # that run ended: this one runs
        self.assertEqual(code, 0, err)

    def test_coupled_verbose_shows_every_line_and_output_dir_is_passed(self):
        other = os.path.join(self.tmp.name, "results")
        os.makedirs(other)
        self.configure(coupler={"endpoint": ENDPOINT},
                       structure={"lines": [["info", "structure quiet line"]]},
                       fluid={"lines": [["debug", "fluid debug line"]]})
        code, _, err, _ = self.launch("-v", "-o", other, self.case)
        self.assertEqual(code, 0, err)
        self.assertIn("[structure] [21:10:00.123] [structure] [info] structure quiet line", err)
        self.assertIn("[fluid] [21:10:00.123] [fluid] [debug] fluid debug line", err)
        self.assertEqual(self.recorded("coupler")["argv"], [self.case, "-o", other])
        self.assertEqual(self.recorded("fluid")["argv"],
                         [self.case, "--endpoint", ENDPOINT, "-o", other])
        self.assertTrue(os.path.isfile(os.path.join(other, "logs", "coupler.console")))

    def test_failing_participant_stops_the_run_and_hanging_sibling_is_killed(self):
        self.configure(coupler={"endpoint": ENDPOINT, "sleep": 30},           # stops on SIGTERM
                       structure={"sleep": 30, "ignore_sigterm": True},       # needs SIGKILL
                       fluid={"sleep": 0.2, "exit": 1, "lines": [["error", "fluid solver diverged"]]})
        code, _, err, elapsed = self.launch(self.case)
        self.assertEqual(code, 1, err)
        self.assertIn("[fluid] [21:10:00.123] [fluid] [error] fluid solver diverged", err)
        self.assertIn("fsi: fluid exited with code 1 (log: %s)"
                      % os.path.join(self.out, "logs", "fluid.console"), err)
        self.assertIn("structure", err.split("fsi: fluid exited")[1])  # the straggler is named
        self.assertIn("SIGTERM", self.events("coupler"))
        self.assertIn("SIGTERM", self.events("structure"))
        for name in ("coupler", "structure"):
            self.assertFalse(self.alive(self.recorded(name)["pid"]), name)
        # 0.2 s run + 1 s grace + 0.5 s before SIGKILL, plus start-up
        self.assertLess(elapsed, 5)

    def test_exit_code_is_that_of_the_first_process_that_failed(self):
        with open(os.path.join(self.out, "structure.log"), "w") as f:
            f.write("written by the structure\n")
        # The coupler fails 0.5 s after the structure (within the launcher's 1 s grace), counted
        # from the structure's exit: from the fakes' starts, a loaded machine's start-up skew
        # (over 0.5 s with two MPI ranks beside the tests) reversed the order.
        self.configure(coupler={"endpoint": ENDPOINT, "sleep": 0.5, "exit": 1, "after_exit_of": "structure"},
                       structure={"sleep": 0.1, "exit": 3},
                       fluid={"sleep": 0.6})
        code, _, err, elapsed = self.launch(self.case)
        self.assertEqual(code, 3, err)
        self.assertIn("fsi: structure exited with code 3 (log: %s)"
                      % os.path.join(self.out, "structure.log"), err)
        self.assertIn("fsi: coupler exited with code 1", err)
        self.assertLess(err.index("structure exited"), err.index("coupler exited"))
        self.assertNotIn("fluid exited", err)
        self.assertLess(elapsed, 5)

    def test_sigint_to_the_launcher_reaches_every_child(self):
        self.configure(coupler={"endpoint": ENDPOINT, "sleep": 30},
                       structure={"sleep": 30}, fluid={"sleep": 30})
        p = self.start(self.case)
        self.wait_started(["coupler", "structure", "fluid"])
        time.sleep(0.2)  # let the fakes install their handlers
        began = time.monotonic()
        os.kill(p.pid, signal.SIGINT)  # the launcher alone, not its process group
        _, err = p.communicate(timeout=10)
        self.assertEqual(p.returncode, 130, err.decode())
        self.assertLess(time.monotonic() - began, 3)
        for name in ("coupler", "structure", "fluid"):
            self.assertIn("SIGINT", self.events(name), name)
            self.assertFalse(self.alive(self.recorded(name)["pid"]), name)
        self.assertNoTraceback(err.decode())

    def test_ctrl_c_waits_for_the_step_and_a_second_one_stops_at_once(self):
        # Our processes answer Ctrl-C by finishing the step and its checkpoint: the launcher
        # waits for them (FSI_INTERRUPT_GRACE_S, 65 s) and says so; a second Ctrl-C stops them.
        self.configure(coupler={"endpoint": ENDPOINT, "sleep": 30, "finish_step_s": 30},
                       structure={"sleep": 30, "finish_step_s": 30}, fluid={"sleep": 30, "finish_step_s": 30})
        p = self.start(self.case)
        self.wait_started(["coupler", "structure", "fluid"])
        time.sleep(0.2)
        os.kill(p.pid, signal.SIGINT)
        time.sleep(1.0)
        for name in ("coupler", "structure", "fluid"):
            self.assertIn("SIGINT", self.events(name), name)
            self.assertTrue(self.alive(self.recorded(name)["pid"]), name)
        self.assertIsNone(p.poll())
        began = time.monotonic()
        os.kill(p.pid, signal.SIGINT)
        _, err = p.communicate(timeout=10)
        self.assertEqual(p.returncode, 130, err.decode())
        self.assertLess(time.monotonic() - began, 3)
        self.assertIn("the run ends at the end of this step", err.decode())
        self.assertIn("interrupted again: stopping every process now", err.decode())
        for name in ("coupler", "structure", "fluid"):
            self.assertIn("SIGTERM", self.events(name), name)
        self.assertNoTraceback(err.decode())

    def test_sigterm_to_the_launcher_stops_everything(self):
        self.configure(coupler={"endpoint": ENDPOINT, "sleep": 30},
                       structure={"sleep": 30}, fluid={"sleep": 30})
        p = self.start(self.case)
        self.wait_started(["coupler", "structure", "fluid"])
        time.sleep(0.2)
        os.kill(p.pid, signal.SIGTERM)
        _, err = p.communicate(timeout=10)
        self.assertEqual(p.returncode, 130, err.decode())
        for name in ("coupler", "structure", "fluid"):
            self.assertIn("SIGTERM", self.events(name), name)

    def test_coupler_failing_before_its_endpoint_is_reported_with_its_output(self):
        self.configure(coupler={"exit": 2, "lines": [["error", "cannot bind tcp://10.0.0.1:5555"]]},
                       structure={}, fluid={})
        code, _, err, elapsed = self.launch(self.case)
        self.assertEqual(code, 2, err)
        self.assertIn("cannot bind tcp://10.0.0.1:5555", err)
        self.assertIn("  | [21:10:00.123] [coupler] [error] cannot bind", err)
        self.assertIn("fsi: coupler exited with code 2", err)
        self.assertIsNone(self.recorded("structure"))
        self.assertIsNone(self.recorded("fluid"))
        self.assertLess(elapsed, 5)

    def test_coupler_that_never_writes_its_endpoint_is_stopped(self):
        self.configure(coupler={"sleep": 30}, structure={}, fluid={})
        env = dict(self.env, FSI_ENDPOINT_TIMEOUT_S="0.5")
        code, _, err, elapsed = self.launch(self.case, env=env)
        self.assertEqual(code, 1, err)
        self.assertIn("coupler.endpoint within 0.5 s", err)
        self.assertIn("SIGTERM", self.events("coupler"))
        self.assertIsNone(self.recorded("structure"))
        self.assertLess(elapsed, 5)

    # --participant ----------------------------------------------------------------------
    def test_participant_starts_only_that_process(self):
        self.configure(coupler={"endpoint": ENDPOINT}, structure={}, fluid={"exit": 1})
        code, _, _, _ = self.launch("--participant", "fluid", self.case)
        self.assertEqual(code, 1)
        fluid = self.recorded("fluid")
        self.assertEqual(fluid["argv"], [self.case])  # reads coupling.endpoint from the case
        self.assertEqual(fluid["pid"], self.launcher.pid)  # in the foreground
        self.assertIsNone(self.recorded("coupler"))
        self.assertIsNone(self.recorded("structure"))

    def test_participant_structure_is_coupled_and_endpoint_passes_through(self):
        self.configure(coupler={}, structure={}, fluid={})
        code, _, _, _ = self.launch("--participant", "structure", "--endpoint",
                                    "tcp://node1:5555", self.case)
        self.assertEqual(code, 0)
        self.assertEqual(self.recorded("structure")["argv"],
                         [self.case, "--coupled", "--endpoint", "tcp://node1:5555"])
        self.assertIsNone(self.recorded("coupler"))

    def test_participant_coupler(self):
        self.configure(coupler={}, structure={}, fluid={})
        code, _, _, _ = self.launch("--participant", "coupler", "-o", self.out, self.case)
        self.assertEqual(code, 0)
        self.assertEqual(self.recorded("coupler")["argv"], [self.case, "-o", self.out])
        self.assertIsNone(self.recorded("structure"))

    def test_unknown_participant_lists_the_valid_ones(self):
        self.configure(coupler={}, structure={}, fluid={})
        code, _, err, _ = self.launch("--participant", "fluidd", self.case)
        self.assertEqual(code, 2)
        self.assertIn("unknown participant 'fluidd' (this case has: coupler, structure, fluid)", err)
        self.assertNoTraceback(err)

    # errors ------------------------------------------------------------------------------
    def test_bad_case_propagates_the_plan_message_and_exit_code(self):
        self.configure(plan_exit=2, plan_stderr="case.yaml: unknown key 'coupling.endpont' "
                                                "(did you mean 'endpoint'?)")
        code, out, err, _ = self.launch(self.case)
        self.assertEqual(code, 2)
        self.assertIn("unknown key 'coupling.endpont'", err)
        self.assertEqual(out, "")
        self.assertNoTraceback(err)
        self.assertIsNone(self.recorded("coupler"))

    def test_user_errors_are_one_line_without_traceback(self):
        self.configure(structure={})
        cases = [
            (["--bin-dir", "/nonexistent/bin", self.case], "build folder /nonexistent/bin not found"),
            ([os.path.join(self.tmp.name, "no-such-case")], "case folder"),
            (["--frobnicate", self.case], "unrecognized arguments: --frobnicate"),
            ([], "CASE_DIR"),
        ]
        for args, message in cases:
            code, _, err, _ = self.launch(*args)
            self.assertEqual(code, 2, args)
            self.assertIn(message, err, args)
            self.assertNoTraceback(err)
        os.remove(os.path.join(self.bin, "fsi-coupler"))
        code, _, err, _ = self.launch(self.case)
        self.assertEqual(code, 2)
        self.assertIn("fsi-coupler not found (build first: ./fsi build)", err)
        self.assertNoTraceback(err)

    def test_missing_participant_executable_is_reported_before_anything_starts(self):
        self.configure(coupler={"endpoint": ENDPOINT}, structure={}, fluid={})
        os.remove(os.path.join(self.bin, "fsi-prescribed-flow"))
        code, _, err, _ = self.launch(self.case)
        self.assertEqual(code, 2)
        self.assertIn("fsi-prescribed-flow not found", err)
        self.assertIsNone(self.recorded("coupler"))

    def test_print_output_dir(self):
        self.configure(structure={})
        code, out, _, _ = self.launch("--print-output-dir", self.case)
        self.assertEqual((code, out), (0, os.path.abspath(self.out) + "\n"))
        other = os.path.join(self.tmp.name, "x")
        code, out, _, _ = self.launch("--print-output-dir", "-o", other, self.case)
        self.assertEqual((code, out), (0, other + "\n"))


if __name__ == "__main__":
    unittest.main(verbosity=2)
