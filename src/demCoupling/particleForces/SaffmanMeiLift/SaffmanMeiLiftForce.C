/*---------------------------------------------------------------------------*\
    voidFraction: unresolved CFD-DEM coupling for OpenFOAM and LIGGGHTS
    Copyright (C) 2026 the voidFraction authors
    License: GNU General Public License v3.0 or later (see LICENSE)
    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/
#include "SaffmanMeiLiftForce.H"
#include "SaffmanMeiLift.H"
#include "keywordSchema.H"
#include "voidFractionModel.H"
#include "parcelScaling.H"
#include "fvc.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(SaffmanMeiLiftForce, 0);
    addToRunTimeSelectionTable(particleForce, SaffmanMeiLiftForce, dictionary);
}


Foam::SaffmanMeiLiftForce::SaffmanMeiLiftForce
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


void Foam::SaffmanMeiLiftForce::beginInterval
(
    const state& s,
    intervalExchange& e
)
{
    const vectorField vorticity(fvc::curl(s.U)().primitiveField());
    vectorField Up, vorticityP;
    s.voidFraction.gather(s.U.primitiveField(), Up, vorticity, vorticityP);
    const vectorField& v = s.velocities;
    vectorField& F = e.addedForce(s.particles.size());
    forAll(Up, i)
    {
        const scalar w = s.weightSum[i];
        if (w <= SMALL) continue;
        const label type = s.type(i);
        const scalar d = s.parcels.particleDiameter(2*s.particles.radii()[i], type);
        F[i] +=
            s.parcels.dragFactor(type)
           *SaffmanMeiLift(d, s.rho, s.nu, Up[i]/w - v[i], vorticityP[i]/w);
    }
}
