#!/usr/bin/python3
"""The ERCOFTAC pump's body-fitted reference (issue 31): the case's openfoam-ami-<resolution>
(cases/ercoftac-pump/make_case.py) copied to OUT/openfoam, meshed by gmsh with the rotor's 7
blades cut out behind an AMI (python/fsi/ercoftac_mesh.py, the same stator cells as the penalized
run's), run by stock pimpleFoam (serial or on MPI ranks) to the end time, and compared with the
measurement by the case's postprocess.py, as a penalized run is (OUT/impeller_outlet.yaml, .png).

    ercoftac_ami_run.py [--resolution coarse] [--end-time S] [--ranks N] [--restart] -o OUT CASE_DIR

The fields are written every revolution (the last two kept): --restart continues the run in OUT
from its latest ones (the same ranks) to the end time; the samples and forces of both parts join.

Progress with ETA on stderr; the tools' logs in OUT/logs/; OUT/cost.yaml: cells, wall seconds
per step and per revolution."""

import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys

import yaml

from fsi import ercoftac_mesh, ercoftac_pump, fsi_launch, pump_ami_run
from fsi.foam_case import foam_entry, set_foam_entry


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--resolution", default="coarse")
    parser.add_argument("--end-time", type=float, default=0.0, help="s (default: the folder's controlDict)")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--restart", action="store_true", help="continue the run in OUT from its latest fields")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("case_dir")
    args = parser.parse_args(argv)
    case_dir = os.path.abspath(args.case_dir)
    sys.path.insert(0, case_dir)
    import make_case  # the case's levels (its mesh sizes) and time steps
    if args.resolution not in make_case.LEVELS:
        raise SystemExit("ercoftac-ami: --resolution %s: one of %s" % (args.resolution, ", ".join(make_case.LEVELS)))
    source = os.path.join(case_dir, "openfoam-ami-" + args.resolution)
    out = os.path.abspath(args.output)
    foam, logs = os.path.join(out, "openfoam"), os.path.join(out, "logs")
    control = os.path.join(foam, "system", "controlDict")
    start = 0.0
    if args.restart:
        latest = pump_ami_run.latest_time(foam, args.ranks) if os.path.isdir(foam) else None
        decomposed = len(glob.glob(os.path.join(foam, "processor*")))
        if latest is None or float(latest) <= 0 or decomposed != (args.ranks if args.ranks > 1 else 0):
            raise SystemExit("ercoftac-ami: --restart: %s has no written fields after t = 0 on %d rank%s (it has %d "
                             "processor folders): run it first, or restart with the ranks it ran on"
                             % (foam, args.ranks, "s" if args.ranks > 1 else "", decomposed))
        start = float(latest)
        with open(os.path.join(logs, "log.checkMesh")) as f:
            cells = int(re.search(r"^\s+cells:\s+(\d+)", f.read(), re.M).group(1))
        set_foam_entry(control, "startFrom", "latestTime")
    else:
        if os.path.exists(foam):
            raise SystemExit("ercoftac-ami: %s exists: give another -o, or --restart to continue it" % foam)
        os.makedirs(logs)
        shutil.copytree(source, foam)
        h_near, h_far = make_case.LEVELS[args.resolution]
        cells = ercoftac_mesh.foam_mesh(foam, "ami", h_near, h_far, logs)
    if args.end_time > 0:
        set_foam_entry(control, "endTime", repr(args.end_time))
    end = float(foam_entry(control, "endTime"))
    dt = float(foam_entry(control, "deltaT"))
    if start >= end - 1e-9:
        raise SystemExit("ercoftac-ami: --restart: %s is already at t = %g s, not before the end time %g s"
                         % (foam, start, end))
    if args.ranks > 1 and not args.restart:
        pump_ami_run.decompose(foam, logs, args.ranks)
    exec_times, wall = pump_ami_run.run_pimple(foam, logs, end, dt, args.ranks, start)
    period = 2 * math.pi / ercoftac_pump.omega_rad_per_s()
    per_step = wall / max(len(exec_times), 1)
    with open(os.path.join(out, "cost.yaml"), "w") as f:
        yaml.safe_dump({"cells": cells, "ranks": args.ranks, "steps": len(exec_times), "wall_s": wall,
                        "wall_s_per_step": per_step, "wall_s_per_revolution": per_step * period / dt}, f,
                       sort_keys=False)
    made = subprocess.run([sys.executable, os.path.join(case_dir, "postprocess.py"), out, case_dir],
                          env=fsi_launch.case_script_env())
    return made.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
