/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
/*---------------------------------------------------------------------------*\
Application
    pimpleDEMFoam

Group
    grpLagrangianSolvers

Description
    Unresolved CFD-DEM solver: incompressible, volume-averaged
    Navier-Stokes equations (PIMPLE), laminar or with the fluid-fraction
    weighted turbulence models of DPMFoam (constant/turbulenceProperties) for the fluid on a mesh coarser than
    the particles, LIGGGHTS running in-process for the particles, coupled
    through a run-time selectable voidFractionModel and dragModel
    (particleFluidCoupling). Formulation A (set I) or B (set II); the drag
    is semi-implicit in the fluid momentum equation; the continuity
    equation carries the time derivative of the fluid fraction.

    Fields: U (interstitial fluid velocity), p (kinematic pressure without
    the hydrostatic part), alpha (fluid fraction), voidfraction (the last
    particle mapping), phi (volumetric flux alpha U . S).

Usage
    \b pimpleDEMFoam [-parallel]

    constant/couplingProperties, constant/transportProperties (nu, rho),
    constant/g, and the LIGGGHTS script named by demScript.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "particleFluidCoupling.H"
#include "fluxReconstruction.H"
#include "ddtFluxCorrection.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Unresolved CFD-DEM: volume-averaged incompressible flow coupled to"
        " LIGGGHTS through a run-time selectable void fraction model"
    );

    #include "postProcess.H"
    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    #include "createFields.H"
    #include "initContinuityErrs.H"

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        ++runTime;
        Info<< "Time = " << runTime.timeName() << nl << endl;

        coupling.beginStep(U, laminarTransport.nu()().weightedAverage(mesh.V()).value());
        alphaf = fvc::interpolate(alpha);

        #include "alphaCourantNo.H"

        while (pimple.loop())
        {
            #include "UEqn.H"
            while (pimple.correct())
            {
                #include "pEqn.H"
            }
            if (turbulence.valid() && pimple.turbCorr())
            {
                turbulence->correct();
            }
        }

        if (coupling.heat())
        {
            #include "TEqn.H"
        }

        coupling.endStep(U, p);

        runTime.write();
        if (runTime.writeTime())
        {
            coupling.write();
        }
        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;
    return 0;
}
