#!/usr/bin/python3
"""Generates this case's geometry from its design: geometry/ (impeller.stl, casing.stl,
geometry.yaml, geometry_checks.yaml, geometry.png) by `fsi-pump-design pump.yaml --write`, when
it is missing or was made from another pump.yaml or another build of the generator. A stamp,
geometry/generated-from, holds the hashes of both and of the STL files written. STL files the
stamp does not name (your own: docs/pump-own-geometry.md) are never overwritten. The generator
is deterministic: a regenerated geometry has the same bytes, and the cached snappyHexMesh meshes
stay valid. The OpenFOAM cases' files (make_case.py, make_ami_case.py), which follow the
geometry, are rewritten after a generation and whenever the scripts, the modules they take files
from, pump.yaml or case.yaml changed (a second stamp, geometry/openfoam-from). It takes about 5 s.

    prepare.py CASE_DIR BIN_DIR     (python/fsi/fsi_launch.py runs it before every run of the case)

To run the case on your own STL files instead, see docs/pump-own-geometry.md.
"""

import fcntl
import hashlib
import os
import shutil
import subprocess
import sys
import time

STLS = ("impeller.stl", "casing.stl")
# The python/fsi modules make_case.py and make_ami_case.py take OpenFOAM files from.
OPENFOAM_MODULES = ("foam_case.py", "front_seal.py", "pump_stations.py")


def sha256(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def stl_lines(digests):
    return "".join("%s sha256 %s\n" % (name, digests[name]) for name in STLS if name in digests)


HERE = os.path.dirname(os.path.abspath(__file__))


def main(argv, pump_curve_variants=True):
    """pump_curve_variants: also the rans and coarse-gaps folders and the AMI reference (this
    case's pump curve); cases/rag-in-pump, which calls this for its own folder, wants neither."""
    if len(argv) != 3:
        sys.exit("usage: prepare.py CASE_DIR BIN_DIR")
    sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))   # fsi.pump_stations, also when run alone
    case_dir, bin_dir = argv[1], argv[2]
    design = os.path.join(case_dir, "pump.yaml")
    generator = os.path.join(bin_dir, "fsi-pump-design")
    geometry = os.path.join(case_dir, "geometry")
    if not os.path.isfile(generator):
        # A build without the generator (the sanitizer pass) takes the geometry of this pump.yaml
        # when it is there.
        stamp_file = os.path.join(geometry, "generated-from")
        if os.path.isfile(stamp_file) and ("pump.yaml sha256 %s\n" % sha256(design)) in open(stamp_file).read() \
                and all(os.path.isfile(os.path.join(geometry, name)) for name in STLS):
            return ensure_stations(case_dir)
        sys.exit("prepare.py: the pump generator %s is not built (./fsi build)" % generator)
    # One generation at a time per case (two runs of the same case may start together).
    lock = open(os.path.join(case_dir, ".geometry.lock"), "w")
    fcntl.flock(lock, fcntl.LOCK_EX)
    stamp_file = os.path.join(geometry, "generated-from")
    inputs = "pump.yaml sha256 %s\nfsi-pump-design sha256 %s\n" % (sha256(design), sha256(generator))
    stamp = open(stamp_file).read() if os.path.isfile(stamp_file) else ""
    stamped = dict(line.split(" sha256 ") for line in stamp.splitlines() if " sha256 " in line)
    present = {name: sha256(os.path.join(geometry, name)) for name in STLS
               if os.path.isfile(os.path.join(geometry, name))}
    if any(stamped.get(name) != digest for name, digest in present.items()):
        return ensure_stations(case_dir)  # files this script did not write: the user's own geometry, left alone
    if stamp == inputs + stl_lines(present) and len(present) == len(STLS):
        ensure_openfoam_files(case_dir, geometry, pump_curve_variants)  # the geometry is up to date
        return ensure_stations(case_dir)
    # Written next to geometry/ and swapped in whole: a failed or interrupted run leaves the old one.
    partial = geometry + ".partial-%d" % os.getpid()
    shutil.rmtree(partial, ignore_errors=True)
    start = time.time()
    made = subprocess.run([generator, design, "--write", partial], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT)
    if made.returncode != 0:
        lines = made.stdout.decode(errors="replace").strip().splitlines()
        shutil.rmtree(partial, ignore_errors=True)
        sys.exit("prepare.py: %s %s --write failed (exit %d):\n%s"
                 % (generator, design, made.returncode, "\n".join(lines[-15:])))
    with open(os.path.join(partial, "generate.log"), "wb") as f:
        f.write(made.stdout)
    with open(os.path.join(partial, "generated-from"), "w") as f:
        f.write(inputs + stl_lines({name: sha256(os.path.join(partial, name)) for name in STLS}))
    old = geometry + ".old-%d" % os.getpid()
    if os.path.isdir(geometry):
        os.rename(geometry, old)
    os.rename(partial, geometry)
    shutil.rmtree(old, ignore_errors=True)
    ensure_openfoam_files(case_dir, geometry, pump_curve_variants)
    print("generated %s from %s in %.1f s (log: %s)"
          % (geometry, design, time.time() - start, os.path.join(geometry, "generate.log")))
    return ensure_stations(case_dir)


