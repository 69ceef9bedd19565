#!/usr/bin/python3
"""Writes the generated files of the rotating-disc case: one OpenFOAM folder per laminar
resolution (openfoam: h = s/10, openfoam-medium: s/20, openfoam-fine: s/40), and the turbulent
ones (openfoam-turbulent: s/10, openfoam-turbulent-medium: s/20; Spalart-Allmaras RANS at the
pump discs' Reynolds number); mesh dictionary, fields, transport, turbulence, schemes,
solution, controlDict in each; and disc.stl. Run it after changing a parameter in
python/fsi/rotating_disc.py or below; the files it writes are committed, so the case runs as it is.

    PYTHONPATH=python /usr/bin/python3 cases/rotating-disc/make_case.py
"""

import os

from fsi.foam_case import LAMINAR_FV_SCHEMES
from fsi.rotating_disc import Disc, disc_stl, write_foam_case

HERE = os.path.dirname(os.path.abspath(__file__))

# Closed housing: the pressure is fixed in one cell. Two correctors, a momentum predictor (the
# project's PIMPLE settings; docs/verification.md, "The limits of PISO").
FV_SOLUTION = """solvers
{
    p      { solver GAMG; smoother GaussSeidel; tolerance 1e-8; relTol 0.01; }
    pFinal { $p; relTol 0; }
    "(U|nuTilda)(|Final)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-10; relTol 0; }
}
PIMPLE
{
    nOuterCorrectors 1;
    nCorrectors      2;
    nNonOrthogonalCorrectors 0;
    momentumPredictor yes;
    pRefCell         0;
    pRefValue        0;
}
"""

# Spalart-Allmaras: bounded upwind-biased convection of nuTilda, the wall distance by meshWave
# (the fluid adds the immersed disc's own distance).
TURBULENT_FV_SCHEMES = LAMINAR_FV_SCHEMES.replace(
    "    div((nuEff", "    div(phi,nuTilda) Gauss limitedLinear 1;\n    div((nuEff") + "wallDist        { method meshWave; }\n"

# Laminar (Daily & Nece's regime I): omega = 1 rad/s, nu = 2.5e-5 m^2/s (Re = 400).
LAMINAR = Disc()
# Turbulent (regime IV): the pump's speed (1440 rpm) in water, Re = omega R^2 / nu = 1.5e6.
TURBULENT = Disc(omega_rad_per_s=1440.0 * 3.141592653589793 / 30.0, nu_m2_per_s=1.0e-6)
# (folder, disc, cells per axial gap, time step s, end time s, turbulent). Laminar: nu dt / h^2 = 2
# at every level. Turbulent: dt = 1e-4 s (a radial speed of 0.2 omega R crosses 0.6 cells a
# step at s/10), 0.5 s = 12 revolutions.
RESOLUTIONS = [("openfoam", LAMINAR, 10, 0.02, 4.0, False), ("openfoam-medium", LAMINAR, 20, 0.005, 4.0, False),
               ("openfoam-fine", LAMINAR, 40, 0.00125, 4.0, False),
               ("openfoam-turbulent", TURBULENT, 10, 1.0e-4, 0.5, True),
               ("openfoam-turbulent-medium", TURBULENT, 20, 5.0e-5, 0.5, True)]


def main():
    for folder, disc, per_gap, dt, end, turbulent in RESOLUTIONS:
        write_foam_case(os.path.join(HERE, folder), disc, disc.axial_gap_m / per_gap, False, end, dt,
                        TURBULENT_FV_SCHEMES if turbulent else LAMINAR_FV_SCHEMES, FV_SOLUTION, turbulent)
    with open(os.path.join(HERE, "disc.stl"), "w") as f:
        f.write(disc_stl(LAMINAR))
    print("wrote", ", ".join(r[0] for r in RESOLUTIONS), "and disc.stl in", HERE)


if __name__ == "__main__":
    main()
