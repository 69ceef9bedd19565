#!/usr/bin/python3
"""The body-fitted sliding-mesh (AMI) reference of a pump point, run by stock pimpleFoam (serial or on MPI ranks):
the case folder that cases/centrifugal-pump/make_ami_case.py wrote (openfoam-ami-<resolution>),
copied to OUT/openfoam with the flow rate set, meshed (blockMesh, snappyHexMesh, createBaffles,
mergeOrSplitBaffles -split, checkMesh; or the same mesh from the cache, ~/.cache/fsi/meshes/<hash
of the mesh inputs>, as apps/fsi-openfoam-fluid/OpenFoamCase.cpp does for the penalized runs), run to
end_time with the logs in OUT/logs/, and the forces function object's output converted to
OUT/forces.csv in the format of the penalized runs (time_s,body0.fx_n,...,body0.tz_n_m: the
fluid's force and torque on the impeller, pressure + viscous, about the origin), so that
python/fsi/pump_point.py's operating_point(OUT, ...) reads it unchanged.

    pump_ami_run.py [--resolution coarse] [--flow-rate Q] [--end-time S] [--ranks N] [--restart] -o OUT CASE_DIR

CASE_DIR is the pump case (cases/centrifugal-pump: its openfoam-ami-<resolution> is taken) or
an AMI case folder itself. Progress with ETA on stderr from pimpleFoam's log. Writes
OUT/operating_point.yaml (pump_point.operating_point) and OUT/cost.yaml (wall seconds per step
and per revolution, the AMI weights' sums). From Python: run_ami_point(case_dir, flow_rate,
out_dir, end_time, resolution)."""

import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import time

import yaml

from fsi import ROOT, fsi_launch  # noqa: E402
from fsi import pump_head_budget  # noqa: E402
from fsi import pump_point  # noqa: E402
from fsi import snap_quality, surface_engine  # noqa: E402
from fsi.foam_case import foam_entry, patch_names, set_foam_entry, write_foam_file, write_operating_point  # noqa: E402
from fsi.fsi_launch import ALLOCATOR_TUNABLES, OPENFOAM_ENVIRONMENT, speaker  # noqa: E402  (Debian's OpenFOAM finds its etc/ through it)

for _name, _value in OPENFOAM_ENVIRONMENT.items():
    os.environ.setdefault(_name, _value)

MESH_DICTS = ("blockMeshDict", "snappyHexMeshDict", "surfaceFeatureExtractDict", "meshQualityDict",
              "createBafflesDict")
FORCE_COLUMNS = ["time_s", "body0.fx_n", "body0.fy_n", "body0.fz_n", "body0.tx_n_m", "body0.ty_n_m", "body0.tz_n_m"]


say = speaker("pump-ami")


