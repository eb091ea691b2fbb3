#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (voidFraction; see LICENSE)
"""pimpleDEMFoam with a turbulence model (constant/turbulenceProperties):
without particles against OpenFOAM's own pimpleFoam on a turbulent plane
channel (k-epsilon with wall functions, and Smagorinsky LES), a solver that
shares no code with ours but the turbulence models; with particles, the
fluidised bed under k-epsilon conserves momentum and runs alike on 1 and 2
ranks. Ends with 'turbulence: N passed, N failed'."""
import os
import re
import shutil
import sys

import numpy as np

import checks
from checks import WORK, check, near
from couplingTests import binary_field, check_coupling_log, copy_tutorial, coupling_forces, edit
from foamCase import ROOT, sh

CHANNEL = os.path.join(ROOT, "tests", "cases", "turbulentChannel")
NX, NY = 50, 20

MODELS = {
    "kEpsilon": ("RAS { RASModel kEpsilon; turbulence on; printCoeffs off; }", "nutkWallFunction"),
    "Smagorinsky": ("LES { LESModel Smagorinsky; turbulence on; printCoeffs off; delta cubeRootVol;\n"
                    "      cubeRootVolCoeffs { deltaCoeff 1; } SmagorinskyCoeffs { Ck 0.094; Ce 1.048; } }",
                    "nutUSpaldingWallFunction"),
}


def channel(dest, model):
    case = os.path.join(WORK, dest)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(CHANNEL, case)
    coeffs, wall = MODELS[model]
    with open(os.path.join(case, "constant", "turbulenceProperties"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }\n"
                "simulationType %s;\n%s\n" % ("RAS" if model == "kEpsilon" else "LES", coeffs))
    edit(os.path.join(case, "0", "nut"), r"nutkWallFunction", wall)
    sh("blockMesh > log.blockMesh", case)
    return case


def test_channel_against_pimpleFoam():
    print("turbulent channel without particles: pimpleDEMFoam against pimpleFoam after 0.1 s")
    for model in MODELS:
        ours, theirs = channel("channel-%s" % model, model), channel("channel-%s-pimpleFoam" % model, model)
        rc, out = sh("pimpleDEMFoam > log.pimpleDEMFoam 2>&1", ours, check=False)
        check("%s: pimpleDEMFoam ran" % model, rc == 0, out[-600:] if rc else "")
        log = open(os.path.join(ours, "log.pimpleDEMFoam")).read()
        check("%s: the model was selected" % model, "turbulence model %s" % model in log)
        rc2, out = sh("pimpleFoam > log.pimpleFoam 2>&1", theirs, check=False)
        check("%s: pimpleFoam ran" % model, rc2 == 0, out[-600:] if rc2 else "")
        if rc or rc2:
            continue
        U = [binary_field(os.path.join(c, "0.1", "U")) for c in (ours, theirs)]
        p = [binary_field(os.path.join(c, "0.1", "p")).reshape(NY, NX) for c in (ours, theirs)]
        nut = [binary_field(os.path.join(c, "0.1", "nut")) for c in (ours, theirs)]
        # the pressure drop: the inlet column's mean (the outlet is at 0)
        near("%s: pressure drop over the channel / pimpleFoam's" % model,
             p[0][:, 0].mean()/p[1][:, 0].mean(), 1, 0.02)
        near("%s: largest velocity difference / largest velocity" % model,
             np.abs(U[0] - U[1]).max()/np.abs(U[1]).max(), 0, 0.04)
        near("%s: largest turbulent viscosity difference / largest" % model,
             np.abs(nut[0] - nut[1]).max()/np.abs(nut[1]).max(), 0, 0.03)
        near("%s: turbulent viscosity 10 to 1000 times the air's" % model,
             np.log10(nut[0].max()/1.5e-5), 2, 1)


