/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "buoyancyForce.H"
#include "keywordSchema.H"
#include "particleData.H"
#include "parcelScaling.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(buoyancyForce, 0);
    addToRunTimeSelectionTable(particleForce, buoyancyForce, dictionary);
}


Foam::buoyancyForce::buoyancyForce
(
    const word& name,
    const dictionary& dict,
    const setup& s
)
:
    particleForce(name)
{
    keywordSchema(dict.dictName()).check(dict);
}


void Foam::buoyancyForce::add(const state& s, const label i, vector& f) const
{
    const scalar volume =
        s.parcels.volumeForceFactor(s.type(i))*s.volumes[i];
    f -= s.rho*volume*s.g;
}
