#!/usr/bin/python3
"""fsi_launch.py: starts the processes of one case (the launcher behind `./fsi run`).

    fsi_launch.py --bin-dir DIR [-o DIR] [-v] CASE_DIR
    fsi_launch.py --bin-dir DIR --participant NAME [--endpoint E] [-o DIR] CASE_DIR
    fsi_launch.py --bin-dir DIR --print-output-dir [-o DIR] CASE_DIR

It asks `fsi-coupler --plan` which processes the scene needs.
- Structure only: runs `fsi-structure CASE_DIR [-o DIR] [-v]` in its place (exec).
- Coupled: starts the coupler, waits for it to write `<output>/coupler.endpoint`, then starts
  the participants with `--endpoint` set to it. The coupler's output is shown in full; the
  participants' lines only from warning level up (all of them with -v), prefixed with
  `[name]`. Everything each process prints is also kept in `<output>/logs/<name>.console`.
  SIGINT and SIGTERM received by the launcher are forwarded to every child still running.
  When a process fails, the others get 15 s to stop on their own, then SIGTERM, then SIGKILL
  5 s later. Exit code: 0 when all succeeded, else that of the first process that failed
  (130 when interrupted).
- --participant NAME: runs only that process of the plan (exec), for starting the processes by
  hand on several machines; participants then read `coupling.endpoint` from the case file
  unless --endpoint is given.

Exit codes: 0 success, 1 run failed, 2 bad input (bad case, unknown option, missing build),
130 interrupted. Python standard library only (Debian's /usr/bin/python3).

Environment (mostly for tests): FSI_ENDPOINT_TIMEOUT_S (default 30), FSI_STOP_GRACE_S
(default 15), FSI_INTERRUPT_GRACE_S (after Ctrl-C, default 65), FSI_KILL_GRACE_S (default 5).
"""

import argparse
import collections
import fcntl
import os
import re
import signal
import subprocess
import sys
import threading
import time

from fsi import foam_case  # scripts/: this script's own folder

EXIT_OK, EXIT_RUN_FAILED, EXIT_BAD_INPUT, EXIT_INTERRUPTED = 0, 1, 2, 130
POLL_S = 0.05
SHOWN_LEVELS = {"warning", "warn", "error", "err", "critical"}
ANSI = re.compile(rb"\x1b\[[0-9;]*[A-Za-z]")
SPDLOG_LEVEL = re.compile(rb"^\[[^\]]*\] \[[^\]]*\] \[([A-Za-z]+)\]")
PRINT_LOCK = threading.Lock()  # one line at a time on the console, from every thread


class UserError(Exception):
    """An error the user can fix: printed as one line, no traceback."""

    def __init__(self, message, code=EXIT_BAD_INPUT):
        super().__init__(message)
        self.code = code


def speaker(prefix):
    """say(message) for a command: "PREFIX: message" on standard error, a whole line at a time
    from every thread (the study commands run members on threads)."""
    def say(message):
        with PRINT_LOCK:
            sys.stderr.write("%s: %s\n" % (prefix, message))
            sys.stderr.flush()
    return say


say = speaker("fsi")


def env_seconds(name, default):
    value = os.environ.get(name)
    if not value:
        return default
    try:
        seconds = float(value)
    except ValueError:
        raise UserError("%s must be a number of seconds, not '%s'" % (name, value))
    if seconds < 0:
        raise UserError("%s must not be negative" % name)
    return seconds


class ArgumentParser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        raise UserError(message)


