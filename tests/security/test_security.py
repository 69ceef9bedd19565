#!/usr/bin/python3
"""Remote links that let no one in (docs/security.md), with the real executables over real
ZeroMQ sockets: a coupled run (coupler, structure, prescribed flow: the rag in the swirling flow)
with coupling.security: curve.

- Rogues (S2, S4, S5): during a run, processes outside it try to get in: no CURVE (plaintext),
  an unknown key, a wrong server key, an admitted key claiming another role, an oversized
  message part, a flood of 200,000 Hellos that never reads its replies. None gets a reply; the
  run completes and its results equal those of an unattacked run bit for bit; the coupler's
  memory stays bounded.
- FailClosed (S3): without the authentication handler (a fault hook), libzmq would admit any key;
  the coupler drops every unauthenticated message, so no one joins and the run stops.
- KeyFiles: fsi-coupler --make-keys (./fsi keys) makes owner-only secret files, keeps them on a
  second call, replaces them with --force; a secret file others may read, or a missing one, is
  refused naming the file and the fix.
- RemoteBinding: a non-loopback endpoint is refused without CURVE unless insecure_remote is set;
  with CURVE it binds; the retired allow_remote key says what replaced it.

FSI_BIN_DIR: the executables; FSI_ROGUE: fsi-rogue-client (both set by ctest)."""

import os
import re
import shutil
import stat
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
BIN_DIR = os.environ.get("FSI_BIN_DIR", os.path.join(ROOT, "build", "bin"))
COUPLER = os.path.join(BIN_DIR, "fsi-coupler")
ROGUE = os.environ.get("FSI_ROGUE", os.path.join(ROOT, "build", "tests", "security", "fsi-rogue-client"))
LAUNCH = os.path.join(ROOT, "python", "fsi", "fsi_launch.py")

try:
    from results_diff import differences
except ImportError as missing:  # Debian's python3-h5py, python3-numpy
    print("skipped: %s" % missing)
    sys.exit(77)


def make_case(folder, end_time_s=0.4, security="curve", extra=""):
    case = os.path.join(folder, "case")
    shutil.copytree(os.path.join(ROOT, "cases", "rag-in-prescribed-flow"), case,
                    ignore=shutil.ignore_patterns("output", "*.png", "*.gif", "keys"))
    path = os.path.join(case, "case.yaml")
    with open(path) as f:
        text = f.read()
    text = re.sub(r"end_time_s: [0-9.e-]+", "end_time_s: %g" % end_time_s, text, count=1)
    text = text.replace("  law: penalty\n", "  law: penalty\n  security: %s\n  handshake_timeout_s: 20\n%s"
                        % (security, extra), 1)
    with open(path, "w") as f:
        f.write(text)
    return case