def test_fvOptions_source():
    print("fvOptions: a uniform momentum source in the channel is taken up by the pressure alone")
    # incompressible flow with fixed inflow: a body force S = grad(S x) lowers
    # the pressure by S (L - x) (the outlet's is fixed) and leaves the
    # velocity as it was
    source, length = 0.5, 0.5
    # the source-free run: test_channel_against_pimpleFoam's, when it has run
    plain = os.path.join(WORK, "channel-kEpsilon")
    if not os.path.isfile(os.path.join(plain, "0.1", "U")):
        plain = channel("channel-kEpsilon", "kEpsilon")
    forced = channel("channel-fvOptions", "kEpsilon")
    with open(os.path.join(forced, "system", "fvOptions"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }\n"
                "push { type vectorSemiImplicitSource; selectionMode all; volumeMode specific;\n"
                "       injectionRateSuSp { U ((%g 0 0) 0); } }\n" % source)
    for case in [c for c in (plain, forced) if not os.path.isfile(os.path.join(c, "0.1", "U"))]:
        rc, out = sh("pimpleDEMFoam > log.pimpleDEMFoam 2>&1", case, check=False)
        check("%s: pimpleDEMFoam ran" % os.path.basename(case), rc == 0, out[-600:] if rc else "")
        if rc:
            return
    log = open(os.path.join(forced, "log.pimpleDEMFoam")).read()
    check("the source was selected", "Selecting finite volume options type vectorSemiImplicitSource" in log)
    U = [binary_field(os.path.join(c, "0.1", "U")) for c in (plain, forced)]
    p = [binary_field(os.path.join(c, "0.1", "p")).reshape(NY, NX) for c in (plain, forced)]
    x = (np.arange(NX) + 0.5)*length/NX
    want = -source*(length - x)
    near("pressure change against -S (L - x), largest error / S L",
         np.abs(p[1] - p[0] - want).max()/(source*length), 0, 1e-5)
    near("velocity change / largest velocity", np.abs(U[1] - U[0]).max()/np.abs(U[0]).max(), 0, 1e-5)


def test_bed_with_kEpsilon():
    print("fluidisedBed under k-epsilon: momentum balance, 2 ranks against 1")
    case = copy_tutorial("fluidisedBed", "bed-kEpsilon")
    shutil.copy(os.path.join(CHANNEL, "constant", "turbulenceProperties"), os.path.join(case, "constant"))
    for name, value, dims in (("k", "1e-4", "[0 2 -2 0 0 0 0]"), ("epsilon", "1e-3", "[0 2 -3 0 0 0 0]"),
                              ("nut", "0", "[0 2 -1 0 0 0 0]")):
        inlet = "calculated" if name == "nut" else "fixedValue"
        outlet = "calculated" if name == "nut" else "inletOutlet; inletValue uniform %s" % value
        with open(os.path.join(case, "0.orig", name), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class volScalarField; object %s; }\n"
                    "dimensions %s;\ninternalField uniform %s;\nboundaryField\n{\n"
                    "    inlet { type %s; value uniform %s; }\n"
                    "    outlet { type %s; value uniform %s; }\n"
                    "    \"(front|back|left|right)\" { type cyclic; }\n}\n"
                    % (name, dims, value, inlet, value, outlet, value))
    edit(os.path.join(case, "system", "fvSchemes"), r"^divSchemes\s*\n\{",
         "divSchemes\n{\n    div(alphaPhi,k) Gauss upwind;\n    div(alphaPhi,epsilon) Gauss upwind;\n"
         "    div(((alpha*nuEff)*dev2(T(grad(U))))) Gauss linear;")
    edit(os.path.join(case, "system", "fvSolution"), r"\"\(U\|UFinal\)\"", "\"(U|k|epsilon)(Final)?\"")
    logs = {}
    for ranks in (1, 2):
        rc, out = sh("./Allrun analytical 3 0.02 %d" % ranks, case, check=False)
        check("%d rank(s): 0.02 s completed" % ranks, rc == 0, out[-800:] if rc else "")
        logs[ranks] = os.path.join(case, "log.%d" % ranks)
        shutil.copy(os.path.join(case, "log.pimpleDEMFoam"), logs[ranks])
        text = open(logs[ranks]).read()
        check("%d rank(s): k-epsilon selected" % ranks, "RAS turbulence model kEpsilon" in text)
        check_coupling_log("k-epsilon, %d rank(s)" % ranks, logs[ranks], 0.2)
    ser, par = coupling_forces(logs[1]), coupling_forces(logs[2])
    if ser and len(ser) == len(par):
        diff = max(abs(p[1][2] - q[1][2]) for p, q in zip(par, ser))/max(abs(q[1][2]) for q in ser)
        check("vertical fluid force on the bed, 2 ranks = 1 rank", diff < 1e-6,
              "(largest relative difference %.1e)" % diff)
    else:
        check("as many couplings on 2 ranks as on 1", False, "(%d and %d)" % (len(ser), len(par)))


def main():
    checks.run([test_channel_against_pimpleFoam, test_fvOptions_source, test_bed_with_kEpsilon], sys.argv[1:])
    return checks.summary("turbulence")


if __name__ == "__main__":
    sys.exit(main())