def parse_args(argv):
    parser = ArgumentParser(
        prog="fsi run", allow_abbrev=False,
        description="Run a case: the structure solver alone, or the coupler and its participants.")
    parser.add_argument("--bin-dir", required=True, help="folder holding the fsi-* executables")
    parser.add_argument("-o", "--output-dir", help="results folder (overrides run.output_directory)")
    parser.add_argument("--participant", metavar="NAME",
                        help="start only this process of the case (coupler, structure, fluid), "
                             "to start them by hand on several machines")
    parser.add_argument("--endpoint", metavar="E",
                        help="endpoint to bind (coupler) or connect to (participants); "
                             "default: the case file's coupling.endpoint")
    parser.add_argument("--resolution", "--preset", metavar="NAME", dest="resolution",
                        help="preset of the case (presets/NAME.yaml over case.yaml): coarse, medium, fine...")
    parser.add_argument("--end-time", metavar="SECONDS", type=float, dest="end_time",
                        help="stop at this simulated time instead of run.end_time_s (a quick look)")
    parser.add_argument("--set", metavar="KEY=VALUE", dest="assignments", action="append", default=[],
                        help="set a key of the case over case.yaml and the preset, in every process "
                             "(e.g. fluid.openfoam.operating_point.flow_rate_m3_per_s=0.0076; repeatable)")
    parser.add_argument("--restart", action="store_true",
                        help="resume from the newest complete checkpoint in the results folder "
                             "(run.checkpoint_interval_s), appending to its results")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="show every line of every process (structure only: debug logging)")
    parser.add_argument("--print-output-dir", action="store_true",
                        help="print the case's results folder and exit")
    parser.add_argument("--print-case-dir", action="store_true",
                        help="print the case folder as given and exit (./fsi run: wherever it stands among the options)")
    parser.add_argument("case_dir", metavar="CASE_DIR", help="case folder holding case.yaml")
    return parser.parse_args(argv)


# ---------------------------------------------------------------------------------------------
# The plan

class Plan:
    def __init__(self, output_dir, processes, precursors=(), keys_dir=None):
        self.output_dir = output_dir
        self.keys_dir = keys_dir  # coupling.security: curve: where the keys are
        self.processes = processes  # [(name, executable path)] in the coupler's order
        self.precursors = list(precursors)  # participants with a run of their own to do first

    def names(self):
        return [name for name, _ in self.processes]

    def executable(self, name):
        return dict(self.processes)[name]


def executable_in(bin_dir, name):
    path = name if os.path.isabs(name) else os.path.join(bin_dir, name)
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        raise UserError("executable %s not found (build first: ./fsi build)" % path)
    return path


def output_args(args):
    """Options every process gets: the output folder, the case preset, the keys set and the end
    time, if given."""
    extra = ["-o", args.output_dir] if args.output_dir else []
    extra += ["--resolution", args.resolution] if args.resolution else []
    for assignment in getattr(args, "assignments", None) or []:
        extra += ["--set", assignment]
    extra += ["--restart"] if getattr(args, "restart", False) else []
    return extra + (["--end-time", repr(args.end_time)] if args.end_time else [])


