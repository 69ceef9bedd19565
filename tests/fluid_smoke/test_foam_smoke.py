#!/usr/bin/env python3
"""Smoke test of the OpenFOAM v1912 build (label: fluid).

Writes a 10x10x10 lid-driven cavity (after Debian's tutorial incompressible/icoFoam/cavity, made
3D: a cube of side 0.1 m) into a temporary folder, meshes it with Debian's blockMesh, runs
fsi-foam-smoke on it and checks what it prints: 1000 cells, the box volume to 1e-12 relative, the
lid speed as max |U|, then a few PISO steps with finite, bounded results.

    test_foam_smoke.py --app PATH/fsi-foam-smoke [--blockmesh /usr/bin/blockMesh] [--keep]
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

from fsi.foam_case import foam_header


SIDE = 0.1          # m
N = 10              # cells per direction
LID = 1.0           # m/s

FILES = {
    "system/blockMeshDict": ("dictionary", f"""
scale   {SIDE};
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1) );
blocks ( hex (0 1 2 3 4 5 6 7) ({N} {N} {N}) simpleGrading (1 1 1) );
edges ();
boundary
(
    movingWall {{ type wall; faces ( (3 7 6 2) ); }}
    fixedWalls {{ type wall; faces ( (0 4 7 3) (2 6 5 1) (1 5 4 0) (0 3 2 1) (4 5 6 7) ); }}
);
mergePatchPairs ();
"""),
    "system/controlDict": ("dictionary", """
application     fsi-foam-smoke;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         0.05;
deltaT          0.005;
writeControl    timeStep;
writeInterval   1000;
purgeWrite      0;
writeFormat     ascii;
writePrecision  6;
writeCompression off;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
"""),
    "system/fvSchemes": ("dictionary", """
ddtSchemes      { default Euler; }
gradSchemes     { default Gauss linear; }
divSchemes
{
    default         none;
    div(phi,U)      Gauss linear;
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear orthogonal; }
interpolationSchemes { default linear; }
snGradSchemes   { default orthogonal; }
"""),
    "system/fvSolution": ("dictionary", """
solvers
{
    p      { solver PCG; preconditioner DIC; tolerance 1e-06; relTol 0.05; }
    pFinal { $p; relTol 0; }
    U      { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-05; relTol 0; }
}
PISO { nCorrectors 2; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }
"""),
    "constant/transportProperties": ("dictionary", """
transportModel  Newtonian;
nu              0.01;
"""),
    "constant/turbulenceProperties": ("dictionary", """
simulationType  laminar;
"""),
    "0/U": ("volVectorField", f"""
dimensions      [0 1 -1 0 0 0 0];
internalField   uniform (0 0 0);
boundaryField
{{
    movingWall {{ type fixedValue; value uniform ({LID} 0 0); }}
    fixedWalls {{ type noSlip; }}
}}
"""),
    "0/p": ("volScalarField", """
dimensions      [0 2 -2 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    movingWall { type zeroGradient; }
    fixedWalls { type zeroGradient; }
}
"""),
}

failures = []
checks = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    checks.append(what)
    if not cond:
        failures.append(what)


def write_case(case):
    for rel, (cls, body) in FILES.items():
        path = os.path.join(case, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(foam_header(cls, os.path.basename(rel)) + body)


def run(cmd, case, env, log):
    res = subprocess.run(cmd, cwd=case, env=env, stdin=subprocess.DEVNULL,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=240)
    with open(os.path.join(case, log), "w") as f:
        f.write(res.stdout)
    if res.returncode != 0:
        print(res.stdout[-4000:])
        print(f"FAIL {' '.join(cmd)} exited with {res.returncode}")
        sys.exit(1)
    return res.stdout


def parse(out, key):
    """The fsi-foam-smoke line that has KEY=..., as a dict."""
    for line in out.splitlines():
        if line.startswith("fsi-foam-smoke:") and f" {key}=" in line:
            return dict(re.findall(r"(\w+)=(\S+)", line))
    print(out[-4000:])
    print(f"FAIL no 'fsi-foam-smoke: ... {key}=' line in the output")
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--app", required=True)
    ap.add_argument("--blockmesh", default=shutil.which("blockMesh") or "/usr/bin/blockMesh")
    ap.add_argument("--steps", type=int, default=5)
    ap.add_argument("--keep", action="store_true", help="keep the case folder")
    a = ap.parse_args()
    a.app = os.path.abspath(a.app)
    a.blockmesh = os.path.abspath(a.blockmesh)

    env = dict(os.environ)
    # Debian's OpenFOAM finds its etc/ (controlDict, cellModels...) through WM_PROJECT_DIR.
    env.setdefault("WM_PROJECT_DIR", "/usr/share/openfoam")
    env.setdefault("FOAM_ETC", env["WM_PROJECT_DIR"] + "/etc")
    env.pop("FOAM_SIGFPE", None)

    tmp = tempfile.mkdtemp(prefix="fsi-foam-smoke-")
    case = os.path.join(tmp, "cavity")
    env["PWD"] = case  # OpenFOAM warns when PWD is not the working folder
    try:
        write_case(case)
        run([a.blockmesh, "-case", case], case, env, "log.blockMesh")
        check(os.path.isfile(os.path.join(case, "constant/polyMesh/owner")), "blockMesh wrote the mesh")

        out = run([a.app, "-case", case], case, env, "log.smoke")
        s = parse(out, "cells")
        check(int(s["cells"]) == N ** 3, f"cells = {s['cells']} (expected {N ** 3})")
        vol, box = float(s["volume"]), SIDE ** 3
        check(abs(vol - box) <= 1e-12 * box, f"volume = {vol!r} (box {box!r}, rel. err {abs(vol - box) / box:.2e})")
        check(abs(float(s["maxU"]) - LID) <= 1e-12, f"max |U| = {s['maxU']} (lid speed {LID})")

        out = run([a.app, "-case", case, "-steps", str(a.steps)], case, env, "log.smoke-steps")
        r = parse(out, "steps")
        u, cont, t = float(r["maxU"]), float(r["continuity"]), float(r["time"])
        check(int(r["steps"]) == a.steps and abs(t - a.steps * 0.005) < 1e-12,
              f"{r['steps']} PISO steps, time = {t}")
        # simulationType laminar selects the laminar model 'Stokes' in v1912
        check(r.get("turbulence") == "Stokes", f"turbulence model = {r.get('turbulence')} (Stokes)")
        check(math.isfinite(u) and abs(u - LID) <= 1e-9, f"after the steps max |U| = {u} (the lid)")
        check(math.isfinite(cont) and 0 <= cont < 1e-6, f"continuity error (sum local) = {cont:.3e}")
        check(not os.path.isdir(os.path.join(case, "0.005")), "nothing written by the smoke app")
    finally:
        if a.keep:
            print(f"case kept in {case}")
        else:
            shutil.rmtree(tmp, ignore_errors=True)

    passed = len(checks) - len(failures)
    print(f"{passed} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
