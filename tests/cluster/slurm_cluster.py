"""A real SLURM cluster of two nodes on this machine, for the tests of ./fsi submit: munged,
slurmctld and two slurmd (-N n1, -N n2, both on this host), in a temporary folder with ports
of their own, started by the test and stopped after it. Needs root and Debian's slurm-wlm and
munge."""

import os
import shutil
import socket
import subprocess
import time


def available():
    if os.geteuid() != 0:
        return "not root"
    for tool in ("munged", "slurmctld", "slurmd", "sbatch", "scontrol"):
        if not shutil.which(tool):
            return "%s not installed (Debian's slurm-wlm and munge)" % tool
    return None


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class SlurmCluster:
    def __init__(self, folder):
        self.folder = folder
        for sub in ("state", "spool/n1", "spool/n2", "log", "munge"):
            os.makedirs(os.path.join(folder, sub), exist_ok=True)
        key = os.path.join(folder, "munge", "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        self.munge_socket = os.path.join(folder, "munge", "munge.socket")
        self.conf = os.path.join(folder, "slurm.conf")
        host = socket.gethostname()
        ports = [free_port() for _ in range(3)]
        with open(self.conf, "w") as f:
            f.write("\n".join([
                "ClusterName=fsitest", "SlurmctldHost=%s" % host, "SlurmUser=root", "SlurmdUser=root",
                "AuthType=auth/munge", "AuthInfo=socket=%s" % self.munge_socket,
                "StateSaveLocation=%s/state" % folder, "SlurmdSpoolDir=%s/spool/%%n" % folder,
                "SlurmctldPidFile=%s/slurmctld.pid" % folder, "SlurmdPidFile=%s/slurmd-%%n.pid" % folder,
                "SlurmctldPort=%d" % ports[0], "SlurmctldLogFile=%s/log/slurmctld.log" % folder,
                "SlurmdLogFile=%s/log/slurmd-%%n.log" % folder, "ProctrackType=proctrack/linuxproc",
                "TaskPlugin=task/none", "SchedulerType=sched/backfill", "SelectType=select/cons_tres",
                "SelectTypeParameters=CR_Core", "ReturnToService=2", "MpiDefault=none",
                "SlurmdParameters=config_overrides", "JobRequeue=1", "SchedulerParameters=bf_interval=1",
                # Two nodes on this host (heterogeneous job components take distinct nodes).
                "NodeName=n1 NodeHostname=%s NodeAddr=127.0.0.1 Port=%d CPUs=4 State=UNKNOWN" % (host, ports[1]),
                "NodeName=n2 NodeHostname=%s NodeAddr=127.0.0.1 Port=%d CPUs=4 State=UNKNOWN" % (host, ports[2]),
                "PartitionName=fsi Nodes=n[1-2] Default=YES MaxTime=INFINITE State=UP OverSubscribe=YES", ""]))
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        self.daemons = []
        self.daemons.append(subprocess.Popen(
            ["munged", "-F", "--socket=" + self.munge_socket, "--key-file=" + key, "--force",
             "--pid-file=" + os.path.join(folder, "munge", "munged.pid"),
             "--log-file=" + os.path.join(folder, "log", "munged.log"),
             "--seed-file=" + os.path.join(folder, "munge", "munged.seed")],
            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT))
        self._wait_for(lambda: os.path.exists(self.munge_socket), "munged")
        self.daemons.append(subprocess.Popen(["slurmctld", "-D", "-c"], env=self.env,
                                             stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT))
        self._wait_for(lambda: self.scontrol("ping").returncode == 0, "slurmctld")
        for node in ("n1", "n2"):
            self.daemons.append(subprocess.Popen(["slurmd", "-D", "-N", node], env=self.env,
                                                 stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT))
        self._wait_for(lambda: self.run("sinfo", "-h", "-o", "%T").stdout.split() == ["idle"], "two idle nodes")

    def _wait_for(self, ready, what, limit_s=30):
        deadline = time.time() + limit_s
        while time.time() < deadline:
            if ready():
                return
            time.sleep(0.2)
        raise RuntimeError("%s did not start within %d s (logs in %s/log)" % (what, limit_s, self.folder))

    def run(self, *command):
        return subprocess.run(list(command), env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)

    def scontrol(self, *args):
        return self.run("scontrol", *args)

    def state(self, job):
        """The job's state (PENDING, RUNNING, COMPLETED, ...), or "" once gone from the controller."""
        shown = self.scontrol("show", "job", "-o", str(job))
        states = set(m.split("=", 1)[1] for m in shown.stdout.split() if m.startswith("JobState="))
        for state in ("RUNNING", "PENDING", "CONFIGURING", "COMPLETING", "REQUEUED"):
            if state in states:
                return state
        return sorted(states)[0] if states else ""

    def components(self, job):
        """The job ids of a heterogeneous job's components (the job itself otherwise)."""
        shown = self.scontrol("show", "job", "-o", str(job)).stdout.split()
        ids = [m.split("=", 1)[1] for m in shown if m.startswith("JobId=")]
        return ids or [str(job)]

    def wait_running(self, job, limit_s):
        """Waits until the job runs (waking the backfill scheduler as wait() does)."""
        deadline = time.time() + limit_s
        pending_since = time.time()
        while time.time() < deadline:
            state = self.state(job)
            if state == "RUNNING":
                return
            if state not in ("PENDING", "CONFIGURING"):
                raise AssertionError("job %s is %s, not running" % (job, state))
            if time.time() - pending_since > 5:
                self.scontrol("reconfigure")
                pending_since = time.time()
            time.sleep(0.2)
        raise AssertionError("job %s did not start within %d s" % (job, limit_s))

    def wait_no_steps(self, limit_s):
        """Waits until no job step runs on this host (no slurmstepd process: the cluster tests run
        one at a time, so every slurmstepd is this cluster's). A requeued job is PENDING again
        while its old steps still end; started again before they have, the old batch script's
        exit status reached the new run, which SLURM then marked FAILED (seen on CI)."""
        deadline = time.time() + limit_s
        while time.time() < deadline:
            if subprocess.run(["pgrep", "-x", "slurmstepd"], stdout=subprocess.DEVNULL).returncode != 0:
                return
            time.sleep(0.2)
        raise AssertionError("job steps still running after %d s: %s" % (
            limit_s, self.run("pgrep", "-a", "slurmstepd").stdout.strip()))

    def wait(self, job, limit_s):
        """Waits until the job (all its components) has ended; returns its final states. An idle
        test cluster's backfill scheduler (which alone starts heterogeneous jobs) runs only when
        something changes: a job pending for no reason is given a reconfigure to wake it."""
        deadline = time.time() + limit_s
        pending_since = None
        while time.time() < deadline:
            state = self.state(job)
            if state not in ("RUNNING", "PENDING", "CONFIGURING", "COMPLETING", "REQUEUED"):
                return state
            if state == "PENDING":
                pending_since = pending_since or time.time()
                if time.time() - pending_since > 5:
                    self.scontrol("reconfigure")
                    pending_since = time.time()
            else:
                pending_since = None
            time.sleep(0.5)
        raise AssertionError("job %s still %s after %d s" % (job, self.state(job), limit_s))

    def stop(self):
        # Jobs first, so that no step (slurmstepd and its processes) outlives the cluster.
        self.run("scancel", "--full", "--user=root")
        deadline = time.time() + 45
        while time.time() < deadline and self.run("squeue", "-h").stdout.strip():
            time.sleep(0.5)
        for daemon in reversed(self.daemons):
            daemon.terminate()
        for daemon in reversed(self.daemons):
            try:
                daemon.wait(15)
            except subprocess.TimeoutExpired:
                daemon.kill()