def case_script_env():
    """The environment for a case's own scripts (prepare.py, postprocess.py): this package's
    folder on PYTHONPATH (as ./fsi sets it), so that they import it also from a copy of the case
    elsewhere (a pump-curve point, a case copied away from the repository), and also when this
    launcher was started without ./fsi."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                                      env.get("PYTHONPATH")]))
    return env


def prepare_case(case_dir, bin_dir, resolution=None):
    """A case's generated inputs: cases/<case>/prepare.py CASE_DIR BIN_DIR, when the case has one
    (the centrifugal pump generates its geometry from pump.yaml). Quiet when there is nothing to do.
    The preset to be run, if any, is in its environment as FSI_RESOLUTION (a case that meshes
    per level meshes that one only)."""
    script = os.path.join(case_dir, "prepare.py")
    if not os.path.isfile(script):
        return
    env = case_script_env()
    env["FSI_RESOLUTION"] = resolution or ""
    made = subprocess.run([sys.executable, script, case_dir, bin_dir], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, env=env)
    text = made.stdout.decode(errors="replace").strip()
    if made.returncode != 0:
        raise UserError("preparing the case failed (%s):\n%s" % (script, text), EXIT_RUN_FAILED)
    if text:
        say(text)


def read_plan(args):
    coupler = executable_in(args.bin_dir, "fsi-coupler")
    command = [coupler, "--plan", args.case_dir] + output_args(args)
    try:
        result = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE)
    except OSError as e:
        raise UserError("cannot run %s: %s" % (coupler, e.strerror))
    if result.returncode != 0:
        sys.stderr.buffer.write(result.stderr)
        sys.stderr.flush()
        code = result.returncode if result.returncode > 0 else 128 - result.returncode
        raise UserError("", code)  # the coupler has said why
    output_dir, processes, precursors, keys_dir = None, [], [], None
    for line in result.stdout.decode("utf-8", "replace").splitlines():
        words = line.split(None, 2) if line.strip() else []
        if not words:
            continue
        if words[0] == "output" and len(words) >= 2:
            output_dir = line.split(None, 1)[1].strip()
        elif words[0] == "process":
            if len(words) != 3:
                raise UserError("unexpected line from '%s --plan': %s" % (coupler, line),
                                EXIT_RUN_FAILED)
            processes.append((words[1], executable_in(args.bin_dir, words[2].strip())))
        elif words[0] == "precursor" and len(words) >= 2:
            precursors.append(words[1])
        elif words[0] == "keys" and len(words) >= 2:
            keys_dir = line.split(None, 1)[1].strip()
        # other lines are for other readers: ignored
    if output_dir is None or not processes:
        raise UserError("'%s --plan' named no output folder or no process" % coupler, EXIT_RUN_FAILED)
    return Plan(output_dir, processes, precursors, keys_dir)


def make_missing_keys(args, plan):
    """A run with CURVE whose processes all start here: its keys are made if there are none
    (a run over several hosts needs the same keys on each, so there they are made by hand:
    ./fsi keys CASE, docs/security.md)."""
    if plan.keys_dir is None or os.path.exists(os.path.join(plan.keys_dir, "coupler.key_secret")):
        return
    made = subprocess.run([executable_in(args.bin_dir, "fsi-coupler"), "--make-keys", args.case_dir],
                          stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    text = made.stdout.decode("utf-8", "replace")
    if made.returncode != 0:
        raise UserError("making the CURVE keys failed:\n" + text, made.returncode)
    say(text.splitlines()[0] if text else "made CURVE keys in " + plan.keys_dir)


def run_precursors(args, plan):
    """A participant's precursor (the OpenFOAM flow alone with its rigid bodies, section 3.2)
    runs to completion before the coupled processes start, so that the coupler's handshake does
    not wait for it. The participant skips it when its earlier result is still valid."""
    for name in plan.precursors:
        command = command_for(name, plan.executable(name), args, None, coupled=True) + ["--precursor"]
        if args.verbose:
            command.append("-v")
        say("%s: precursor run (%s)" % (name, " ".join(command[1:])))
        # Its own progress lines (stderr) show; the solver's residuals (stdout) go to a log.
        folder = os.path.join(plan.output_dir, "precursor")
        os.makedirs(folder, exist_ok=True)
        console_path = os.path.join(folder, "%s.console" % name)
        if os.path.lexists(console_path):  # a new file, not the one a hard-linked copy shares
            os.remove(console_path)
        with open(console_path, "wb") as console:
            code = subprocess.call(command, stdin=subprocess.DEVNULL,
                                   stdout=None if args.verbose else console)
        if code != 0:
            if code < 0:
                code = 128 - code
            raise UserError("%s: the precursor run failed with exit code %d (log: %s)"
                            % (name, code, os.path.join(plan.output_dir, "precursor", "%s.log" % name)),
                            code if code in (EXIT_BAD_INPUT, EXIT_INTERRUPTED) else EXIT_RUN_FAILED)


RUN_LOCK = ".fsi-run.lock"   # in an output folder while a run writes it
HELD_LOCKS = []              # the run's lock, held until the launcher exits


def lock_output(output_dir):
    """One run at a time in an output folder: two runs into one (a second `./fsi run -o` of the
    same folder, a study member started twice, a SLURM task beside a local run) would write over
    each other's checkpoints and results. Refused naming the folder; released when this launcher
    exits, however it ends."""
    os.makedirs(output_dir, exist_ok=True)
    path = os.path.join(output_dir, RUN_LOCK)
    lock = open(path, "w")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        lock.close()
        raise UserError("%s is being written by another run (it holds %s): wait for it to end, or give "
                        "another output folder (-o)" % (os.path.realpath(output_dir), path))
    HELD_LOCKS.append(lock)


def run_flow_alone(command, output_dir, verbose, restart=False):
    """A case without structures: the OpenFOAM flow alone with its rigid bodies (a pump's
    operating point). Its progress lines (stderr) show; the solver's residuals (stdout) go to
    <output>/logs/fluid.console unless -v (continued by a restart). Ctrl-C or SIGTERM reaches the
    fluid, which finishes its step and checkpoints it when the case has checkpoints: the launcher
    waits for it (FSI_INTERRUPT_GRACE_S, default 65 s); a second signal stops it at once."""
    os.makedirs(os.path.join(output_dir, "logs"), exist_ok=True)
    console_path = os.path.join(output_dir, "logs", "fluid.console")
    grace_s = env_seconds("FSI_INTERRUPT_GRACE_S", 65.0)
    signals = []
    with open(console_path, "ab" if restart else "wb") as console:
        child = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=None if verbose else console)

        def on_signal(signum, _frame):
            signals.append(signum)
            if len(signals) == 1:
                child.send_signal(signum)   # a terminal's Ctrl-C reached it already: a flag set twice
            else:
                child.kill()

        previous = {s: signal.signal(s, on_signal) for s in (signal.SIGINT, signal.SIGTERM)}
        try:
            signalled_at = None
            while True:
                try:
                    code = child.wait(timeout=0.5)
                    break
                except subprocess.TimeoutExpired:
                    if signals and signalled_at is None:
                        signalled_at = time.monotonic()
                    if signalled_at is not None and time.monotonic() - signalled_at > grace_s:
                        say("the fluid did not stop within %g s of the signal (FSI_INTERRUPT_GRACE_S): killed"
                            % grace_s)
                        child.kill()
                        signalled_at = float("inf")
        finally:
            for s, handler in previous.items():
                signal.signal(s, handler)
    if code < 0:
        code = 128 - code
    if signals and code == EXIT_INTERRUPTED:
        say("interrupted: the fluid stopped at a step boundary (with a checkpoint when run.checkpoint_interval_s "
            "is set: ./fsi run --restart resumes)")
    elif code not in (EXIT_OK, EXIT_BAD_INPUT, EXIT_INTERRUPTED):
        say("the fluid stopped with exit code %d (logs: %s, %s)"
            % (code, os.path.join(output_dir, "fluid.log"), console_path))
    return code


def command_for(name, executable, args, endpoint, coupled):
    """The command line of one process. endpoint: None to let it read the case file."""
    command = [executable, args.case_dir]
    if not coupled:  # structure only, exactly as before the coupler existed
        return command + output_args(args) + (["-v"] if args.verbose else [])
    if name == "structure":
        command.append("--coupled")
    if endpoint:
        command += ["--endpoint", endpoint]
    return command + output_args(args)


# ---------------------------------------------------------------------------------------------
# Coupled run: children, their output, signals

class Child:
    def __init__(self, name, command, output_dir, show_all):
        self.name = name
        self.command = command
        self.show_all = show_all
        # The coupler's lines carry the run's progress and are shown as they are.
        self.prefix = b"" if name == "coupler" else ("[%s] " % name).encode()
        self.log_path = os.path.join(output_dir, name + ".log")
        self.console_path = os.path.join(output_dir, "logs", name + ".console")
        self.tail = collections.deque(maxlen=10)
        self.code = None          # exit code once it has exited (128 + n for signal n)
        self.exit_time = None
        self.stopped_by_launcher = False
        self.process = None
        self.reader = None
        self.waiter = None

    def start(self):
        console = open(self.console_path, "wb")
        try:
            self.process = subprocess.Popen(self.command, stdin=subprocess.DEVNULL,
                                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        except OSError as e:
            console.close()
            raise UserError("cannot start %s: %s" % (self.command[0], e.strerror), EXIT_RUN_FAILED)
        self.reader = threading.Thread(target=self._read, args=(console,), daemon=True)
        self.reader.start()
        self.waiter = threading.Thread(target=self._wait, daemon=True)
        self.waiter.start()

    def running(self):
        return self.process is not None and self.code is None

    def signal(self, signum):
        if self.running():
            try:
                self.process.send_signal(signum)
            except OSError:
                pass

    def log_hint(self):
        return self.log_path if os.path.exists(self.log_path) else self.console_path

    def _wait(self):
        code = self.process.wait()
        self.exit_time = time.monotonic()  # exact order of the exits, for "the first that failed"
        self.code = code if code >= 0 else 128 - code

    def _read(self, console):
        visible = True  # lines before the first spdlog line (plain stderr) are shown
        with console:
            for raw in iter(self.process.stdout.readline, b""):
                console.write(raw)
                console.flush()
                line = raw.rstrip(b"\r\n")
                self.tail.append(line)
                match = SPDLOG_LEVEL.match(ANSI.sub(b"", line))
                if match:  # continuation lines of a message keep its visibility
                    visible = match.group(1).decode().lower() in SHOWN_LEVELS
                if self.show_all or visible:
                    with PRINT_LOCK:
                        sys.stderr.buffer.write(self.prefix + line + b"\n")
                        sys.stderr.flush()
        self.process.stdout.close()


class CoupledRun:
    def __init__(self, args, plan):
        self.args = args
        self.plan = plan
        self.children = []
        self.interrupted = None  # the signal received, if any
        self.signals = 0         # how many: a second one stops every process at once
        self.endpoint_timed_out = False
        self.endpoint_timeout_s = env_seconds("FSI_ENDPOINT_TIMEOUT_S", 30.0)
        self.stop_grace_s = env_seconds("FSI_STOP_GRACE_S", 15.0)
        self.kill_grace_s = env_seconds("FSI_KILL_GRACE_S", 5.0)
        # After Ctrl-C the coupler finishes the step and checkpoints it (at most 60 s).
        self.interrupt_grace_s = env_seconds("FSI_INTERRUPT_GRACE_S", 65.0)

    def _on_signal(self, signum, _frame):
        # No printing here: the main thread may hold PRINT_LOCK (_wait_all says it).
        self.interrupted = signum
        self.signals += 1
        for child in self.children:
            child.signal(signum)

    def _start(self, name, endpoint):
        command = command_for(name, self.plan.executable(name), self.args, endpoint, coupled=True)
        # The coupler's lines are all shown; a participant's from warning level up (-v: all).
        child = Child(name, command, self.plan.output_dir,
                      show_all=(name == "coupler" or self.args.verbose))
        self.children.append(child)
        child.start()
        if self.interrupted:  # the signal came while it was being started
            child.signal(self.interrupted)
        return child

    def run(self):
        out = self.plan.output_dir
        try:
            os.makedirs(os.path.join(out, "logs"), exist_ok=True)
        except OSError as e:
            raise UserError("cannot create %s: %s" % (os.path.join(out, "logs"), e.strerror))
        endpoint_file = os.path.join(out, "coupler.endpoint")
        try:
            os.remove(endpoint_file)
        except FileNotFoundError:
            pass
        except OSError as e:
            raise UserError("cannot remove the stale %s: %s" % (endpoint_file, e.strerror))

        previous = {s: signal.signal(s, self._on_signal) for s in (signal.SIGINT, signal.SIGTERM)}
        try:
            coupler = self._start("coupler", self.args.endpoint)
            endpoint = self._wait_for_endpoint(coupler, endpoint_file)
            if endpoint is not None:
                for name in self.plan.names():
                    if name != "coupler" and not self.interrupted:
                        self._start(name, endpoint)
            self._wait_all()
        finally:
            for s, handler in previous.items():
                signal.signal(s, handler)
        for child in self.children:
            child.reader.join(timeout=2.0)
        return self._report(endpoint_file)

    def _wait_for_endpoint(self, coupler, endpoint_file):
        deadline = time.monotonic() + self.endpoint_timeout_s
        while True:
            try:
                with open(endpoint_file) as f:
                    endpoint = f.read().strip()
                if endpoint:
                    return endpoint
            except FileNotFoundError:
                pass
            if not coupler.running() or self.interrupted:
                return None
            if time.monotonic() >= deadline:
                self.endpoint_timed_out = True
                say("the coupler wrote no %s within %g s; stopping it"
                    % (endpoint_file, self.endpoint_timeout_s))
                self._stop(self.children)
                return None
            time.sleep(POLL_S)

    def _stop(self, children):
        """SIGTERM, then SIGKILL after kill_grace_s, for those still running."""
        stragglers = [c for c in children if c.running()]
        for child in stragglers:
            child.stopped_by_launcher = True
            child.signal(signal.SIGTERM)
        deadline = time.monotonic() + self.kill_grace_s
        while any(c.running() for c in stragglers) and time.monotonic() < deadline:
            time.sleep(POLL_S)
        for child in stragglers:
            if child.running():
                say("%s did not stop after SIGTERM; killing it" % child.name)
                child.signal(signal.SIGKILL)
        for child in stragglers:
            child.waiter.join()

    def _wait_all(self):
        grace_start = None
        said = 0
        while any(c.running() for c in self.children):
            if self.signals > said:
                said = self.signals
                if said == 1:
                    say("interrupted: the run ends at the end of this step, with its checkpoint when the case "
                        "checkpoints (Ctrl-C again to stop at once)")
                else:
                    say("interrupted again: stopping every process now")
                    self._stop(self.children)
                    break
            if grace_start is None:
                ended = [c for c in self.children if not c.running()]
                if self.interrupted or any(c.code != 0 or c.name == "coupler" for c in ended):
                    grace_start = time.monotonic()  # the others should now stop on their own
            elif time.monotonic() - grace_start >= (self.interrupt_grace_s if self.interrupted
                                                    else self.stop_grace_s):
                names = ", ".join(c.name for c in self.children if c.running())
                say("still running %g s after the %s: %s; stopping"
                    % (self.interrupt_grace_s if self.interrupted else self.stop_grace_s,
                       "interruption" if self.interrupted else "run ended", names))
                self._stop(self.children)
                break
            time.sleep(POLL_S)
        for child in self.children:
            child.waiter.join()

    def _report(self, endpoint_file):
        coupler = self.children[0]
        if len(self.children) == 1 and not self.interrupted:
            # The coupler stopped (or hung) before it wrote its endpoint.
            if not self.endpoint_timed_out:
                say("the coupler stopped before it wrote %s; last lines of its output:" % endpoint_file)
                with PRINT_LOCK:
                    for line in coupler.tail:
                        sys.stderr.buffer.write(b"  | " + line + b"\n")
                    sys.stderr.flush()
            note = " after fsi stopped it" if coupler.stopped_by_launcher else ""
            say("coupler exited with code %d%s (log: %s)" % (coupler.code, note, coupler.log_hint()))
            if self.endpoint_timed_out or coupler.code == EXIT_OK:
                return EXIT_RUN_FAILED
            return coupler.code

        failed = sorted((c for c in self.children if c.code != 0), key=lambda c: c.exit_time)
        if not self.interrupted and failed and all(c.code == EXIT_INTERRUPTED for c in failed):
            # A signal at one process (a kill, a scheduler's): the coupler ended the run for all.
            say("interrupted by a signal at one process; results so far are in %s" % self.plan.output_dir)
            return EXIT_INTERRUPTED
        if self.interrupted:
            if not failed:
                return EXIT_OK
            say("interrupted; results so far are in %s" % self.plan.output_dir)
        for child in failed:
            if self.interrupted and child.code == EXIT_INTERRUPTED:
                continue
            note = " after fsi stopped it" if child.stopped_by_launcher else ""
            say("%s exited with code %d%s (log: %s)" % (child.name, child.code, note, child.log_hint()))
        if self.interrupted:
            return EXIT_INTERRUPTED
        return failed[0].code if failed else EXIT_OK


# ---------------------------------------------------------------------------------------------

def exec_process(command):
    sys.stdout.flush()
    sys.stderr.flush()
    try:
        os.execv(command[0], command)
    except OSError as e:
        raise UserError("cannot run %s: %s" % (command[0], e.strerror), EXIT_RUN_FAILED)


# Debian's OpenFOAM reads its etc/ through WM_PROJECT_DIR while its libraries load, before
# main(): the fluid process must be started with it set (foam_case.py, which starts OpenFOAM's
# tools too, holds it).
OPENFOAM_ENVIRONMENT = foam_case.OPENFOAM_ENVIRONMENT
# The allocator settings our executables set for themselves (common/Allocator.hpp), for stock OpenFOAM
# programs started by our scripts (the AMI reference, the benches' stock runs): freed blocks kept in the
# heap instead of page-faulted in again every step (about 2x on a 296k-cell step of this machine). The
# values of common/Allocator.cpp: 32 MiB and 256 MiB.
ALLOCATOR_TUNABLES = {"GLIBC_TUNABLES": "glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=268435456"}


def main(argv):
    for name, value in OPENFOAM_ENVIRONMENT.items():
        os.environ.setdefault(name, value)
    args = parse_args(argv)
    if args.print_case_dir:
        print(args.case_dir)
        return EXIT_OK
    if not os.path.isdir(args.bin_dir):
        raise UserError("build folder %s not found (build first: ./fsi build)" % args.bin_dir)
    if not os.path.isdir(args.case_dir):
        raise UserError("case folder %s not found" % args.case_dir)
    if not args.print_output_dir:
        prepare_case(args.case_dir, args.bin_dir, args.resolution)
    plan = read_plan(args)
    if args.print_output_dir:
        print(plan.output_dir)
        return EXIT_OK
    coupled = "coupler" in plan.names()

    if args.endpoint and not coupled:
        raise UserError("--endpoint applies only to coupled scenes (this case runs %s alone)"
                        % ", ".join(plan.names()))
    if args.participant is not None:
        if args.participant not in plan.names():
            raise UserError("unknown participant '%s' (this case has: %s)"
                            % (args.participant, ", ".join(plan.names())))
        name = args.participant
        run_precursors(args, Plan(plan.output_dir, plan.processes, [n for n in plan.precursors if n == name]))
        exec_process(command_for(name, plan.executable(name), args, args.endpoint, coupled))

    if not coupled:
        name = plan.names()[0]
        command = command_for(name, plan.executable(name), args, None, coupled=False)
        if name == "fluid":
            lock_output(plan.output_dir)
            return run_flow_alone(command, plan.output_dir, args.verbose, args.restart)
        exec_process(command)

    lock_output(plan.output_dir)
    make_missing_keys(args, plan)
    run_precursors(args, plan)
    return CoupledRun(args, plan).run()


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except UserError as e:
        if str(e):
            say("error: %s" % e)
        sys.exit(e.code)
    except KeyboardInterrupt:
        say("interrupted")
        sys.exit(EXIT_INTERRUPTED)