class Fnv1a:
    """common/Fnv1a.hpp: FNV-1a 64 bit, add() appends a 0xff separator."""

    def __init__(self):
        self.h = 14695981039346656037

    def add_bytes(self, data):
        h = self.h
        for c in data:
            h = ((h ^ c) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
        self.h = h

    def add(self, data):
        self.add_bytes(data if isinstance(data, bytes) else data.encode())
        self.h = ((self.h ^ 0xFF) * 1099511628211) & 0xFFFFFFFFFFFFFFFF

    def add_file(self, path):
        try:
            with open(path, "rb") as f:
                self.add(f.read())
        except FileNotFoundError:
            self.add(b"")

    def hex(self):
        return "%016x" % self.h


def mesh_cache_root():
    if os.environ.get("FSI_MESH_CACHE"):
        return os.environ["FSI_MESH_CACHE"]
    if os.environ.get("XDG_CACHE_HOME"):
        return os.path.join(os.environ["XDG_CACHE_HOME"], "fsi", "meshes")
    if os.environ.get("HOME"):
        return os.path.join(os.environ["HOME"], ".cache", "fsi", "meshes")
    return ""


def mesh_inputs_hash(foam_case):
    """As mesh_inputs_hash() of OpenFoamCase.cpp (the system dicts, then the triSurface files in
    name order), with createBafflesDict among the dicts and an "ami" tag first: never the key of
    a penalized mesh."""
    h = Fnv1a()
    h.add("ami")
    for name in MESH_DICTS:
        h.add_file(os.path.join(foam_case, "system", name))
    tri = os.path.join(foam_case, "constant", "triSurface")
    if os.path.isdir(tri):
        for name in sorted(os.listdir(tri)):
            if os.path.isfile(os.path.join(tri, name)):
                h.add(name)
                h.add_file(os.path.join(tri, name))
    return h.hex()


def run_tool(tool, foam_case, logs, options=(), who="pump-ami"):
    """An OpenFOAM utility on foam_case, its output in logs/log.<tool>; announced as `who`'s."""
    log = os.path.join(logs, "log." + tool)
    sys.stderr.write("%s: meshing: %s %s (log %s)\n" % (who, tool, " ".join(options), log))
    with open(log, "w") as f:
        code = subprocess.call([tool, "-case", foam_case] + list(options), stdout=f, stderr=subprocess.STDOUT,
                               stdin=subprocess.DEVNULL)
    if code != 0:
        raise RuntimeError("%s failed (exit %d): see %s" % (tool, code, log))
    return log


def mesh(foam_case, logs):
    """blockMesh, snappyHexMesh, createBaffles, mergeOrSplitBaffles -split, checkMesh; or the
    cached mesh of the same inputs. The 0/ fields are set aside while meshing (the tools would
    map them)."""
    root = mesh_cache_root()
    key = mesh_inputs_hash(foam_case)
    cached = os.path.join(root, key) if root else ""
    poly = os.path.join(foam_case, "constant", "polyMesh")
    if cached and os.path.exists(os.path.join(cached, "polyMesh", "owner")):
        shutil.rmtree(poly, ignore_errors=True)
        shutil.copytree(os.path.join(cached, "polyMesh"), poly)
        for name in ("log.checkMesh", "log.snappyHexMesh", "log.createBaffles", "log.mergeOrSplitBaffles"):
            if os.path.exists(os.path.join(cached, name)):
                shutil.copy(os.path.join(cached, name), os.path.join(logs, name))
        say("meshing: the AMI mesh of these inputs is cached: %s" % cached)
        return cached
    start = time.monotonic()
    zero, aside = os.path.join(foam_case, "0"), os.path.join(foam_case, "0.fields")
    os.rename(zero, aside)
    try:
        run_tool("blockMesh", foam_case, logs)
        run_tool("snappyHexMesh", foam_case, logs, ["-overwrite"])
        run_tool("createBaffles", foam_case, logs, ["-overwrite"])
        run_tool("mergeOrSplitBaffles", foam_case, logs, ["-split", "-overwrite"])
    finally:
        if os.path.isdir(zero):
            shutil.rmtree(zero)
        os.rename(aside, zero)
    for extra in ("cellLevel", "pointLevel", "level0Edge", "surfaceIndex"):
        path = os.path.join(poly, extra)
        if os.path.exists(path):
            os.remove(path)
    check = run_tool("checkMesh", foam_case, logs, ["-constant"])
    with open(check) as f:
        text = f.read()
    failed = [line.strip(" *") for line in text.splitlines() if line.lstrip().startswith("***")]
    say("meshing: done in %.0f s, checkMesh: %s" % (time.monotonic() - start,
                                                    "Mesh OK" if "Mesh OK." in text else "%s (see %s)" % ("; ".join(failed), check)))
    if cached:
        partial = "%s.partial.%d" % (cached, os.getpid())
        try:
            os.makedirs(partial)
            shutil.copytree(poly, os.path.join(partial, "polyMesh"))
            for name in ("log.checkMesh", "log.snappyHexMesh", "log.createBaffles", "log.mergeOrSplitBaffles"):
                shutil.copy(os.path.join(logs, name), os.path.join(partial, name))
            os.rename(partial, cached)
        except OSError:
            shutil.rmtree(partial, ignore_errors=True)
    return cached


def read_foam_vectors(path):
    """Rows of floats of a forces .dat file (`time (x y z) (x y z) ...`), comments skipped."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(w) for w in line.replace("(", " ").replace(")", " ").split()])
    return rows


def write_forces_csv(foam_case, out_dir):
    """OUT/forces.csv from postProcessing/forces/<start>/{force,moment}.dat: total = pressure +
    viscous (the first vector of each row), restarts joined (the later start wins)."""
    rows = {}
    starts = sorted(glob.glob(os.path.join(foam_case, "postProcessing", "forces", "*")),
                    key=lambda p: float(os.path.basename(p)))
    for start in starts:
        forces = read_foam_vectors(os.path.join(start, "force.dat"))
        moments = {r[0]: r for r in read_foam_vectors(os.path.join(start, "moment.dat"))}
        for f in forces:
            m = moments.get(f[0])
            if m is not None:
                rows[f[0]] = f[1:4] + m[1:4]
    if not rows:
        raise RuntimeError("no forces output in %s/postProcessing/forces" % foam_case)
    with open(os.path.join(out_dir, "forces.csv"), "w") as f:
        f.write(",".join(FORCE_COLUMNS) + "\n")
        for t in sorted(rows):
            f.write("%.9g,%s\n" % (t, ",".join("%.9g" % v for v in rows[t])))
    return len(rows)


def write_parts_csv(foam_case, out_dir):
    """OUT/parts.csv from postProcessing/forces_<part>/<start>/moment.dat (make_ami_case.py's
    function object per impeller patch): the torque (N m, pressure + viscous) of each part, in the
    penalized runs' format (time_s,body0.<part>.tx_n_m,...), and OUT/parts_pressure.csv, the
    pressure's share alone (a smooth surface of revolution, the discs, takes none: what they take
    is the snapped mesh's roughness). Returns the parts (none: no file)."""
    parts = sorted(os.path.basename(p)[len("forces_"):]
                   for p in glob.glob(os.path.join(foam_case, "postProcessing", "forces_*")))
    rows = {}
    for k, part in enumerate(parts):
        starts = sorted(glob.glob(os.path.join(foam_case, "postProcessing", "forces_" + part, "*")),
                        key=lambda p: float(os.path.basename(p)))
        for start in starts:
            for m in read_foam_vectors(os.path.join(start, "moment.dat")):
                rows.setdefault(m[0], [None] * len(parts))[k] = m[1:7]   # total, then pressure
    complete = {t: r for t, r in rows.items() if all(v is not None for v in r)}
    if not complete:
        return []
    for name, columns in (("parts.csv", slice(0, 3)), ("parts_pressure.csv", slice(3, 6))):
        with open(os.path.join(out_dir, name), "w") as f:
            f.write(",".join(["time_s"] + ["body0.%s.t%s_n_m" % (p, c) for p in parts for c in "xyz"]) + "\n")
            for t in sorted(complete):
                f.write("%.9g,%s\n" % (t, ",".join("%.9g" % v for r in complete[t] for v in r[columns])))
    return parts


def ami_weights(foam_case):
    """min/max of the AMI weights' sums over the run, per patch, from the AMIWeights output."""
    result = {}
    for path in glob.glob(os.path.join(foam_case, "postProcessing", "AMIWeights", "*", "*.dat")):
        with open(path) as f:
            header = []
            for line in f:
                if line.startswith("#"):
                    words = line[1:].split()
                    if words and words[0] == "Time":
                        header = words
                    continue
                values = line.split()
                for name, v in zip(header[1:], values[1:]):
                    try:
                        x = float(v)
                    except ValueError:
                        continue
                    lo, hi = result.get(name, (math.inf, -math.inf))
                    result[name] = (min(lo, x), max(hi, x))
    return {k: [v[0], v[1]] for k, v in sorted(result.items())}


def decompose(foam_case, logs, ranks):
    """decomposePar into `ranks` subdomains cut along x, as the penalized runs are
    (apps/fsi-openfoam-fluid/OpenFoamCase.cpp; Debian's scotch is a stub): each rank holds half
    of the rotor and half of the casing."""
    write_foam_file(foam_case, "system/decomposeParDict", "dictionary",
                    "numberOfSubdomains %d;\nmethod hierarchical;\ncoeffs { n (%d 1 1); order xyz; }\n"
                    % (ranks, ranks))
    run_tool("decomposePar", foam_case, logs, ["-force"])


def mpirun_prefix(ranks):
    """mpirun for `ranks` ranks of an OpenFOAM solver, as SelfLaunch.cpp starts the penalized fluid
    (empty for one rank)."""
    if ranks <= 1:
        return []
    prefix = ["mpirun", "-np", str(ranks), "--oversubscribe", "-x", "WM_PROJECT_DIR", "-x", "FOAM_ETC"]
    for name in ALLOCATOR_TUNABLES:
        prefix += ["-x", name]
    if os.geteuid() == 0:
        prefix.append("--allow-run-as-root")
    return prefix


def latest_time(foam_case, ranks):
    """The latest time folder with fields (U) of the case, or of its processor0 when decomposed."""
    root = os.path.join(foam_case, "processor0") if ranks > 1 else foam_case
    times = [d for d in os.listdir(root) if re.fullmatch(r"[0-9.eE+-]+", d)
             and os.path.isfile(os.path.join(root, d, "U"))] if os.path.isdir(root) else []
    return max(times, key=float) if times else None


def run_pimple(foam_case, logs, end_time, dt, ranks=1, start_time=0.0):
    """pimpleFoam, serial or on `ranks` MPI ranks (decomposed case), from start_time; progress with
    ETA on stderr. ([ExecutionTime per step], wall s)."""
    log = os.path.join(logs, "log.pimpleFoam")
    steps = round((end_time - start_time) / dt)
    say("pimpleFoam from t = %g to %g s (dt = %g s, %d steps, %d rank%s), log %s"
        % (start_time, end_time, dt, steps, ranks, "s" if ranks > 1 else "", log))
    exec_times, t, last_report, start = [], start_time, 0.0, time.monotonic()
    if start_time > 0 and os.path.exists(log):          # a continued run keeps the earlier log
        os.rename(log, "%s.until-%g" % (log, start_time))
    command = mpirun_prefix(ranks) + ["pimpleFoam", "-case", foam_case] + (["-parallel"] if ranks > 1 else [])
    with open(log, "w") as f:
        # With our executables' allocator settings: the comparison per revolution is of the methods.
        process = subprocess.Popen(command, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   env=dict(os.environ, **ALLOCATOR_TUNABLES))
        for raw in iter(process.stdout.readline, b""):
            line = raw.decode("utf-8", "replace")
            f.write(line)
            if line.startswith("Time = "):
                try:
                    t = float(line.split()[2])
                except (IndexError, ValueError):
                    pass
            elif line.startswith("ExecutionTime = "):
                exec_times.append(float(line.split()[2]))
                now = time.monotonic()
                if now - last_report > 15.0 and t > start_time:
                    elapsed = now - start
                    say("flow: t = %.6g of %g s, step %d/%d, %.0f ms/step, ETA %.0f s"
                        % (t, end_time, len(exec_times), steps, 1e3 * elapsed / len(exec_times),
                           elapsed * (end_time - t) / (t - start_time)))
                    last_report = now
        code = process.wait()
    if code != 0:
        raise RuntimeError("pimpleFoam failed (exit %d): see %s" % (code, log))
    return exec_times, time.monotonic() - start


def time_mesh_motion(foam_case, logs, steps=20):
    """Wall seconds per step of the mesh motion alone (the solid-body rotation and the AMI's
    new addressing and weights): moveDynamicMesh on a copy of the case for `steps` steps.
    pimpleFoam's log does not time its mesh.update()."""
    copy = foam_case.rstrip("/") + ".mesh-motion"
    if os.path.exists(copy):
        shutil.rmtree(copy)
    shutil.copytree(foam_case, copy, ignore=shutil.ignore_patterns("postProcessing", "processor*", "[1-9]*",
                                                                   "0.[0-9]*"))
    control = os.path.join(copy, "system", "controlDict")
    dt = float(foam_entry(control, "deltaT"))
    set_foam_entry(control, "endTime", repr(steps * dt))
    log = os.path.join(logs, "log.moveDynamicMesh")
    with open(log, "w") as f:
        code = subprocess.call(["moveDynamicMesh", "-case", copy, "-noFunctionObjects"], stdout=f,
                               stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    shutil.rmtree(copy, ignore_errors=True)
    if code != 0:
        say("moveDynamicMesh failed (exit %d): see %s" % (code, log))
        return None
    with open(log) as f:
        times = [float(m) for m in re.findall(r"^ExecutionTime = ([0-9.eE+-]+) s", f.read(), re.M)]
    if len(times) < 3:
        return None
    return (times[-1] - times[0]) / (len(times) - 1)


def solver_split(log):
    """The AMI's addressing updates counted in pimpleFoam's log (one per step)."""
    with open(log) as f:
        text = f.read()
    return {"ami_addressing_updates": text.count("Creating addressing and weights")}


def case_folder(case_dir, resolution):
    """The AMI case of a resolution; a preset <res>-ami-mesh (the penalized impeller on the AMI
    mesh) pairs with openfoam-ami-<res>."""
    if os.path.isdir(os.path.join(case_dir, "system")):
        return case_dir
    if resolution.endswith("-ami-mesh"):
        resolution = resolution[:-len("-ami-mesh")]
    return os.path.join(case_dir, "openfoam-ami-" + resolution)


MAP_FIELDS = """// Written by pump_ami_run.py: a warm start from a run of the penalized case (the same casing
// patches; the AMI case's impeller walls and AMI pair are not in the source and keep their
// conditions).
patchMap ( %s );
cuttingPatches ( );
"""


def map_initial_fields(foam_case, logs, source):
    """Maps the latest fields of the OpenFOAM case `source` (a penalized run's output/openfoam,
    ended after whole revolutions) onto the AMI mesh as its initial fields."""
    times = [d for d in os.listdir(source) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0
             and os.path.isfile(os.path.join(source, d, "U"))]
    if not times:
        raise SystemExit("pump-ami: %s has no time folder after 0 with fields to start from" % source)
    latest = max(times, key=float)
    patches = patch_names(source)
    write_foam_file(foam_case, "system/mapFieldsDict", "dictionary",
                    MAP_FIELDS % " ".join("%s %s" % (p, p) for p in patches))
    run_tool("mapFields", foam_case, logs, ["-sourceTime", latest, source])
    for stale in ("phi", "fsiAcceleration"):
        path = os.path.join(foam_case, "0", stale)
        if os.path.exists(path):
            os.remove(path)
    say("warm start: the fields of t = %s s of %s mapped onto the AMI mesh" % (latest, source))


def check_snap(foam_case, out_dir):
    """How closely the snapped impeller follows its STL (snap_quality.py): out_dir/snap_quality.yaml,
    and a warning per part that is a staircase over more than 5 % of its area (its steps take a
    pressure drag a smooth wall does not: 7.8 N m on a single-channel impeller's drum, 1.25 cells
    from the sliding interface). A check that cannot run says why and the run goes on."""
    stl = os.path.join(foam_case, "constant", "triSurface", "impeller.stl")
    try:
        table = snap_quality.report(foam_case, stl)
    except (snap_quality.SnapError, surface_engine.EngineError, OSError) as error:
        say("no snap check of the impeller: %s" % error)
        return
    with open(os.path.join(out_dir, "snap_quality.yaml"), "w") as f:
        f.write("# python/fsi/snap_quality.py: the impeller's patches against %s; stepped = the share of\n"
                "# the area whose faces stand more than %g deg off the surface's normal\n"
                % (os.path.relpath(stl, out_dir), snap_quality.STEPPED_ANGLE_DEG))
        yaml.safe_dump(table, f, sort_keys=False)
    worst = max(table.items(), key=lambda item: item[1]["stepped_area_fraction"])
    say("snap check: at most %.1f %% of a part's area stepped (%s)" % (100 * worst[1]["stepped_area_fraction"], worst[0]))
    for line in snap_quality.warnings(table):
        say("warning: " + line)


def run_ami_point(case_dir, flow_rate, out_dir, end_time, resolution="coarse", initial_fields_from=None,
                  ranks=1, restart=False):
    """Runs the AMI reference at `flow_rate` (m^3/s) to `end_time` (s) in out_dir on `ranks` MPI
    ranks; returns the operating point (pump_point.operating_point) and writes
    out_dir/{forces.csv, operating_point.yaml, cost.yaml}. initial_fields_from: an OpenFOAM case
    whose latest fields are the initial ones (a warm start; see map_initial_fields). The fields
    are written every quarter revolution (the last two kept): restart=True continues the run in
    out_dir from its latest ones (same ranks) to end_time, and the forces of both parts are joined."""
    source = case_folder(os.path.abspath(case_dir), resolution)
    if not os.path.isfile(os.path.join(source, "constant", "dynamicMeshDict")):
        raise SystemExit("pump-ami: %s is not an AMI case folder (make_ami_case.py writes them)" % source)
    if ranks < 1:
        raise SystemExit("pump-ami: --ranks %d: the number of MPI ranks is at least 1" % ranks)
    out_dir = os.path.abspath(out_dir)
    foam_case, logs = os.path.join(out_dir, "openfoam"), os.path.join(out_dir, "logs")
    control = os.path.join(foam_case, "system", "controlDict")
    start_time, t0 = 0.0, time.monotonic()
    if restart:
        decomposed = len(glob.glob(os.path.join(foam_case, "processor*")))
        latest = latest_time(foam_case, ranks)
        if latest is None or decomposed != (ranks if ranks > 1 else 0):
            raise SystemExit("pump-ami: --restart: %s has no fields to continue from on %d rank%s (it has %d "
                             "processor folders): run it first, or restart with the ranks it ran on"
                             % (foam_case, ranks, "s" if ranks > 1 else "", decomposed))
        start_time = float(latest)
        if start_time >= end_time - 1e-9:
            raise SystemExit("pump-ami: --restart: %s is already at t = %s s, not before --end-time %g s"
                             % (foam_case, latest, end_time))
        set_foam_entry(control, "startFrom", "latestTime")
        say("restart: continuing %s from t = %s s" % (foam_case, latest))
    else:
        if os.path.exists(foam_case):
            shutil.rmtree(foam_case)
        os.makedirs(logs, exist_ok=True)
        shutil.copytree(source, foam_case, symlinks=False)          # the STL links resolved
        write_operating_point(foam_case, flow_rate)
    set_foam_entry(control, "endTime", repr(float(end_time)))
    dt = float(foam_entry(control, "deltaT"))
    with open(os.path.join(foam_case, "constant", "dynamicMeshDict")) as f:
        text = f.read()
    omega = float(re.search(r"^omega\s+([^;]+);", text, re.M).group(1))
    axis = [float(v) for v in re.search(r"^axis\s+\(([^)]*)\)", text, re.M).group(1).split()]
    period = 2 * math.pi / omega
    # The fields of every quarter revolution (purgeWrite keeps the last two), to continue from: a
    # run stopped (a session's end, a node lost) loses at most a quarter revolution, as the
    # penalized run's checkpoints in ./fsi pump-compare.
    set_foam_entry(control, "writeInterval", repr(min(period / 4.0, float(end_time))))
    if not restart:
        mesh(foam_case, logs)
        if os.path.exists(os.path.join(foam_case, "system", "topoSetDict")):
            # cell zones the case's fvOptions act on (a pump's front seal: front_seal.py), added to the
            # mesh made or cached (the cache stays without them), before the fields are mapped and decomposed
            run_tool("topoSet", foam_case, logs)
        check_snap(foam_case, out_dir)
        if initial_fields_from:
            map_initial_fields(foam_case, logs, os.path.abspath(initial_fields_from))
        if ranks > 1:
            decompose(foam_case, logs, ranks)
    mesh_s = time.monotonic() - t0
    with open(os.path.join(logs, "log.checkMesh")) as f:
        check = f.read()
    cells = int(re.search(r"^\s+cells:\s+(\d+)", check, re.M).group(1))
    exec_times, wall = run_pimple(foam_case, logs, end_time, dt, ranks, start_time)
    if ranks > 1:   # the last fields in the case itself: the head budget and warm starts read them
        run_tool("reconstructPar", foam_case, logs, ["-latestTime"])
    n = write_forces_csv(foam_case, out_dir)
    write_parts_csv(foam_case, out_dir)
    steps = len(exec_times)
    per_step = [b - a for a, b in zip([0.0] + exec_times[:-1], exec_times)]
    steady = per_step[min(5, steps - 1):] if steps else [float("nan")]
    cost = {
        "cells": cells,
        "ranks": ranks,
        # The failed checks as checkMesh words them (snappy's AMI meshes usually fail only the
        # skewness of boundary faces, which snappyHexMesh allows up to maxBoundarySkewness 20).
        "checkMesh": "Mesh OK" if "Mesh OK." in check else
        "; ".join(line.strip(" *") for line in check.splitlines() if line.lstrip().startswith("***")),
        "mesh_wall_s": round(mesh_s, 1),
        "steps": steps,
        "dt_s": dt,
        "pimpleFoam_wall_s": round(wall, 1),
        "execution_s_per_step": sum(steady) / len(steady),
        "wall_s_per_revolution": wall / ((end_time - start_time) / period),
        "steps_per_revolution": period / dt,
        "ami_weights_sum_min_max": ami_weights(foam_case),
    }
    snap = os.path.join(out_dir, "snap_quality.yaml")
    if os.path.isfile(snap):
        with open(snap) as f:
            cost["impeller_stepped_area_fraction"] = {k: v["stepped_area_fraction"]
                                                      for k, v in (yaml.safe_load(f) or {}).items()}
    cost.update(solver_split(os.path.join(logs, "log.pimpleFoam")))
    motion = time_mesh_motion(foam_case, logs)
    if motion is not None:
        cost["mesh_motion_and_ami_s_per_step"] = motion
        cost["mesh_motion_and_ami_s_per_revolution"] = motion * period / dt
    with open(os.path.join(out_dir, "cost.yaml"), "w") as f:
        yaml.safe_dump(cost, f, sort_keys=False)
    say("forces.csv (%d rows); %.1f wall s per revolution (%d cells, %d rank%s)"
        % (n, cost["wall_s_per_revolution"], cells, ranks, "s" if ranks > 1 else ""))
    radius = None
    pump_yaml = os.path.join(os.path.dirname(source), "pump.yaml")
    if os.path.isfile(pump_yaml):
        with open(pump_yaml) as f:
            radius = 0.5 * yaml.safe_load(f)["impeller"]["outer_diameter_m"]
    point = None
    if radius:
        try:
            point = pump_point.operating_point(out_dir, omega, axis, radius, float(flow_rate))
        except ValueError as error:
            say("no operating point: %s" % error)
    if point:
        try:  # where the head is made and lost, as postprocess.py does for the penalized runs
            with open(pump_yaml) as f:
                rows = pump_head_budget.head_budget(foam_case, yaml.safe_load(f))
            point["head_budget_of_the_last_fields"] = {
                "euler_head_of_the_mean_torque_m": point["shaft_power_w"] / (1000.0 * 9.81 * float(flow_rate)),
                "stations": [{k: round(v, 5) if isinstance(v, float) else v for k, v in row.items()} for row in rows]}
        except (ImportError, ValueError) as error:
            say("no head budget: %s" % error)
        with open(os.path.join(out_dir, "operating_point.yaml"), "w") as f:
            f.write("# The operating point of this AMI run (python/fsi/pump_point.py), SI units.\n")
            yaml.safe_dump(point, f, sort_keys=False)
        say("H = %.4g m, T = %.4g N m, eta = %.3f" % (point["head_m"], point["shaft_torque_n_m"], point["efficiency"]))
    return point


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--resolution", default="coarse")
    parser.add_argument("--flow-rate", type=float, default=0.0, help="m^3/s (default: the design flow rate, pump.yaml)")
    parser.add_argument("--end-time", type=float, default=0.0, help="s (default: case.yaml run.end_time_s)")
    parser.add_argument("--initial-fields-from", default="",
                        help="an OpenFOAM case (a penalized run's output/openfoam, ended after whole revolutions) "
                             "whose latest fields start this run")
    parser.add_argument("--ranks", type=int, default=1, help="MPI ranks of pimpleFoam (default 1: serial)")
    parser.add_argument("--restart", action="store_true",
                        help="continue the run in OUTPUT from its latest fields (written every quarter revolution) to "
                             "--end-time, on the ranks it ran on")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("case_dir")
    args = parser.parse_args(argv)
    pump_dir = args.case_dir if os.path.isfile(os.path.join(args.case_dir, "pump.yaml")) else os.path.dirname(
        os.path.abspath(args.case_dir))
    q, end = args.flow_rate, args.end_time
    if not q:
        with open(os.path.join(pump_dir, "pump.yaml")) as f:
            q = float(yaml.safe_load(f)["operation"]["design_flow_rate_m3_per_s"])
    if not end:
        with open(os.path.join(pump_dir, "case.yaml")) as f:
            end = float(yaml.safe_load(f)["run"]["end_time_s"])
    if pump_dir == args.case_dir and not args.restart:
        # a pump case: its geometry and OpenFOAM folders generated from its pump.yaml when missing
        # or stale (prepare.py, as ./fsi run does; quiet when there is nothing to do)
        try:
            fsi_launch.prepare_case(args.case_dir, os.environ.get("FSI_BIN_DIR") or os.path.join(ROOT, "build", "bin"),
                                    args.resolution)
        except fsi_launch.UserError as e:
            sys.exit("pump-ami: %s" % e)
    run_ami_point(args.case_dir, q, args.output, end, args.resolution, args.initial_fields_from or None,
                  args.ranks, args.restart)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
