#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""pimpleDEMFoam against the drag laws over the particle Reynolds numbers
users meet: fixed beds (particles held on a lattice, so the porosity is
exact and uniform) from Re_p 0.1 to 100 for every law, both formulations,
one and two particle sizes, the pressure gradient against the law written
here from the papers; the same bed on 2 ranks against serial; a single
settling sphere from Re 0.1 to 800 against Schiller-Naumann."""
import math
import os
import shutil
import sys

import numpy as np
from scipy.optimize import brentq

import checks
from checks import WORK, check, near
from dragLaws import LAWS
from foamCase import ROOT, set_dem, sh

RHO, NU = 1000.0, 1e-6
MU = RHO*NU
CELL = 0.004                   # cells of 4 mm; 2 x 2 columns, cyclic sides
BED_LAYERS = 10                # the bed fills z = 0 to 40 mm
PROBES = (0.010, 0.030)        # cell centres two cells inside the bed
D_LARGE, D_SMALL = 1.9e-3, 1.2e-3
RE_LEVELS = (0.1, 1.0, 10.0, 100.0)   # superficial Re_p of the large spheres
LEVEL_STEPS = 10               # fluid steps of 1 ms per inlet velocity
DT = 1e-3


def lattice(bidisperse):
    """2 x 2 x 2 spheres in every bed cell, each wholly inside its cell: every
    bed cell holds the same solid, so the flow is one-dimensional"""
    rows = []
    for k in range(BED_LAYERS*2):
        for j in range(4):
            for i in range(4):
                small = bidisperse and (i + j + k) % 2 == 1
                d = D_SMALL if small else D_LARGE
                rows.append((d, (0.001 + 0.002*i, 0.001 + 0.002*j, 0.001 + 0.002*k)))
    return rows


def write_case(case, law, formulation, bidisperse):
    shutil.rmtree(case, ignore_errors=True)
    for sub in ("constant", "system", "0", "DEM/post"):
        os.makedirs(os.path.join(case, sub))
    tut = os.path.join(ROOT, "tutorials", "packedBedErgun")
    for f in ("constant/g", "constant/transportProperties"):
        shutil.copy(os.path.join(tut, f), os.path.join(case, f))
    head = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
    # linearUpwind: a steady flow stays steady (limitedLinearV's direction
    # follows the round-off in the lateral velocity and stirs the pressure)
    with open(os.path.join(case, "system", "fvSchemes"), "w") as f:
        f.write(head % ("dictionary", "fvSchemes") +
                "ddtSchemes { default Euler; }\ngradSchemes { default Gauss linear; }\n"
                "divSchemes { default none; div(alphaPhi,U) Gauss linearUpwind grad(U);"
                " div(((alpha*nu)*dev2(T(grad(U))))) Gauss linear; }\n"
                "laplacianSchemes { default Gauss linear corrected; }\n"
                "interpolationSchemes { default linear; }\nsnGradSchemes { default corrected; }\n")
    with open(os.path.join(case, "system", "fvSolution"), "w") as f:
        f.write(head % ("dictionary", "fvSolution") +
                "solvers\n{\n    p { solver PCG; preconditioner DIC; tolerance 1e-13; relTol 0; }\n"
                "    pFinal { $p; }\n    \"(U|UFinal)\" { solver smoothSolver; smoother symGaussSeidel;"
                " tolerance 1e-13; relTol 0; }\n}\n"
                "PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0;"
                " momentumPredictor yes; }\n")
    end = DT*LEVEL_STEPS*len(RE_LEVELS)
    with open(os.path.join(case, "system", "controlDict"), "w") as f:
        f.write(head % ("dictionary", "controlDict") +
                "application pimpleDEMFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\n"
                "endTime %g;\ndeltaT %g;\nwriteControl timeStep;\nwriteInterval 1000;\n"
                "writeFormat ascii;\nwritePrecision 12;\ntimePrecision 6;\nrunTimeModifiable false;\n"
                "functions { bedProbes { type probes; libs (\"libsampling.so\"); fields (p);"
                " probeLocations ((0.002 0.002 %g) (0.002 0.002 %g)); writeControl timeStep;"
                " writeInterval 1; } }\n" % (end, DT, PROBES[0], PROBES[1]))
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write(head % ("dictionary", "blockMeshDict") +
                "vertices ((0 0 -0.008) (0.008 0 -0.008) (0.008 0.008 -0.008) (0 0.008 -0.008)\n"
                "  (0 0 0.056) (0.008 0 0.056) (0.008 0.008 0.056) (0 0.008 0.056));\n"
                "blocks (hex (0 1 2 3 4 5 6 7) (2 2 16) simpleGrading (1 1 1));\n"
                "boundary (\n inlet { type patch; faces ((0 3 2 1)); }\n"
                " outlet { type patch; faces ((4 5 6 7)); }\n"
                " left { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }\n"
                " right { type cyclic; neighbourPatch left; faces ((1 2 6 5)); }\n"
                " front { type cyclic; neighbourPatch back; faces ((0 1 5 4)); }\n"
                " back { type cyclic; neighbourPatch front; faces ((3 7 6 2)); }\n);\n")
    # the inlet velocity in steps, each held LEVEL_STEPS fluid steps
    table = []
    for n, re in enumerate(RE_LEVELS):
        u = re*NU/D_LARGE
        table += ["(%g (0 0 %.12g))" % (DT*LEVEL_STEPS*n + (DT if n else 0), u),
                  "(%g (0 0 %.12g))" % (DT*LEVEL_STEPS*(n + 1), u)]
    cyclic = '    "(left|right|front|back)" { type cyclic; }\n'
    with open(os.path.join(case, "0", "U"), "w") as f:
        f.write(head % ("volVectorField", "U") +
                "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\nboundaryField\n{\n"
                "    inlet { type uniformFixedValue; uniformValue table (%s); }\n"
                "    outlet { type pressureInletOutletVelocity; value uniform (0 0 0); }\n%s}\n"
                % (" ".join(table), cyclic))
    with open(os.path.join(case, "0", "p"), "w") as f:
        f.write(head % ("volScalarField", "p") +
                "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\nboundaryField\n{\n"
                "    inlet { type zeroGradient; }\n    outlet { type fixedValue; value uniform 0; }\n%s}\n"
                % cyclic)
    forces = "(pressureGradient buoyancy)" if formulation == "A" else "(buoyancy)"
    with open(os.path.join(case, "constant", "couplingProperties"), "w") as f:
        f.write(head % ("dictionary", "couplingProperties") +
                'demScript "DEM/in.fixed";\ncouplingInterval 100;\nformulation %s;\ndragModel %s;\n'
                "forces %s;\nparticlesOutside error;\nvoidFractionModel analytical;\nalphaMin 0.2;\n"
                % (formulation, law, forces))
    spheres = lattice(bidisperse)
    with open(os.path.join(case, "DEM", "bed.data"), "w") as f:
        f.write("fixed bed\n\n%d atoms\n1 atom types\n0 0.008 xlo xhi\n0 0.008 ylo yhi\n"
                "-0.008 0.056 zlo zhi\n\nAtoms\n\n" % len(spheres))
        for n, (d, (x, y, z)) in enumerate(spheres):
            f.write("%d 1 %.17g 2500 %.17g %.17g %.17g\n" % (n + 1, d, x, y, z))
    # no integrator: the particles stay where they are, at rest
    with open(os.path.join(case, "DEM", "in.fixed"), "w") as f:
        f.write("atom_style granular\natom_modify map array\nboundary p p f\nnewton off\n"
                "communicate single vel yes\nunits si\nread_data bed.data\n"
                "neighbor 0.0002 bin\nneigh_modify delay 0\n"
                "fix m1 all property/global youngsModulus peratomtype 5.e6\n"
                "fix m2 all property/global poissonsRatio peratomtype 0.45\n"
                "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3\n"
                "fix m4 all property/global coefficientFriction peratomtypepair 1 0.3\n"
                "pair_style gran model hertz tangential history\npair_coeff * *\n"
                "timestep 1.e-5\nfix cfd all couple/cfd couple_every 100 mpi\n"
                "fix cfd2 all couple/cfd/force\nrun 0\n")
    sh("blockMesh > log.blockMesh", case)
    return spheres


def law_force(law, d, a, u):
    return LAWS[law](d, a, u, RHO, MU)


def law_gradient(law, spheres, Us):
    """-dp/dz of the bed: every force on the particles of one cell balances
    the cell's fluid, a grad p V = sum of the drag forces (either formulation)"""
    per_cell = [d for d, (x, y, z) in spheres if x < CELL and y < CELL and z < CELL]
    vcell = CELL**3
    a = 1 - sum(math.pi*d**3/6 for d in per_cell)/vcell
    u = Us/a
    return sum(law_force(law, d, a, u) for d in per_cell)/(a*vcell), a