def make_keys(case, *extra):
    return subprocess.run([COUPLER, "--make-keys", case] + list(extra), stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def launch(case, out, env=None):
    return subprocess.Popen([sys.executable, LAUNCH, "--bin-dir", BIN_DIR, "-o", out, case],
                            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, env=env)


def read(path):
    with open(path) as f:
        return f.read()


def rss_kib(pid):
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


def coupler_pid(out):
    found = subprocess.run(["pgrep", "-f", "fsi-coupler .*%s" % re.escape(out)], stdout=subprocess.PIPE, text=True)
    pids = [int(p) for p in found.stdout.split()]
    return pids[0] if pids else None


def run_watching(case, out, during=None):
    """Runs the case; calls during(endpoint) once the participants have joined. Returns the
    launcher's output and the coupler's largest resident memory (KiB)."""
    child = launch(case, out)
    peak, started, done = 0, False, None
    deadline = time.time() + 120
    while child.poll() is None and time.time() < deadline:
        pid = coupler_pid(out)
        if pid:
            peak = max(peak, rss_kib(pid))
        log = os.path.join(out, "coupler.log")
        if not started and during and os.path.exists(log) and "participants joined" in read(log):
            started = True
            done = during(read(os.path.join(out, "coupler.endpoint")).strip())
        time.sleep(0.05)
    output = child.communicate(timeout=60)[0]
    return child.returncode, output, peak, done


class Rogues(unittest.TestCase):
    ROGUES = [("plaintext", []), ("unknown-key", []), ("wrong-server-key", []), ("stolen-role", []),
              ("oversized", ["--bytes", str(64 << 20)]), ("flood", ["--messages", "200000"])]

    @classmethod
    def setUpClass(cls):
        for exe in (COUPLER, ROGUE):
            if not os.access(exe, os.X_OK):
                raise unittest.SkipTest("not built: %s" % exe)
        cls.tmp = tempfile.mkdtemp(prefix="fsi_security_")
        cls.case = make_case(cls.tmp, 0.6)
        made = make_keys(cls.case)
        assert made.returncode == 0, made.stdout
        cls.clean = os.path.join(cls.tmp, "clean")
        code, output, cls.clean_peak_kib, _ = run_watching(cls.case, cls.clean)
        assert code == 0, output[-3000:]

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_rogues_get_nowhere_and_the_run_is_unchanged(self):
        keys = os.path.join(self.case, "keys")

        def attack(endpoint):
            return [subprocess.Popen([ROGUE, endpoint, mode, keys, "--seconds", "4"] + extra,
                                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                    for mode, extra in self.ROGUES]

        out = os.path.join(self.tmp, "attacked")
        code, output, peak_kib, rogues = run_watching(self.case, out, attack)
        self.assertEqual(code, 0, output[-3000:])
        self.assertIsNotNone(rogues, "the run ended before the rogues could start")
        reports = {}
        for process in rogues:
            text = process.communicate(timeout=60)[0]
            fields = text.split()
            self.assertEqual(fields[0], "mode", text)
            reports[fields[1]] = dict(zip(fields[2::2], map(int, fields[3::2])))
        print("rogues:", reports)
        for mode, _ in self.ROGUES:
            self.assertEqual(reports[mode]["replies"], 0, (mode, reports[mode]))
        # Without an admitted key, or without the coupler's, the CURVE handshake itself fails.
        for mode in ("plaintext", "unknown-key", "wrong-server-key"):
            self.assertEqual(reports[mode]["accepted"], 0, (mode, reports[mode]))
        # The oversized part closes its connection (ZMQ_MAXMSGSIZE from the structure's size).
        self.assertGreaterEqual(reports["oversized"]["disconnected"], 1, reports["oversized"])
        with open(os.path.join(out, "coupler.log")) as f:
            log = f.read()
        self.assertIn("refused a connection from 127.0.0.1: its CURVE key", log)
        self.assertIn("ignored hello from fluid:flood, which came after the run started", log)
        self.assertLess(log.count("ignored"), 20, "the flood flooded the log")
        # Bounded queues: the flood leaves no trace in the coupler's memory beyond its queues.
        self.assertLess(peak_kib, self.clean_peak_kib + 64 * 1024, (peak_kib, self.clean_peak_kib))
        self.assertEqual(differences(self.clean, out, ("coupling.h5", "structure.h5")), [])


class FailClosed(unittest.TestCase):
    def test_without_the_authentication_handler_no_one_gets_in(self):
        tmp = tempfile.mkdtemp(prefix="fsi_security_closed_")
        self.addCleanup(shutil.rmtree, tmp, True)
        case = make_case(tmp, 0.05)
        with open(os.path.join(case, "case.yaml")) as f:
            text = f.read().replace("handshake_timeout_s: 20", "handshake_timeout_s: 3")
        with open(os.path.join(case, "case.yaml"), "w") as f:
            f.write(text)
        self.assertEqual(make_keys(case).returncode, 0)
        out = os.path.join(tmp, "out")
        child = launch(case, out, dict(os.environ, FSI_FAULT_NO_ZAP_HANDLER="1"))
        output = child.communicate(timeout=60)[0]
        self.assertNotEqual(child.returncode, 0, output[-3000:])
        with open(os.path.join(out, "coupler.log")) as f:
            log = f.read()
        self.assertIn("authentication handler is not started", log)
        self.assertIn("its connection is not authenticated (no CURVE identity)", log)
        self.assertIn("messages were dropped as not authenticated", log)
        self.assertNotIn("participants joined", log)


class KeyFiles(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="fsi_security_keys_")
        self.addCleanup(shutil.rmtree, self.tmp, True)
        self.case = make_case(self.tmp, 0.01)
        self.keys = os.path.join(self.case, "keys")

    def test_keys_are_owner_only_kept_and_replaced_on_request(self):
        made = make_keys(self.case)
        self.assertEqual(made.returncode, 0, made.stdout)
        self.assertIn("for: coupler, structure, fluid", made.stdout)
        self.assertEqual(stat.S_IMODE(os.stat(self.keys).st_mode), 0o700)
        for name in ("coupler", "structure", "fluid"):
            secret = os.path.join(self.keys, name + ".key_secret")
            self.assertEqual(stat.S_IMODE(os.stat(secret).st_mode), 0o600, secret)
            self.assertIn("secret-key", read(secret))
            self.assertNotIn("secret-key", read(os.path.join(self.keys, name + ".key")))
        before = read(os.path.join(self.keys, "fluid.key_secret"))
        again = make_keys(self.case)
        self.assertIn("already made", again.stdout)
        self.assertEqual(read(os.path.join(self.keys, "fluid.key_secret")), before)
        self.assertEqual(make_keys(self.case, "--force").returncode, 0)
        self.assertNotEqual(read(os.path.join(self.keys, "fluid.key_secret")), before)

    def test_a_secret_key_others_may_read_is_refused(self):
        self.assertEqual(make_keys(self.case).returncode, 0)
        secret = os.path.join(self.keys, "structure.key_secret")
        os.chmod(secret, 0o644)
        child = launch(self.case, os.path.join(self.tmp, "out"))
        output = child.communicate(timeout=60)[0]
        self.assertNotEqual(child.returncode, 0)
        self.assertIn(secret + " may be read by other users (mode 644)", output)
        self.assertIn("chmod 600", output)

    def test_missing_keys_say_how_to_make_them(self):
        # A process started on its own (one host of several) does not make keys: the hosts must
        # share one set.
        made = subprocess.run([sys.executable, LAUNCH, "--bin-dir", BIN_DIR, "--participant", "coupler", "-o",
                               os.path.join(self.tmp, "out"), self.case], stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        self.assertEqual(made.returncode, 2, made.stdout[-2000:])
        self.assertIn(os.path.join(self.keys, "coupler.key_secret"), made.stdout)
        self.assertIn("./fsi keys CASE", made.stdout)
        self.assertFalse(os.path.exists(self.keys))

    def test_a_run_on_one_host_makes_its_keys(self):
        child = launch(self.case, os.path.join(self.tmp, "out"))
        output = child.communicate(timeout=60)[0]
        self.assertEqual(child.returncode, 0, output[-2000:])
        self.assertIn("made CURVE keys in %s" % self.keys, output)
        self.assertEqual(stat.S_IMODE(os.stat(os.path.join(self.keys, "coupler.key_secret")).st_mode), 0o600)


class RemoteBinding(unittest.TestCase):
    def coupler(self, security, extra="", endpoint="tcp://0.0.0.0:0"):
        tmp = tempfile.mkdtemp(prefix="fsi_security_bind_")
        self.addCleanup(shutil.rmtree, tmp, True)
        case = make_case(tmp, 0.01, security, extra)
        with open(os.path.join(case, "case.yaml")) as f:
            text = f.read().replace("handshake_timeout_s: 20", "handshake_timeout_s: 1")
        with open(os.path.join(case, "case.yaml"), "w") as f:
            f.write(text)
        if security == "curve":
            make_keys(case)
        return subprocess.run([COUPLER, case, "-o", os.path.join(tmp, "out"), "--endpoint", endpoint],
                              stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=60)

    def test_plaintext_on_a_network_address_is_refused(self):
        made = self.coupler("none")
        self.assertEqual(made.returncode, 2, made.stdout)
        self.assertIn("refusing to bind tcp://0.0.0.0:0", made.stdout)
        self.assertIn("security: curve", made.stdout)
        self.assertIn("insecure_remote: true", made.stdout)

    def test_insecure_remote_or_curve_may_bind_it(self):
        for security, extra in (("none", "  insecure_remote: true\n"), ("curve", "")):
            made = self.coupler(security, extra)
            self.assertIn("coupler listening on tcp://0.0.0.0:", made.stdout, security)
            self.assertIn("CURVE: encrypted" if security == "curve" else "plaintext", made.stdout, security)

    def test_the_retired_allow_remote_says_what_replaced_it(self):
        made = self.coupler("none", "  allow_remote: true\n", "tcp://127.0.0.1:0")
        self.assertEqual(made.returncode, 2, made.stdout)
        self.assertIn("allow_remote", made.stdout)
        self.assertIn("was replaced: use security: curve", made.stdout)


if __name__ == "__main__":
    unittest.main()