def ensure_openfoam_files(case_dir, geometry, pump_curve_variants):
    """The OpenFOAM cases' files (make_case.py, make_ami_case.py) when the geometry or anything
    that writes them changed since they were written: the scripts, the modules they take files
    from, pump.yaml and case.yaml. A stamp, geometry/openfoam-from, holds those hashes; it is
    written last, so a failed script leaves none and the next run writes the files again. The
    scripts write unchanged bytes for unchanged inputs."""
    import fsi   # python/fsi, on the path (main): also for a copy of the case elsewhere
    python = os.path.dirname(os.path.abspath(fsi.__file__))
    sources = [os.path.join(geometry, "generated-from"), os.path.join(case_dir, "pump.yaml"),
               os.path.join(case_dir, "case.yaml"), os.path.join(HERE, "make_case.py"),
               os.path.join(HERE, "make_ami_case.py")] + [os.path.join(python, name) for name in OPENFOAM_MODULES]
    inputs = "".join("%s sha256 %s\n" % (os.path.relpath(path, case_dir), sha256(path))
                     for path in sources if os.path.isfile(path)) + "variants %s\n" % pump_curve_variants
    stamp_file = os.path.join(geometry, "openfoam-from")
    if os.path.isfile(stamp_file) and open(stamp_file).read() == inputs:
        return
    if os.path.exists(stamp_file):
        os.remove(stamp_file)
    # The OpenFOAM cases' files follow the geometry (the background box around the casing, the
    # rotor cylinder of the AMI reference).
    scripts = [["make_case.py", case_dir] + ([] if pump_curve_variants else ["--resolutions-only"])]
    if pump_curve_variants:
        scripts.append(["make_ami_case.py"])
    for script, *args in scripts:
        made = subprocess.run([sys.executable, os.path.join(HERE, script)] + args, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT)
        if made.returncode != 0:
            sys.exit("prepare.py: %s failed:\n%s" % (script, made.stdout.decode(errors="replace").strip()))
    with open(stamp_file, "w") as f:
        f.write(inputs)


def ensure_stations(case_dir):
    """geometry/stations/ (python/fsi/pump_stations.py: the head budget's stations, sampled by
    the runs' function objects) when missing or older than pump.yaml or geometry.yaml. Without a
    geometry.yaml (your own STL files), none: the station function objects then sample nothing."""
    geometry = os.path.join(case_dir, "geometry")
    sources = [os.path.join(case_dir, "pump.yaml"), os.path.join(geometry, "geometry.yaml")]
    if not os.path.isfile(sources[1]):
        return 0
    from fsi import pump_stations
    folder = os.path.join(geometry, "stations")
    files = [os.path.join(folder, name + ".stl") for name in pump_stations.STATIONS]
    if all(os.path.isfile(f) for f in files) and \
            min(os.path.getmtime(f) for f in files) >= max(os.path.getmtime(s) for s in sources):
        return 0
    pump_stations.write_stations(case_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