def probe_gradients(case):
    """the steady pressure gradient at the end of each inlet level"""
    probe = np.loadtxt(os.path.join(case, "postProcessing", "bedProbes", "0", "p"))
    out = []
    for n in range(len(RE_LEVELS)):
        row = np.argmin(abs(probe[:, 0] - DT*LEVEL_STEPS*(n + 1)))
        out.append(RHO*(probe[row, 1] - probe[row, 2])/(PROBES[1] - PROBES[0]))
    return probe, out


def test_fixed_beds():
    print("fixed beds, Re_p 0.1 to 100: pressure gradient against each law (0.1 %)")
    for bidisperse in (False, True):
        for law in LAWS:
            for formulation in ("A", "B"):
                label = "%s, formulation %s, %s" % (law, formulation,
                                                    "two sizes" if bidisperse else "one size")
                case = os.path.join(WORK, "fixedBed")
                spheres = write_case(case, law, formulation, bidisperse)
                rc, out = sh("pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
                check("%s: run completed" % label, rc == 0)
                if rc:
                    continue
                _, grads = probe_gradients(case)
                worst, porosity = 0.0, None
                for re, got in zip(RE_LEVELS, grads):
                    want, porosity = law_gradient(law, spheres, re*NU/D_LARGE)
                    worst = max(worst, abs(got/want - 1))
                check("%s (porosity %.4f): within 0.1 %% at Re_p %s" % (label, porosity,
                      " ".join("%g" % r for r in RE_LEVELS)), worst < 1e-3, "(largest %.1e)" % worst)


def test_fixed_bed_parallel():
    print("the two-size fixed bed on 2 ranks, split between the probes, against serial")
    case = os.path.join(WORK, "fixedBed-parallel")
    write_case(case, "DiFelice", "B", True)
    sh("pimpleDEMFoam > log.serial 2>&1", case)
    serial, _ = probe_gradients(case)
    shutil.rmtree(os.path.join(case, "postProcessing"))
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                "numberOfSubdomains 2;\nmethod simple;\ncoeffs { n (1 1 2); }\n")
    rc, out = sh("decomposePar -force > log.decomposePar && "
                 "timeout 300 mpirun -np 2 pimpleDEMFoam -parallel > log.parallel 2>&1", case, check=False)
    check("parallel run completed", rc == 0, out[-800:] if rc else "")
    if rc:
        return
    par, _ = probe_gradients(case)
    scale = np.max(np.abs(serial[:, 1:]))
    diff = np.max(np.abs(par[:, 1:] - serial[:, 1:]))/scale
    check("probe pressures, 2 ranks against serial, every step", diff < 1e-9, "(%.1e of the largest)" % diff)


