#!/usr/bin/python3
"""./fsi submit: run cases on a cluster through SLURM (docs/cluster.md).

    fsi_submit.py --bin-dir BIN [--partition P] [--time T] [--fluid-nodes N] [--dry-run]
                  [--sbatch-arg ARG ...] CASE_DIR [CASE_DIR ...]

One coupled case: a heterogeneous job. Component 0 (one node) runs the coupler and the
structure, component 1 the fluid: its `fluid.openfoam.mpi_ranks` tasks on --fluid-nodes nodes
(default 1). The coupler listens on component 0's node address (NodeAddr from scontrol) at a
port taken from the job id, and each process is started as by `./fsi run --participant NAME
--endpoint E`. The processes cross the network: the case must use coupling.security: curve
(keys made here when missing) or say insecure_remote: true.

A structure-only case, or the flow alone: a job of one task running `./fsi run`.

Several cases (an ensemble's members): a job array, one task a case, each case run on one node
as `./fsi run` runs it.

Every job is requeueable: SLURM restarts a requeued job's script from the top
(../shared/docs/reliability-tests.md, fact 11), and the script then resumes from the newest
complete checkpoint of its output folder (--restart; set run.checkpoint_interval_s). The script
is written to <output>/slurm/job.sh (an array's beside its first case's folder, in
slurm-array/) and submitted with sbatch, unless --dry-run.
"""

import argparse
import os
import shlex
import subprocess
import sys

from fsi import ROOT
from fsi import fsi_launch  # noqa: E402
from fsi.fsi_launch import UserError, say  # noqa: E402

try:
    import yaml
except ImportError:  # Debian's python3-yaml
    yaml = None


def parse_args(argv):
    parser = argparse.ArgumentParser(prog="fsi submit", allow_abbrev=False,
                                     description="Submit cases to SLURM (docs/cluster.md)")
    parser.add_argument("--bin-dir", required=True)
    parser.add_argument("--partition", help="SLURM partition (default: the cluster's default)")
    parser.add_argument("--time", help="time limit of the job (SLURM format, e.g. 12:00:00)")
    parser.add_argument("--fluid-nodes", type=int, default=1,
                        help="nodes of the fluid's component (its MPI ranks spread over them; default 1)")
    parser.add_argument("--sbatch-arg", action="append", default=[], metavar="ARG",
                        help="one more #SBATCH line for every component (e.g. --account=proj), repeatable")
    parser.add_argument("--dry-run", action="store_true", help="write the script, do not submit it")
    parser.add_argument("cases", nargs="+", metavar="CASE_DIR")
    return parser.parse_args(argv)


def launcher_args(bin_dir, case):
    """What fsi_launch's plan and key helpers read of its command line, for one case."""
    return argparse.Namespace(bin_dir=bin_dir, case_dir=case, output_dir=None, resolution=None, end_time=None)


def plan_of(bin_dir, case):
    return fsi_launch.read_plan(launcher_args(bin_dir, case))


def case_yaml(case):
    if yaml is None:
        raise UserError("python3-yaml is needed to read %s/case.yaml" % case)
    with open(os.path.join(case, "case.yaml")) as f:
        return yaml.safe_load(f) or {}


def mpi_ranks(case):
    fluid = case_yaml(case).get("fluid") or {}
    return int((fluid.get("openfoam") or {}).get("mpi_ranks", 1))


def check_network_security(case, plan):
    coupling = case_yaml(case).get("coupling") or {}
    if plan.keys_dir is None and not coupling.get("insecure_remote", False):
        raise UserError("%s: on a cluster the coupler and its participants talk over the network; set "
                        "coupling.security: curve (docs/security.md), or insecure_remote: true on a network you "
                        "trust entirely" % os.path.join(case, "case.yaml"), fsi_launch.EXIT_BAD_INPUT)


def header(name, log, args, components):
    lines = ["#!/bin/bash", "#SBATCH --job-name=%s" % name, "#SBATCH --output=%s" % log,
             "#SBATCH --open-mode=append", "#SBATCH --requeue"]
    for i, component in enumerate(components):
        if i > 0:
            lines.append("#SBATCH hetjob")
        if args.partition:
            lines.append("#SBATCH --partition=%s" % args.partition)
        if args.time:
            lines.append("#SBATCH --time=%s" % args.time)
        lines.extend("#SBATCH %s" % a for a in args.sbatch_arg)
        lines.append("#SBATCH " + component)
    return lines


RESUME = """# A requeued job starts again from the top: resume from the newest complete checkpoint.
RESTART=()
if ls {out}/checkpoints/step-*/manifest.ckpt >/dev/null 2>&1; then RESTART=(--restart); fi
echo "fsi submit: job $SLURM_JOB_ID (restart count ${{SLURM_RESTART_COUNT:-0}}) ${{RESTART[*]:-from the start}}"
"""


