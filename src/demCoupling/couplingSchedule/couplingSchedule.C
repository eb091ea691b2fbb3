/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "couplingSchedule.H"

Foam::couplingSchedule::couplingSchedule
(
    const Time& runTime,
    const dictionary& dict,
    const scalar demTimeStep
)
:
    demTimeStep_(demTimeStep),
    demSteps_(0),
    fluidSteps_(1),
    fluidStep_(0),
    nCouplings_(0)
{
    const label interval = dict.get<label>("couplingInterval");
    if (interval < 1)
    {
        FatalIOErrorInFunction(dict)
            << "couplingInterval must be a positive number of DEM steps, not "
            << interval << exit(FatalIOError);
    }
    if (runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "adjustTimeStep: the fluid step must stay a fixed multiple or"
            << " divisor of the coupling time" << exit(FatalIOError);
    }
    const scalar couplingTime = interval*demTimeStep;
    const scalar dtFluid = runTime.deltaTValue();
    const scalar perCoupling = couplingTime/dtFluid;
    const scalar perFluid = dtFluid/couplingTime;
    const scalar tol = 1e-6;
    if (perCoupling >= 1 - tol && mag(perCoupling - round(perCoupling)) < tol*perCoupling)
    {
        fluidSteps_ = label(round(perCoupling));
        demSteps_ = interval;
    }
    else if (perFluid >= 1 && mag(perFluid - round(perFluid)) < tol*perFluid)
    {
        fluidSteps_ = 1;
        demSteps_ = interval*label(round(perFluid));
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "the coupling time " << couplingTime << " s (couplingInterval "
            << interval << " x DEM step " << demTimeStep << " s) is not a"
            << " whole multiple or divisor of the fluid step " << dtFluid
            << " s (controlDict deltaT)" << exit(FatalIOError);
    }
    // a continued run goes on counting from its start time
    nCouplings_ = label(round(runTime.value()/(demSteps_*demTimeStep_)));
    Info<< "particleFluidCoupling: " << demSteps_ << " DEM steps and "
        << fluidSteps_ << " fluid steps per coupling" << endl;
}


void Foam::couplingSchedule::addKeywords(keywordSchema& schema)
{
    schema.add("couplingInterval", keywordSchema::wholeNumber);
}
