"""Shared helpers of the coupled-run tests (tests/coupled): where the executables and cases are,
how to read and write case files, how to start a run (through the launcher or process by
process) and how to read its results. Debian's /usr/bin/python3 with python3-h5py,
python3-numpy and python3-yaml.

The executables come from FSI_BIN_DIR (set by ctest; default <source>/build/bin). Every test
writes into its own temporary folder, never into cases/*/output, so tests can run in parallel.
"""

import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

try:
    import h5py
    import numpy as np
    import yaml
except ImportError as e:  # ctest reports exit code 77 as "skipped", with this line
    print("SKIP: %s (install python3-h5py, python3-numpy and python3-yaml)" % e)
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.abspath(os.path.join(HERE, "..", ".."))
BIN_DIR = os.environ.get("FSI_BIN_DIR", os.path.join(SOURCE_DIR, "build", "bin"))
LAUNCHER = os.path.join(SOURCE_DIR, "python", "fsi", "fsi_launch.py")
PYTHON = "/usr/bin/python3"
COUPLER = os.path.join(BIN_DIR, "fsi-coupler")
STRUCTURE = os.path.join(BIN_DIR, "fsi-structure")
FLUID = os.path.join(BIN_DIR, "fsi-prescribed-flow")
EPS = np.finfo(float).eps


def case_dir(name):
    return os.path.join(SOURCE_DIR, "cases", name)


# ---- case files ------------------------------------------------------------------------------

class _Loader(yaml.SafeLoader):
    """YAML 1.2 numbers: PyYAML (YAML 1.1) reads '3.2e4' as a string; yaml-cpp as a number."""


_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?$|^[-+]?\.(?:inf|Inf|INF)$"),
    list("-+0123456789."))


def load_case(path):
    """The case.yaml of a case folder (or the file itself) as nested dicts."""
    if os.path.isdir(path):
        path = os.path.join(path, "case.yaml")
    with open(path) as f:
        return yaml.load(f, Loader=_Loader)


def reference(name, preset):
    """The self-measured reference values of a case's preset (cases/<name>/reference.yaml, with
    their provenance): what the tests assert against and the docs quote."""
    return load_case(os.path.join(case_dir(name), "reference.yaml"))[preset]


def write_case(folder, case):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "case.yaml"), "w") as f:
        yaml.safe_dump(case, f, default_flow_style=None, sort_keys=False)
    return folder


def standalone(case):
    """The same scene without fluid and coupling: the structure solver alone."""
    case = dict(case)
    case.pop("fluid", None)
    case.pop("coupling", None)
    return case


# ---- results ---------------------------------------------------------------------------------

def status_of(h5_path):
    with h5py.File(h5_path, "r") as f:
        status = f.attrs["status"]
    return status.decode() if isinstance(status, bytes) else str(status)


class StructureResults:
    def __init__(self, out):
        with h5py.File(os.path.join(out, "structure.h5"), "r") as f:
            self.time_s = f["time_s"][:]
            self.structures = {}
            for name, g in f["structures"].items():
                self.structures[name] = {k: g[k][:] for k in g if isinstance(g[k], h5py.Dataset)}

    def energy(self, name):
        g = self.structures[name]
        return g["kinetic_energy_j"] + g["elastic_energy_j"] + g["potential_energy_j"]


# ---- runs ------------------------------------------------------------------------------------

class TempDirTest(unittest.TestCase):
    """Each test gets a fresh temporary folder, removed afterwards unless FSI_KEEP_TEST_DIRS=1."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="fsi-coupled-%s-" % self._testMethodName)
        self.processes = []

    def tearDown(self):
        for p in self.processes:  # only what this test started, by pid
            if p.poll() is None:
                p.kill()
                p.wait()
        if os.environ.get("FSI_KEEP_TEST_DIRS") != "1":
            shutil.rmtree(self.tmp, ignore_errors=True)
        else:
            print("kept", self.tmp)

    def launch(self, case, out, timeout=60, extra_env=None, extra_args=()):
        """./fsi run [EXTRA_ARGS] CASE -o OUT; returns (exit code, stderr text)."""
        env = dict(os.environ, **(extra_env or {}))
        result = subprocess.run([PYTHON, LAUNCHER, "--bin-dir", BIN_DIR, "-o", out] + list(extra_args) + [case],
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, timeout=timeout, env=env)
        return result.returncode, result.stderr.decode("utf-8", "replace")

    def assert_run_completed(self, out, code, stderr):
        """Every process completed: exit 0, both results files say so (the participants got
        the coupler's final Shutdown; see also CleanShutdown)."""
        self.assertEqual(code, 0, stderr[-3000:])
        self.assertEqual(status_of(os.path.join(out, "coupling.h5")), "completed", stderr[-3000:])
        self.assertEqual(status_of(os.path.join(out, "structure.h5")), "completed", stderr[-3000:])

    def start(self, command, log_name):
        log = open(os.path.join(self.tmp, log_name), "wb")
        p = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT)
        log.close()
        p.log_path = os.path.join(self.tmp, log_name)
        self.processes.append(p)
        return p

    def start_coupler(self, case, out):
        """fsi-coupler CASE -o OUT; returns (process, endpoint)."""
        endpoint_file = os.path.join(out, "coupler.endpoint")
        coupler = self.start([COUPLER, case, "-o", out], "coupler.console")
        deadline = time.monotonic() + 20
        while time.monotonic() < deadline:
            if os.path.exists(endpoint_file):
                with open(endpoint_file) as f:
                    endpoint = f.read().strip()
                if endpoint:
                    return coupler, endpoint
            self.assertIsNone(coupler.poll(), "the coupler exited: " + read(coupler.log_path))
            time.sleep(0.02)
        self.fail("the coupler wrote no coupler.endpoint within 20 s")

    def start_participant(self, which, case, out, endpoint):
        if which == "structure":
            return self.start([STRUCTURE, case, "--coupled", "--endpoint", endpoint, "-o", out],
                              "structure.console")
        return self.start([FLUID, case, "--endpoint", endpoint, "-o", out], "fluid.console")


def read(path):
    try:
        with open(path, "rb") as f:
            return f.read().decode("utf-8", "replace")
    except FileNotFoundError:
        return ""


def wait_for_text(path, pattern, timeout, process=None):
    """Waits until the file at path holds a match of the regex; returns the match."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        match = re.search(pattern, read(path))
        if match:
            return match
        if process is not None and process.poll() is not None:
            break
        time.sleep(0.02)
    return re.search(pattern, read(path))


def wait_exit(process, timeout):
    """Exit code, or None if still running after timeout seconds."""
    try:
        return process.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        return None


def children_of(pid):
    """Pids whose parent is pid (from /proc)."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                stat = f.read()
        except OSError:
            continue
        ppid = int(stat.rsplit(")", 1)[1].split()[1])
        if ppid == pid:
            found.append(int(entry))
    return found


def alive(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
        return state != "Z"
    except OSError:
        return False