def coupled_script(case, plan, args, bin_dir):
    out = plan.output_dir
    q = shlex.quote
    ranks = mpi_ranks(case)
    lines = header("fsi-" + os.path.basename(os.path.normpath(case)), os.path.join(out, "slurm", "slurm-%j.out"),
                   args, ["--nodes=1 --ntasks=2 --cpus-per-task=1",
                          "--nodes=%d --ntasks=%d" % (args.fluid_nodes, ranks)])
    launch = "/usr/bin/python3 %s --bin-dir %s -o %s" % (q(os.path.join(ROOT, "python", "fsi", "fsi_launch.py")), q(bin_dir),
                                                          q(out))
    lines += ["set -uo pipefail", "", RESUME.format(out=q(out)),
              "# The coupler listens on component 0's node, at a port of this job.",
              'HOST=$(scontrol show hostnames "$SLURM_JOB_NODELIST_HET_GROUP_0" | head -n1)',
              'ADDR=$(scontrol show node "$HOST" -o | sed -n "s/.* NodeAddr=\\([^ ]*\\).*/\\1/p")',
              'if ! [[ "$ADDR" =~ ^[0-9.]+$ ]]; then ADDR=$(getent ahostsv4 "$ADDR" | awk "NR==1 {print \\$1}"); fi',
              'ENDPOINT="tcp://$ADDR:$((20000 + SLURM_JOB_ID % 20000))"',
              'echo "fsi submit: coupler on $HOST at $ENDPOINT"', "",
              "pids=()"]
    for name, group in (("coupler", 0), ("structure", 0), ("fluid", 1)):
        lines.append('srun --het-group=%d --ntasks=1 --exact %s --participant %s --endpoint "$ENDPOINT" '
                     '"${RESTART[@]}" %s &' % (group, launch, name, q(case)))
        lines.append("pids+=($!)")
    lines += ["", "status=0", 'for pid in "${pids[@]}"; do wait "$pid" || status=$?; done', 'exit "$status"', ""]
    return "\n".join(lines)


def single_script(case, plan, args, bin_dir):
    out = plan.output_dir
    q = shlex.quote
    lines = header("fsi-" + os.path.basename(os.path.normpath(case)), os.path.join(out, "slurm", "slurm-%j.out"),
                   args, ["--nodes=1 --ntasks=1 --cpus-per-task=%d" % (2 if len(plan.processes) > 1 else 1)])
    lines += ["set -uo pipefail", "", RESUME.format(out=q(out)),
              '/usr/bin/python3 %s --bin-dir %s -o %s "${RESTART[@]}" %s' % (
                  q(os.path.join(ROOT, "python", "fsi", "fsi_launch.py")), q(bin_dir), q(out), q(case)), ""]
    return "\n".join(lines)


def array_script(cases, plans, args, bin_dir, folder):
    q = shlex.quote
    lines = header("fsi-ensemble", os.path.join(folder, "slurm-%A_%a.out"), args,
                   ["--nodes=1 --ntasks=1 --cpus-per-task=2"])
    lines.insert(2, "#SBATCH --array=0-%d" % (len(cases) - 1))
    lines += ["set -uo pipefail", "", "CASES=(%s)" % " ".join(q(c) for c in cases),
              "OUTS=(%s)" % " ".join(q(p.output_dir) for p in plans),
              'CASE=${CASES[$SLURM_ARRAY_TASK_ID]}', 'OUT=${OUTS[$SLURM_ARRAY_TASK_ID]}',
              RESUME.format(out='"$OUT"'),
              '/usr/bin/python3 %s --bin-dir %s -o "$OUT" "${RESTART[@]}" "$CASE"' % (
                  q(os.path.join(ROOT, "python", "fsi", "fsi_launch.py")), q(bin_dir)), ""]
    return "\n".join(lines)


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    os.chmod(path, 0o755)


def main(argv):
    args = parse_args(argv)
    bin_dir = os.path.abspath(args.bin_dir)
    if args.fluid_nodes < 1:
        raise UserError("--fluid-nodes must be at least 1, not %d" % args.fluid_nodes, fsi_launch.EXIT_BAD_INPUT)
    cases = [os.path.abspath(c) for c in args.cases]
    plans = [plan_of(bin_dir, c) for c in cases]
    if len(cases) == 1:
        case, plan = cases[0], plans[0]
        coupled = len(plan.processes) > 1
        if coupled:
            check_network_security(case, plan)
            fsi_launch.make_missing_keys(launcher_args(bin_dir, case), plan)
        script = os.path.join(plan.output_dir, "slurm", "job.sh")
        write(script, (coupled_script if coupled else single_script)(case, plan, args, bin_dir))
    else:
        for case, plan in zip(cases, plans):  # each member on one node, as ./fsi run: loopback
            fsi_launch.make_missing_keys(launcher_args(bin_dir, case), plan)
        folder = os.path.join(os.path.dirname(cases[0]), "slurm-array")
        script = os.path.join(folder, "job.sh")
        write(script, array_script(cases, plans, args, bin_dir, folder))
    if args.dry_run:
        say("batch script written: %s (not submitted: --dry-run)" % script)
        return 0
    try:
        made = subprocess.run(["sbatch", "--parsable", script], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True)
    except OSError as e:
        raise UserError("cannot run sbatch (%s): is this a SLURM login node? The script is %s" % (e.strerror, script))
    if made.returncode != 0:
        raise UserError("sbatch refused %s:\n%s" % (script, made.stdout.strip()))
    job = made.stdout.strip().split(";")[0]
    say("submitted job %s (script %s); follow it with: squeue -j %s" % (job, script, job))
    print(job)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except UserError as e:
        if str(e):
            say("error: %s" % e)
        sys.exit(e.code)