def cd_schiller_naumann(re):
    return 24/re*(1 + 0.15*re**0.687) if re < 1000 else 0.44


def test_settling_spheres():
    print("a glass sphere settling in a liquid, Re 0.1 to 800: terminal velocity against Schiller-Naumann")
    # (diameter, kinematic viscosity, mesh scale): the cell stays 6 or more diameters
    for d, nu, scale, end in ((1e-3, 9e-5, 0.001, 0.05), (1e-3, 4e-6, 0.001, 0.15),
                              (2.49e-3, 1e-6, 0.002, 0.3)):
        mu = RHO*nu

        def excess(v):
            re = RHO*v*d/mu
            return 1500*9.81*math.pi*d**3/6 - 0.5*cd_schiller_naumann(re)*RHO*math.pi*d*d/4*v*v
        want = brentq(excess, 1e-7, 5.0)
        re = RHO*want*d/mu
        case = os.path.join(WORK, "settling-Re%g" % round(re, 1))
        shutil.rmtree(case, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "tutorials", "settlingSphere"), case)
        sh("./Allclean && cp -r 0.orig 0 && sed -i 's/^nu .*/nu %g;/' constant/transportProperties && "
           "sed -i 's/^endTime .*/endTime %g;/' system/controlDict && "
           "sed -i 's/^scale .*/scale %g;/' system/blockMeshDict && blockMesh > log.blockMesh" % (nu, end, scale),
           case)
        # the tutorial's box and release point, scaled with the mesh
        s = scale/0.001
        set_dem(case, boxWidth=0.04*s, boxHeight=0.096*s, releaseXY=0.02*s, releaseZ=0.085*s, diameter=d)
        rc, out = sh("pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
        check("Re %.3g: run completed" % re, rc == 0)
        if rc:
            continue
        hist = np.loadtxt(os.path.join(case, "DEM", "post", "history.txt"))
        near("Re %.3g (d = %g mm, nu = %g): terminal velocity / Schiller-Naumann" % (re, 1e3*d, nu),
             -hist[-1, 2]/want, 1.0, 0.02)


def main():
    checks.run([test_fixed_beds, test_fixed_bed_parallel, test_settling_spheres], sys.argv[1:])
    return checks.summary("dragLaws")


if __name__ == "__main__":
    sys.exit(main())
