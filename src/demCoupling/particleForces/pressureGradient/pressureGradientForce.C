/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "pressureGradientForce.H"
#include "keywordSchema.H"
#include "voidFractionModel.H"
#include "parcelScaling.H"
#include "fvc.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(pressureGradientForce, 0);
    addToRunTimeSelectionTable(particleForce, pressureGradientForce, dictionary);
}


Foam::pressureGradientForce::pressureGradientForce
(
    const word& name,
    const dictionary& dict,
    const setup& s
)
:
    particleForce(name)
{
    keywordSchema(dict.dictName()).check(dict);
    if (s.formulationB)
    {
        FatalIOErrorInFunction(dict)
            << "formulation B puts the pressure gradient into drag/alpha:"
            << " remove pressureGradient from forces" << exit(FatalIOError);
    }
}


Foam::tmp<Foam::vectorField> Foam::pressureGradientForce::stepField
(
    const volScalarField& p
) const
{
    return tmp<vectorField>::New(fvc::grad(p)().primitiveField());
}


void Foam::pressureGradientForce::add
(
    const state& s,
    const label i,
    vector& f
) const
{
    const scalar w = s.weightSum[i];
    if (w > SMALL)
    {
        const scalar volume =
            s.parcels.volumeForceFactor(s.type(i))*s.volumes[i];
        f -= s.rho*volume*gradP_[i]/w;
    }
}
